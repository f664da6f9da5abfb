// `vkrt-bench gpu kernels [SCENES|DIRS...] [--general] [--adaptive] [--wavefront] [--gpu N] [--shader-dir DIR] [-k DEPTH]`:
// every render-kernel variant those scenes need, built (never run) on the selected device, with
// what its compiler reports: registers, spilled registers, scratch, waves per SIMD and compile
// time (VK_KHR_pipeline_executable_properties; RADV reports them all, NVIDIA some, lavapipe none).
// Prefers a compile-only device: with RADV_FORCE_FAMILY=navi21 and the radeon ICD, Mesa's RADV/ACO
// compiles for a Navi 21 without AMD hardware (docs/BENCHMARKS.md, "Kernel registers"). Default
// scenes: the course's XML and JSON in ../shared (VKRT_SHARED overrides). The last line:
// `kernels: N variants, max VGPRs X, spilled VGPRs Y, max scratch Z bytes`; with --wavefront (the
// wavefront renderer's six stage kernels per scene, after the megakernel; with --adaptive also their
// adaptive variants, `a-<stage>`) a line of the same form for each of the two renderers precedes it
// (`megakernel: ...`, `wavefront: ...`).
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench_args.h"
#include "bench_gpu.h"
#include "gpu_renderer.h"
#include "kernel_statistics.h"
#include "scene_loader.h"

namespace vkrt::bench {

namespace {

struct Args {
    std::vector<std::string> inputs;
    RenderOptions render;
    bool general = false;
    bool adaptive = false;  // also the variant of adaptive sampling's rounds (--target-error)
    bool wavefront = false; // also the wavefront renderer's stages (--gpu-kernel wavefront)
    GpuRendererOptions gpu;
};

std::string sharedDir() {
    const char* env = std::getenv("VKRT_SHARED");
    return env && *env ? env : VKRT_DEFAULT_SHARED_DIR;
}

Args parseArgs(const std::vector<std::string>& args) {
    Args a;
    a.render.quiet = true;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const bool value = i + 1 < args.size();
        if (args[i] == "--general") a.general = true;
        else if (args[i] == "--adaptive") a.adaptive = true;
        else if (args[i] == "--wavefront") a.wavefront = true;
        else if (args[i] == "--gpu" && value) a.gpu.gpu = static_cast<int>(nonNegativeNumber(args[++i], "--gpu"));
        else if (args[i] == "--shader-dir" && value) a.gpu.shaderDir = args[++i];
        else if (args[i] == "-k" && value) a.render.maxDepth = positiveInt(args[++i], "-k");
        else if (args[i].rfind("-", 0) == 0)
            throw std::runtime_error("unknown option " + args[i] +
                                     " (usage: vkrt-bench gpu kernels [SCENES|DIRS...] [--general] [--adaptive] [--wavefront] [--gpu N] [--shader-dir DIR] [-k DEPTH])");
        else a.inputs.push_back(args[i]);
    }
    if (a.inputs.empty())
        a.inputs = {sharedDir() + "/scenes/upstream", sharedDir() + "/scenes/json"};
    return a;
}

bool isSceneFile(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".xml" || ext == ".json";
}

// Files as given; a folder's .xml and .json files (not its subfolders: they hold assets), sorted.
std::vector<std::filesystem::path> sceneFiles(const std::vector<std::string>& inputs) {
    std::vector<std::filesystem::path> files;
    for (const std::string& input : inputs) {
        if (std::filesystem::is_directory(input)) {
            std::vector<std::filesystem::path> found;
            for (const auto& entry : std::filesystem::directory_iterator(input))
                if (entry.is_regular_file() && isSceneFile(entry.path())) found.push_back(entry.path());
            std::sort(found.begin(), found.end());
            if (found.empty()) throw std::runtime_error(input + ": no .xml or .json scenes");
            files.insert(files.end(), found.begin(), found.end());
        } else if (std::filesystem::is_regular_file(input)) {
            files.emplace_back(input);
        } else {
            throw std::runtime_error(input + ": no such scene file or folder");
        }
    }
    return files;
}

std::string number(double v, const char* format = "%.0f") {
    if (v < 0) return "-";
    char text[32];
    std::snprintf(text, sizeof text, format, v);
    return text;
}

}  // namespace

int runGpuKernelsBench(const std::vector<std::string>& argv) {
    const Args a = parseArgs(argv);
    // Compile times are the compiler's, not Mesa's on-disk cache's (a second run would read 1 ms);
    // MESA_SHADER_CACHE_DISABLE=false in the environment keeps the cache.
    setenv("MESA_SHADER_CACHE_DISABLE", "true", 0);
    const std::vector<std::filesystem::path> files = sceneFiles(a.inputs);
    KernelStatisticsCompiler compiler(a.gpu);
    std::printf("# %zu scenes; render kernel variants built on %s (%s), not run\n", files.size(), compiler.deviceName().c_str(),
                compiler.driver().c_str());
    if (!compiler.hasStatistics())
        std::printf("# this device reports no compiler statistics (VK_KHR_pipeline_executable_properties): compile times only\n");
    std::printf("# vgprs/sgprs: registers per lane/wave; spilled: registers moved to scratch memory; scratch: bytes per\n"
                "#   wave; waves: per SIMD (occupancy); compile_s: pipeline creation; '=' marks a variant built for an\n"
                "#   earlier scene (same features)\n");
    std::printf("%-40s %-8s %6s %8s %6s %8s %9s %6s %9s  %s\n", "scene", "stage", "vgprs", "spilled", "sgprs", "spilled",
                "scratch", "waves", "compile_s", "features");
    // Per renderer: 0 the megakernel (its specialised, general and adaptive variants), 1 the wavefront stages.
    struct Totals {
        double maxVgprs = 0, spilledVgprs = 0, maxScratch = 0;
        std::size_t variants = 0;
    };
    Totals totals[2];
    double maxVgprs = 0, spilledVgprs = 0, maxScratch = 0;
    int failed = 0;
    for (const std::filesystem::path& file : files) {
        const std::string label = file.filename().string();
        try {
            Diagnostics diagnostics;  // warnings of real course files are expected; not this tool's concern
            LoadOptions load{false, /*localOrigin=*/true};
            load.shaderEmitters = true;
            const Scene scene = loadScene(file.string(), load, diagnostics);
            const GpuSceneData data = GpuRenderer::prepare(scene);
            RenderOptions options = a.render;
            options.camera = scene.defaultCamera;
            std::vector<KernelVariant> variants{KernelVariant::Specialised};
            if (a.general) variants.push_back(KernelVariant::General);
            struct Build {
                KernelVariant variant;
                bool adaptive;
                std::uint32_t wavefrontStage;
            };
            std::vector<Build> builds;
            for (const KernelVariant variant : variants) builds.push_back({variant, false, gpu::WAVEFRONT_OFF});
            if (a.adaptive) builds.push_back({KernelVariant::Specialised, true, gpu::WAVEFRONT_OFF});
            if (a.wavefront)
                for (const bool adaptive : {false, true}) {
                    if (adaptive && !a.adaptive) continue;
                    for (std::uint32_t s = gpu::WAVEFRONT_GENERATE; s < gpu::WAVEFRONT_STAGE_COUNT; ++s)
                        builds.push_back({KernelVariant::Specialised, adaptive, s});
                }
            for (const auto& [variant, adaptive, wavefrontStage] : builds) {
                const KernelVariantReport r = compiler.compile(data, options, variant, adaptive, wavefrontStage);
                const std::string stage = variant == KernelVariant::General ? "general"
                                          : adaptive && wavefrontStage == gpu::WAVEFRONT_OFF ? "adaptive"
                                          : adaptive ? "a-" + r.stage
                                                     : r.stage;
                std::printf("%-40s %-8s %6s %8s %6s %8s %9s %6s %9s  %s%s (k=%u)\n", label.c_str(), stage.c_str(),
                            number(r.vgprs).c_str(), number(r.spilledVgprs).c_str(), number(r.sgprs).c_str(),
                            number(r.spilledSgprs).c_str(), number(r.scratchBytes).c_str(), number(r.wavesPerSimd).c_str(),
                            number(r.compileSeconds, "%.3f").c_str(), r.cached ? "= " : "", r.features.c_str(), r.samplesPerDispatch);
                maxVgprs = std::max(maxVgprs, r.vgprs);
                maxScratch = std::max(maxScratch, r.scratchBytes);
                if (!r.cached) spilledVgprs += std::max(0.0, r.spilledVgprs);
                Totals& t = totals[wavefrontStage == gpu::WAVEFRONT_OFF ? 0 : 1];
                t.maxVgprs = std::max(t.maxVgprs, r.vgprs);
                t.maxScratch = std::max(t.maxScratch, r.scratchBytes);
                if (!r.cached) {
                    t.spilledVgprs += std::max(0.0, r.spilledVgprs);
                    ++t.variants;
                }
            }
        } catch (const std::exception& e) {
            std::printf("%-40s error: %s\n", label.c_str(), e.what());
            ++failed;
        }
        std::fflush(stdout);
    }
    if (a.wavefront && compiler.hasStatistics())
        for (int k = 0; k < 2; ++k)
            std::printf("%s: %zu variants, max VGPRs %s, spilled VGPRs %s, max scratch %s bytes\n", k == 0 ? "megakernel" : "wavefront",
                        totals[k].variants, number(totals[k].maxVgprs).c_str(), number(totals[k].spilledVgprs).c_str(),
                        number(totals[k].maxScratch).c_str());
    std::printf("kernels: %zu variants, max VGPRs %s, spilled VGPRs %s, max scratch %s bytes\n", compiler.variants(),
                compiler.hasStatistics() ? number(maxVgprs).c_str() : "-",
                compiler.hasStatistics() ? number(spilledVgprs).c_str() : "-",
                compiler.hasStatistics() ? number(maxScratch).c_str() : "-");
    std::fflush(stdout);
    return failed ? 1 : 0;
}

}  // namespace vkrt::bench
