#include "command_line.h"

#include <filesystem>
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

// The options every command shares (what the image is, which GPU, how to run).
void addImageOptions(CLI::App& app, CommandLine& cl, std::string& bg) {
    app.add_option("scene", cl.scenePath, "Scene file (XML, UMD course format)");
    app.add_option("-i,--input", cl.scenePath, "Scene file (the course's spelling)");
    app.add_option("-w,--width", cl.render.width, "Image width in pixels")->check(CLI::Range(1, 1 << 16));
    app.add_option("-h,--height", cl.render.height, "Image height in pixels")->check(CLI::Range(1, 1 << 16));
    app.add_option("-k,--max-depth", cl.render.maxDepth, "Reflection/refraction recursion depth")
        ->check(CLI::Range(0, 64));
    app.add_option("--light-samples", cl.render.lightSamples, "Area-light samples per pixel sample")
        ->check(CLI::Range(1, 4096));
    app.add_option("--gloss-samples", cl.render.glossSamples,
                   "Glossy reflection directions per pixel sample (at primary hits)")
        ->check(CLI::Range(1, 4096));
    app.add_option("--seed", cl.render.seed, "Random seed: the same seed and options give the same image");
    app.add_option("--bg", bg, "Background colour r,g,b (overrides the scene's bgColor)");
    app.add_option("--camera", cl.camera, "Which camera of the scene (index; default: the one <sceneParameters> names, else the first)")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--threads", cl.render.threads, "CPU threads (default: all cores)")->check(CLI::Range(0, 1024));
    app.add_option("--gpu", cl.gpuIndex, "Vulkan device index (see --list-devices)")->check(CLI::NonNegativeNumber);
    app.add_flag("--validate", cl.validate, "Enable the Vulkan validation layers");
    app.add_option("--shader-dir", cl.shaderDir,
                   "Compile the GLSL kernels from this directory at run time (edit and re-run, no rebuild)")
        ->check(CLI::ExistingDirectory);
    app.add_flag("--strict", cl.strict, "Treat scene warnings as errors");
    app.add_flag("-q,--quiet", cl.render.quiet, "No progress bar or summary");
}

void addRenderOptions(CLI::App& app, CommandLine& cl, std::string& bg, std::string& sampler, std::string& device) {
    addImageOptions(app, cl, bg);
    app.add_option("-r,--rpp", cl.render.samplesPerPixel,
                   "Samples per pixel; n*n jittered sub-pixel samples when it is a square")
        ->check(CLI::Range(1, 1 << 20));
    app.add_option("--sampler", sampler,
                   "Sample pattern: jittered (Cook 1984), regular, random or sobol (Owen-scrambled, Burley 2020)")
        ->check(CLI::IsMember({"jittered", "regular", "random", "sobol"}));
    app.add_option("--device", device, "Renderer: gpu (Vulkan), cpu (reference) or auto (gpu if available)")
        ->check(CLI::IsMember({"auto", "cpu", "gpu"}));
    app.add_flag("--general-kernel", cl.general, "GPU: use the kernel with every feature (no specialisation)");
}

// vkrt sweep: lists instead of single values, and where the results and the reference cache go.
struct SweepText {
    std::string out, cache, device = "both", referenceDevice;
    std::vector<std::string> samplers{"random", "regular", "jittered", "sobol"};
};

void addSweepOptions(CLI::App& app, CommandLine& cl, std::string& bg, SweepText& text) {
    addImageOptions(app, cl, bg);
    study::SweepOptions& sw = cl.sweep;
    app.add_option("--out", text.out, "Directory for sweep.csv, the plots and report.md")->required();
    app.add_option("--rpp", sw.rpps, "Rays per pixel to sweep, comma-separated")->delimiter(',')->check(CLI::Range(1, 1 << 20));
    app.add_option("--seeds", sw.seeds, "Seeds per setting (--seed, --seed + 1, ...)")->check(CLI::Range(1, 1000));
    app.add_option("--samplers", text.samplers, "Samplers to sweep, comma-separated")
        ->delimiter(',')
        ->check(CLI::IsMember({"jittered", "regular", "random", "sobol"}));
    app.add_option("--device", text.device, "Devices to sweep: gpu, cpu or both")->check(CLI::IsMember({"gpu", "cpu", "both"}));
    app.add_option("--reference-rpp", sw.referenceRpp, "Rays per pixel of the converged reference (sobol; even: two halves estimate its noise)")
        ->check(CLI::Range(2, 1 << 24));
    app.add_option("--reference-device", text.referenceDevice,
                   "Device for the reference (default: gpu when sweeping the gpu, else cpu)")
        ->check(CLI::IsMember({"gpu", "cpu"}));
    app.add_option("--cache", text.cache, "Reference cache directory (default: $XDG_CACHE_HOME/vkrt or ~/.cache/vkrt)");
    app.add_option("--target-rmse", sw.targetRmse, "Target RMSE for the report's cheapest setting")
        ->check(CLI::PositiveNumber);
}

}  // namespace

ParseResult parseCommandLine(int argc, const char* const* argv) {
    CommandLine cl;
    std::vector<std::string> args(argv + 1, argv + argc);
    if (!args.empty() && (args[0] == "compare" || args[0] == "sweep")) {
        cl.command = args[0] == "compare" ? Command::Compare : Command::Sweep;
        args.erase(args.begin());
    }
    const bool compare = cl.command == Command::Compare;
    const bool sweep = cl.command == Command::Sweep;

    CLI::App app{compare ? "vkrt compare: render a scene on the GPU and on the CPU reference with the same seed and "
                           "report how far apart the images are (--stat: different seeds and a z-test)"
                 : sweep ? "vkrt sweep: measure error against a converged reference and render time over samplers, rays "
                           "per pixel, seeds and devices; writes DIR/sweep.csv, DIR/error_vs_*.png and DIR/report.md"
                         : "vkrt: a Vulkan compute-shader ray tracer for the UMD course scene format.\n"
                           "Usage: vkrt scene.xml [options]  |  vkrt compare scene.xml [options]  |  "
                           "vkrt sweep scene.xml --out DIR [options]  |  vkrt --list-devices",
                 compare ? "vkrt compare" : sweep ? "vkrt sweep" : "vkrt"};
    app.set_help_flag("--help", "Print this help and exit");
    app.option_defaults()->always_capture_default();
    std::string bg, sampler = "jittered", device = "auto";
    SweepText sweepText;
    if (sweep) {
        addSweepOptions(app, cl, bg, sweepText);
    } else {
        addRenderOptions(app, cl, bg, sampler, device);
    }
    bool listDevices = false;
    if (compare) {
        app.add_option("-o,--output", cl.heatMapPath,
                       "Difference heat map image (with --stat the z map); none is written without -o");
        app.add_flag("--stat", cl.statistical,
                     "Statistical comparison: GPU (seed + 1, -r rpp) vs a CPU reference (seed, 16x the rpp, at least "
                     "256) by a per-pixel z-test against the CPU's sample variance (alpha 0.01, Sidak; pass when "
                     ">= 99.75% of values pass; exit code 3 on failure)");
    } else if (!sweep) {
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
        cl.render.sampler = parseSampler(sampler);  // CLI11 checked the name
        cl.device = device == "cpu" ? DeviceChoice::Cpu : device == "gpu" ? DeviceChoice::Gpu : DeviceChoice::Auto;
        if (sweep) {
            study::SweepOptions& sw = cl.sweep;
            sw.scenePath = cl.scenePath;
            sw.outDir = sweepText.out;
            sw.cacheDir = sweepText.cache;
            sw.samplers.clear();
            for (const std::string& name : sweepText.samplers) sw.samplers.push_back(parseSampler(name));
            sw.devices.clear();
            if (sweepText.device != "cpu") sw.devices.push_back(study::Device::Gpu);
            if (sweepText.device != "gpu") sw.devices.push_back(study::Device::Cpu);
            if (!sweepText.referenceDevice.empty())
                sw.referenceDevice = sweepText.referenceDevice == "gpu" ? study::Device::Gpu : study::Device::Cpu;
        }
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return {std::nullopt, code == 0 ? 0 : 2};
    }

    const std::string stem = std::filesystem::path(cl.scenePath).stem().string();
    if (cl.outputPath.empty()) cl.outputPath = stem + ".png";
    return {cl, 0};
}

}  // namespace vkrt
