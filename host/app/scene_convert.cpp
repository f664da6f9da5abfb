#include "scene_convert.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "interrupt.h"
#include "json_writer.h"
#include "output_file.h"
#include "render_options.h"
#include "scene_compare.h"
#include "scene_loader.h"
#include "scene_writing.h"
#include "xml_writer.h"

namespace vkrt {

namespace {

namespace fs = std::filesystem;

// Before anything is read, as for images: a bad -o never costs the load of a 100K-triangle mesh.
std::string checkOutput(const std::string& output, const std::string& input) {
    const std::string ext = lowerExtension(output);
    if (ext != ".json" && ext != ".xml")
        throw std::runtime_error(output + ": unsupported scene format '" + ext + "' (use .json or .xml)");
    checkOutputFolder(output, "a scene file");
    checkNotTheInput(output, input);
    return ext.substr(1);
}

std::string plural(std::size_t n, const char* noun) {
    return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

std::string countsOf(const Scene& scene) {
    std::string counts = plural(scene.cameras.size(), "camera") + ", " + plural(scene.lights.size(), "light") + ", " +
                         plural(scene.shaders.size(), "shader") + ", " + plural(scene.shapes.size(), "shape") + ", " +
                         plural(scene.instances.size(), "instance");
    if (!scene.emitters.empty()) counts += " (" + plural(scene.emitters.size(), "shape light") + ")";
    return counts;
}

void writeText(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw std::runtime_error(path.string() + ": cannot write the scene file");
}

}  // namespace

Conversion convertScene(const std::string& input, const std::string& output, Diagnostics& diagnostics,
                        const std::atomic<bool>* cancel) {
    // Ctrl-C is seen between the steps (a load of the largest course mesh takes about 0.2 s).
    const auto checkCancel = [cancel] {
        if (cancel && cancel->load()) throw RenderCancelled{};
    };
    Conversion conversion;
    conversion.format = checkOutput(output, input);
    const Scene scene = [&] {
        // Nothing is written before this load ends, so Ctrl-C inside it may end the process.
        const ExitAtOnceOnInterrupt scope;
        LoadOptions options{diagnostics.strict()};
        options.environmentTexels = false;  // convert writes the map's names, never its texels
        return loadScene(input, options, diagnostics);
    }();
    checkCancel();

    const fs::path directory = fs::path(output).parent_path();
    const bool json = conversion.format == "json";
    const Scene written = [&] {
        try {
            return writing::withWritableNames(scene, json ? writing::NameFormat::Json : writing::NameFormat::Xml,
                                              &conversion.escapedNames);
        } catch (const std::runtime_error& e) {
            throw std::runtime_error(output + ": not written: " + input + ": " + e.what());
        }
    }();
    const std::string text = json ? jsonSceneText(written, directory) : xmlSceneText(written, directory);

    // The model the file must load back as (the names and placeholders a write changes).
    const Scene expected = writing::asWritten(written);
    for (std::size_t i = 0; i < scene.shaders.size(); ++i) {
        if (scene.shaders[i].name.empty()) ++conversion.renamedShaders;
        if (scene.shaders[i].undefined) conversion.definedPlaceholders.push_back(scene.shaders[i].name);
    }

    // Written beside OUT (so relative paths resolve as they will in the result), loaded back and
    // compared before the rename.
    writeAtomically(output, [&](const std::string& temporary) {
        writeText(temporary, text);
        Diagnostics reloadWarnings;  // the input's warnings were reported; the result may repeat some
        Scene reloaded;
        try {
            LoadOptions reload;
            reload.environmentTexels = false;
            reloaded = loadScene(temporary, reload, reloadWarnings);
        } catch (const SceneError& e) {
            throw std::runtime_error(output + ": not written: the converted scene does not load (please report this): " +
                                     e.what());
        }
        checkCancel();
        const SceneDifferences differences = compareScenes(expected, reloaded);
        if (!differences.equal())
            throw std::runtime_error(output + ": not written: the converted scene does not load back as the same scene (" +
                                     std::to_string(differences.count) + " fields differ; please report this):\n" +
                                     differences.summary());
    });
    conversion.counts = countsOf(scene);
    return conversion;
}

}  // namespace vkrt
