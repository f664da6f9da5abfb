#include "scene_loader.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "geometry_extent.h"
#include "json_loader.h"
#include "local_origin.h"
#include "shader_emitters.h"
#include "source_text.h"
#include "xml_loader.h"

namespace vkrt {

namespace {

enum class Format { Xml, Json, Unknown };

const char* nameOf(Format format) { return format == Format::Xml ? "XML" : format == Format::Json ? "JSON" : "?"; }

Format formatOfExtension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension == ".xml") return Format::Xml;
    if (extension == ".json") return Format::Json;
    return Format::Unknown;
}

// The offset of the first byte after a UTF-8 byte order mark and white space.
std::size_t firstSignificantByte(const std::string& text) {
    std::size_t at = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
    while (at < text.size() && std::isspace(static_cast<unsigned char>(text[at]))) ++at;
    return at;
}

Format formatOfContent(const std::string& text, std::size_t at) {
    if (at >= text.size()) return Format::Unknown;
    return text[at] == '<' ? Format::Xml : text[at] == '{' ? Format::Json : Format::Unknown;
}

}  // namespace

Scene loadScene(const std::string& path, const LoadOptions& options, Diagnostics& diagnostics) {
    const Format byName = formatOfExtension(path);
    const char* element = byName == Format::Xml ? "xml" : byName == Format::Json ? "json" : "scene";
    const std::string text = readSourceFile(path, element);
    const std::size_t at = firstSignificantByte(text);
    const Format byContent = formatOfContent(text, at);

    Format format = byName;
    if (byName == Format::Unknown) {
        if (byContent == Format::Unknown)
            throw SceneError({path, 1, element, "cannot tell the scene format: the name ends in neither .xml nor .json "
                                                "and the content starts with neither '<' nor '{'", ""});
        format = byContent;
    } else if (byContent != Format::Unknown && byContent != byName) {
        const LineIndex lines(text);
        throw SceneError({path, lines.lineOf(static_cast<std::ptrdiff_t>(at)), element,
                          std::string("the file is named as ") + nameOf(byName) + " but its content is " + nameOf(byContent),
                          text.substr(at, 1), lines.columnOf(static_cast<std::ptrdiff_t>(at))});
    }
    // A known name with content of neither kind (empty, '['): that format's parser says what is wrong.
    Scene scene = format == Format::Xml ? loadXmlScene(path, text, options, diagnostics)
                                        : loadJsonScene(path, text, options, diagnostics);
    if (options.shaderEmitters) rules::makeShaderEmitters(scene, diagnostics);
    if (options.localOrigin) rules::rebaseWorldMeshes(scene);
    rules::warnGeometryBeyondFloat(scene, options.strict, diagnostics);
    return scene;
}

}  // namespace vkrt
