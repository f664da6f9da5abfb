// `vkrt-bench gpu scenes [DIR] [-w W -h H -r RPP] [--shader-dir DIR]`: every .xml and .json scene in DIR (the
// extension in any case, as loadScene reads them; default the upstream course scenes in ../shared,
// $VKRT_SHARED overriding as in the tests) rendered by the GPU kernel
// specialised to the scene, by the general kernel (every feature on), and by the CPU reference,
// all with the same options, each device from the scene it prepared itself (its own tree). One row
// per scene with both prepare times and both time ratios, then their median and range.
// The mean difference GPU vs CPU is printed too, so a broken render cannot pass as a fast one.
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench_args.h"
#include "bench_gpu.h"
#include "bench_timing.h"
#include "cpu_renderer.h"
#include "gpu_renderer.h"
#include "image_compare.h"
#include "scene_loader.h"

namespace vkrt::bench {

namespace {

struct Args {
    std::string dir;
    RenderOptions render;
    int repeat = 1;
    std::string shaderDir;  // render.comp compiled from DIR at run time: same-binary A/B runs of kernel edits
};

std::string defaultSceneDir() {
    const char* env = std::getenv("VKRT_SHARED");
    return std::string(env && *env ? env : VKRT_DEFAULT_SHARED_DIR) + "/scenes/upstream";
}

Args parseArgs(const std::vector<std::string>& args) {
    Args a;
    a.render.width = a.render.height = 128;  // small and few samples: ~55 scenes x 3 renders in minutes
    a.render.samplesPerPixel = 4;
    a.render.quiet = true;
    std::vector<std::string> positional;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const bool value = i + 1 < args.size();
        if (args[i] == "-w" && value) a.render.width = positiveInt(args[++i], "-w");
        else if (args[i] == "-h" && value) a.render.height = positiveInt(args[++i], "-h");
        else if (args[i] == "-r" && value) a.render.samplesPerPixel = positiveInt(args[++i], "-r");
        else if (args[i] == "--repeat" && value) a.repeat = positiveInt(args[++i], "--repeat");
        else if (args[i] == "--shader-dir" && value) a.shaderDir = args[++i];
        else if (args[i].rfind("-", 0) == 0) throw std::runtime_error("unknown option " + args[i]);
        else positional.push_back(args[i]);
    }
    if (positional.size() > 1)
        throw std::runtime_error("usage: vkrt-bench gpu scenes [DIR] [-w W] [-h H] [-r RPP] [--repeat N] [--shader-dir DIR]");
    a.dir = positional.empty() ? defaultSceneDir() : positional[0];
    return a;
}

// A scene file by its extension, as loadScene chooses the format: .xml or .json in any case.
bool isSceneFile(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".xml" || ext == ".json";
}

std::vector<std::filesystem::path> sceneFiles(const std::string& dir) {
    if (!std::filesystem::is_directory(dir)) throw std::runtime_error(dir + ": not a directory");
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        if (entry.is_regular_file() && isSceneFile(entry.path())) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    if (files.empty()) throw std::runtime_error(dir + ": no .xml or .json scenes");
    return files;
}

// Submission time of one GPU render of `variant`, median of `repeat`, after a small warm-up render
// of the same variant: the pipeline then exists and lavapipe has compiled it, so neither weighs in
// (GpuRenderStats::renderSeconds excludes them anyway; the warm-up also settles first-touch costs).
double gpuSeconds(GpuRenderer& gpu, const GpuSceneData& data, const RenderOptions& options, KernelVariant variant,
                  int repeat, Image* image) {
    GpuRenderSettings settings;
    settings.variant = variant;
    RenderOptions warm = options;
    warm.width = std::min(options.width, 16);
    warm.height = std::min(options.height, 16);
    gpu.render(data, warm, nullptr, settings);
    std::vector<double> seconds;
    for (int r = 0; r < repeat; ++r) {
        GpuRenderStats stats;
        *image = gpu.render(data, options, &stats, settings);
        seconds.push_back(stats.renderSeconds);
    }
    return median(seconds);
}

double cpuSeconds(const Scene& scene, const SceneAccel& accel, const RenderOptions& options, int repeat, Image* image) {
    std::vector<double> seconds;
    for (int r = 0; r < repeat; ++r) {
        RenderStats stats;
        *image = renderCpu(scene, accel, options, &stats);
        seconds.push_back(stats.seconds);
    }
    return median(seconds);
}

// Wall time of one prepare (each device's tree and tables).
template <class Prepare>
auto timedPrepare(Prepare prepare, double* seconds) {
    const auto start = std::chrono::steady_clock::now();
    auto prepared = prepare();
    *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return prepared;
}

void printSummary(const char* what, std::vector<double> v) {
    if (v.empty()) return;
    std::sort(v.begin(), v.end());
    std::printf("  %-22s median %.2f  range %.2f .. %.2f\n", what, median(v), v.front(), v.back());
}

}  // namespace

int runGpuScenesBench(const std::vector<std::string>& argv) {
    const Args a = parseArgs(argv);
    const std::vector<std::filesystem::path> files = sceneFiles(a.dir);
    GpuRendererOptions gpuOptions;
    if (!a.shaderDir.empty()) gpuOptions.shaderDir = a.shaderDir;
    GpuRenderer gpu(gpuOptions);
    if (!a.shaderDir.empty()) std::printf("# GPU kernels compiled from %s\n", a.shaderDir.c_str());
    std::printf("# %zu scenes in %s, %dx%d, %d rpp, depth %d, on %s; CPU reference on all cores\n", files.size(),
                a.dir.c_str(), a.render.width, a.render.height, a.render.samplesPerPixel, a.render.maxDepth,
                gpu.deviceName().c_str());
    std::printf("# timed: GPU = GpuRenderStats::renderSeconds (the submissions, first to last; no pipeline creation,\n"
                "#   LLVM compile, upload or readback; a 16x16 warm-up render of the same variant first); CPU = renderCpu's\n"
                "#   RenderStats::seconds (the render loop). Ratios are of times: general/spec > 1 means specialising pays,\n"
                "#   gpu/cpu > 1 means the GPU path (specialised) is slower. mean_diff = mean |GPU - CPU| of the 8-bit images.\n");
    if (a.repeat > 1) std::printf("# each time is the median of %d renders\n", a.repeat);
    std::printf("#   gpu_prep_s / cpu_prep_s: each device's prepare (its own BVH, and for the GPU the kernel's tables).\n");
    std::printf("%-42s %10s %10s %10s %8s %10s %10s %8s %10s\n", "scene", "gpu_prep_s", "spec_s", "general_s", "gen/spec",
                "cpu_prep_s", "cpu_s", "gpu/cpu", "mean_diff");

    std::vector<double> generalOverSpec, gpuOverCpu;
    int failed = 0;
    for (const std::filesystem::path& file : files) {
        const std::string label = file.filename().string();
        std::fflush(stdout);
        try {
            Diagnostics diagnostics;  // warnings of real course files are expected; not this tool's concern
            LoadOptions load{false, /*localOrigin=*/true};
            load.shaderEmitters = true;
            const Scene scene = loadScene(file.string(), load, diagnostics);
            double gpuPrepare = 0.0, cpuPrepare = 0.0;
            const GpuSceneData gpuData = timedPrepare([&] { return GpuRenderer::prepare(scene); }, &gpuPrepare);
            const SceneAccel cpuAccel = timedPrepare([&] { return prepareCpuScene(scene); }, &cpuPrepare);
            RenderOptions options = a.render;
            options.camera = scene.defaultCamera;
            Image spec, general, cpu;
            const double s = gpuSeconds(gpu, gpuData, options, KernelVariant::Specialised, a.repeat, &spec);
            const double g = gpuSeconds(gpu, gpuData, options, KernelVariant::General, a.repeat, &general);
            const double c = cpuSeconds(scene, cpuAccel, options, a.repeat, &cpu);
            const double diff = compareImages(spec, cpu).meanAbs;
            std::printf("%-42s %10.4f %10.4f %10.4f %8.2f %10.4f %10.4f %8.2f %10.5f\n", label.c_str(), gpuPrepare, s, g,
                        g / s, cpuPrepare, c, s / c, diff);
            generalOverSpec.push_back(g / s);
            gpuOverCpu.push_back(s / c);
        } catch (const std::exception& e) {
            std::printf("%-42s error: %s\n", label.c_str(), e.what());
            ++failed;
        }
    }
    std::printf("summary over %zu scenes (%d failed):\n", gpuOverCpu.size(), failed);
    printSummary("general/spec (time)", generalOverSpec);
    printSummary("gpu/cpu (time)", gpuOverCpu);
    return failed ? 1 : 0;
}

}  // namespace vkrt::bench
