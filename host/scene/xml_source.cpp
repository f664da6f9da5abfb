#include "xml_source.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "diagnostics.h"

namespace vkrt {

namespace {

std::string readWholeFile(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw SceneError({path, 0, "xml", "scene file not found", path});
    if (!std::filesystem::is_regular_file(path, ec)) throw SceneError({path, 0, "xml", "not a regular file", path});
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SceneError({path, 0, "xml", "cannot open the scene file", path});
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad()) throw SceneError({path, 0, "xml", "cannot read the scene file", path});
    return buffer.str();
}

// The text at a parse-error offset, so the message shows what the parser choked on.
std::string snippetAt(const std::string& text, std::ptrdiff_t offset) {
    if (offset < 0 || static_cast<std::size_t>(offset) >= text.size()) return "end of file";
    std::size_t end = text.find('\n', static_cast<std::size_t>(offset));
    if (end == std::string::npos) end = text.size();
    return text.substr(static_cast<std::size_t>(offset), std::min<std::size_t>(end - offset, 40));
}

}  // namespace

XmlSource::XmlSource(std::string path) : path_(std::move(path)), document_(std::make_unique<pugi::xml_document>()) {
    const std::string text = readWholeFile(path_);
    for (std::size_t i = 0; i < text.size(); ++i)
        if (text[i] == '\n') newlineOffsets_.push_back(static_cast<std::ptrdiff_t>(i));

    // encoding_utf8: the files are ASCII/UTF-8, and a fixed encoding keeps pugixml's offsets equal
    // to offsets in `text` (conversion from UTF-16 would shift them).
    const pugi::xml_parse_result result =
        document_->load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_utf8);
    if (!result) {
        throw SceneError({path_, lineOfOffset(result.offset), "xml",
                          std::string("malformed XML (") + result.description() + ") at", snippetAt(text, result.offset)});
    }
    if (!root()) throw SceneError({path_, 1, "xml", "the file has no root element", ""});
}

int XmlSource::lineOfOffset(std::ptrdiff_t offset) const {
    const auto before = std::lower_bound(newlineOffsets_.begin(), newlineOffsets_.end(), offset);
    return static_cast<int>(std::distance(newlineOffsets_.begin(), before)) + 1;
}

int XmlSource::lineOf(pugi::xml_node node) const {
    const std::ptrdiff_t offset = node.offset_debug();
    return offset < 0 ? 0 : lineOfOffset(offset);
}

}  // namespace vkrt
