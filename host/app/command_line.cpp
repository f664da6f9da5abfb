#include "command_line.h"

#include <filesystem>
#include <map>
#include <sstream>

#include <CLI/CLI.hpp>

namespace vkrt {

namespace {

// "r,g,b" or "r g b" -> a colour; throws CLI::ValidationError.
glm::vec3 parseColour(const std::string& text) {
    std::string s = text;
    for (char& c : s)
        if (c == ',') c = ' ';
    std::istringstream in(s);
    glm::vec3 c;
    std::string extra;
    if (!(in >> c.r >> c.g >> c.b) || (in >> extra))
        throw CLI::ValidationError("--bg", "expected three numbers r,g,b, got '" + text + "'");
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(c[i])) throw CLI::ValidationError("--bg", "not a finite colour: '" + text + "'");
    return c;
}

void addRenderOptions(CLI::App& app, CommandLine& cl, std::string& bg, std::string& sampler, std::string& device) {
    app.add_option("scene", cl.scenePath, "Scene file (XML, UMD course format)");
    app.add_option("-i,--input", cl.scenePath, "Scene file (the course's spelling)");
    app.add_option("-w,--width", cl.render.width, "Image width in pixels")->check(CLI::Range(1, 1 << 16));
    app.add_option("-h,--height", cl.render.height, "Image height in pixels")->check(CLI::Range(1, 1 << 16));
    app.add_option("-r,--rpp", cl.render.samplesPerPixel,
                   "Samples per pixel; n*n jittered sub-pixel samples when it is a square")
        ->check(CLI::Range(1, 1 << 20));
    app.add_option("-k,--max-depth", cl.render.maxDepth, "Reflection/refraction recursion depth")
        ->check(CLI::Range(0, 64));
    app.add_option("--light-samples", cl.render.lightSamples, "Area-light samples per pixel sample")
        ->check(CLI::Range(1, 4096));
    app.add_option("--gloss-samples", cl.render.glossSamples,
                   "Glossy reflection directions per pixel sample (at primary hits)")
        ->check(CLI::Range(1, 4096));
    app.add_option("--seed", cl.render.seed, "Random seed: the same seed and options give the same image");
    app.add_option("--sampler", sampler,
                   "Sample pattern: jittered (Cook 1984), regular, random or sobol (Owen-scrambled, Burley 2020)")
        ->check(CLI::IsMember({"jittered", "regular", "random", "sobol"}));
    app.add_option("--bg", bg, "Background colour r,g,b (overrides the scene's bgColor)");
    app.add_option("--camera", cl.camera, "Which camera of the scene (index; default: the one <sceneParameters> names, else the first)")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--threads", cl.render.threads, "CPU threads (default: all cores)")->check(CLI::Range(0, 1024));
    app.add_option("--device", device, "Renderer: gpu (Vulkan), cpu (reference) or auto (gpu if available)")
        ->check(CLI::IsMember({"auto", "cpu", "gpu"}));
    app.add_option("--gpu", cl.gpuIndex, "Vulkan device index (see --list-devices)")->check(CLI::NonNegativeNumber);
    app.add_flag("--validate", cl.validate, "Enable the Vulkan validation layers");
    app.add_option("--shader-dir", cl.shaderDir,
                   "Compile the GLSL kernels from this directory at run time (edit and re-run, no rebuild)")
        ->check(CLI::ExistingDirectory);
    app.add_flag("--general-kernel", cl.general, "GPU: use the kernel with every feature (no specialisation)");
    app.add_flag("--strict", cl.strict, "Treat scene warnings as errors");
    app.add_flag("-q,--quiet", cl.render.quiet, "No progress bar or summary");
}

}  // namespace

ParseResult parseCommandLine(int argc, const char* const* argv) {
    CommandLine cl;
    std::vector<std::string> args(argv + 1, argv + argc);
    if (!args.empty() && args[0] == "compare") {
        cl.command = Command::Compare;
        args.erase(args.begin());
    }
    const bool compare = cl.command == Command::Compare;

    CLI::App app{compare ? "vkrt compare: render a scene on the GPU and on the CPU reference with the same seed and "
                           "report how far apart the images are"
                         : "vkrt: a Vulkan compute-shader ray tracer for the UMD course scene format.\n"
                           "Usage: vkrt scene.xml [options]  |  vkrt compare scene.xml [options]  |  vkrt --list-devices",
                 compare ? "vkrt compare" : "vkrt"};
    app.set_help_flag("--help", "Print this help and exit");
    app.option_defaults()->always_capture_default();
    std::string bg, sampler = "jittered", device = "auto";
    addRenderOptions(app, cl, bg, sampler, device);
    bool listDevices = false;
    if (compare) {
        app.add_option("-o,--output", cl.heatMapPath, "Difference heat map image (default <scene>_diff.png)");
    } else {
        app.add_option("-o,--output", cl.outputPath, "Output image: .png, .exr (linear float), .jpg or .ppm");
        app.add_flag("--list-devices", listDevices, "List the Vulkan devices and exit");
    }

    try {
        std::vector<std::string> reversed(args.rbegin(), args.rend());
        app.parse(reversed);
        if (listDevices) {
            cl.command = Command::ListDevices;
            return {cl, 0};
        }
        if (cl.scenePath.empty()) throw CLI::RequiredError("a scene file (vkrt scene.xml)");
        if (!bg.empty()) cl.render.background = parseColour(bg);
        static const std::map<std::string, SamplerKind> samplers = {
            {"jittered", SamplerKind::Jittered}, {"regular", SamplerKind::Regular}, {"random", SamplerKind::Random},
            {"sobol", SamplerKind::Sobol}};
        cl.render.sampler = samplers.at(sampler);
        cl.device = device == "cpu" ? DeviceChoice::Cpu : device == "gpu" ? DeviceChoice::Gpu : DeviceChoice::Auto;
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return {std::nullopt, code == 0 ? 0 : 2};
    }

    const std::string stem = std::filesystem::path(cl.scenePath).stem().string();
    if (cl.outputPath.empty()) cl.outputPath = stem + ".png";
    if (compare && cl.heatMapPath.empty()) cl.heatMapPath = stem + "_diff.png";
    return {cl, 0};
}

}  // namespace vkrt
