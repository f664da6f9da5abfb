#include "render_steps.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>

#include <sys/resource.h>
#include <unistd.h>

#include "camera_basis.h"
#include "cpu_renderer.h"
#include "device_choice.h"
#include "device_list.h"
#include "interrupt.h"
#include "output_file.h"
#include "scene_inputs.h"
#include "scene_loader.h"
#include "scene_writing.h"

namespace vkrt {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void checkNotASceneInput(const std::string& output, const Scene& scene) {
    for (const SceneInput& input : sceneInputs(scene)) {
        std::error_code ec;
        if (std::filesystem::equivalent(output, input.path, ec))
            throw std::runtime_error(output + ": is " + input.kind + " that " + scene.path + " reads (" + input.path.string() +
                                     "); choose another output name (-o)");
    }
}

void printWarnings(const Diagnostics& diagnostics, bool quiet) {
    if (quiet) return;
    for (const std::string& line : diagnostics.summary()) std::cerr << "warning: " << line << "\n";
}

// Loads the scene, prints its warnings, and settles which camera renders.
Scene loadWithWarnings(CommandLine& cl) {
    Diagnostics diagnostics(cl.strict);
    Scene scene = [&] {
        const ExitAtOnceOnInterrupt scope;  // a large mesh or texture takes seconds to read
        try {
            LoadOptions load{cl.strict, /*localOrigin=*/true};
            load.shaderEmitters = true;
            return loadScene(cl.scenePath, load, diagnostics);
        } catch (...) {
            // The warnings before the error may say why it happened (`tpye="point"`, then
            // "missing required attribute type").
            printWarnings(diagnostics, cl.render.quiet);
            throw;
        }
    }();
    printWarnings(diagnostics, cl.render.quiet);
    // An image written over a file the scene reads would destroy the scene's own input.
    for (const std::string& output : {cl.outputPath, cl.heatMapPath})
        if (!output.empty()) checkNotASceneInput(output, scene);
    cl.render.camera = cl.camera.value_or(scene.defaultCamera);
    if (cl.render.camera >= static_cast<int>(scene.cameras.size()))
        throw std::invalid_argument("--camera " + std::to_string(cl.render.camera) + ": " + cl.scenePath + " has " +
                                    std::to_string(scene.cameras.size()) + " camera(s)");
    // The command line's lens overrides the scene's, as the course's -d does.
    Camera& camera = scene.cameras[cl.render.camera];
    if (cl.focusDistance) camera.focusDistance = *cl.focusDistance;
    if (cl.aperture) camera.aperture = *cl.aperture;
    // --up replaces the camera's up vector; only now is the gaze it must not be parallel to known.
    if (cl.up) {
        if (const std::string p = upProblem(*cl.up, camera.gaze); !p.empty())
            throw std::invalid_argument("--up " + writing::vec3Text(*cl.up) + ": " + p + " (camera " + std::to_string(cl.render.camera) +
                                        " of " + cl.scenePath + " looks along " + writing::vec3Text(camera.gaze) + ")");
        camera.up = cl.up;
    }
    // Half a lens asked for on the command line is said (a warning, so not under -q); `--aperture 0`
    // (the pinhole on purpose) is not.
    const bool askedForLens = cl.focusDistance.value_or(0.0f) > 0.0f || cl.aperture.value_or(0.0f) > 0.0f;
    if (!cl.render.quiet && askedForLens && (camera.focusDistance > 0.0f) != (camera.aperture > 0.0f))
        std::cerr << "warning: focus distance " << camera.focusDistance << ", aperture " << camera.aperture
                  << ": depth of field needs both above 0 (-d/--focus-distance and --aperture, or the camera's "
                     "focusDistance and aperture); rendering with a pinhole\n";
    return scene;
}

GpuRendererOptions gpuOptions(const CommandLine& cl) {
    GpuRendererOptions options;
    options.gpu = cl.gpuIndex;
    options.validation = cl.validate;
    options.fallBack = cl.device != DeviceChoice::Gpu;
    if (!cl.shaderDir.empty()) options.shaderDir = cl.shaderDir;
    return options;
}


// The render's samples that were not finite, and its pixels whose finite samples summed past float
// (RENDERING.md §8): both devices count them alike.
static void warnAboutRadiance(std::uint64_t nonFiniteSamples, std::uint64_t overflowedPixels, bool quiet) {
    if (quiet) return;  // -q: "no progress bar, summary or warnings"
    if (nonFiniteSamples > 0) std::cerr << "warning: " << nonFiniteSamples << " samples were NaN/Inf and were replaced by black\n";
    if (overflowedPixels > 0)
        std::cerr << "warning: " << overflowedPixels << " pixel(s) summed their samples past float's range (radiance near 3.4e38): "
                  << "clamped to 3.4e38 (docs/RENDERING.md §8)\n";
}

DeviceRender renderPreparedOnCpu(const Scene& scene, const SceneAccel& accel, const RenderOptions& options) {
    RenderStats stats;
    Image image = renderCpu(scene, accel, options, &stats);
    warnAboutRadiance(stats.nonFiniteSamples, stats.overflowedPixels, options.quiet);
    return {std::move(image), "cpu (" + std::to_string(stats.threads) + (stats.threads == 1 ? " thread)" : " threads)"), 0.0, stats.seconds};
}

DeviceRender renderOnCpu(const Scene& scene, const RenderOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    const SceneAccel accel = [&] {
        const ExitAtOnceOnInterrupt scope;  // the tree of a large mesh takes seconds
        return prepareCpuScene(scene);
    }();
    const double prepareSeconds = secondsSince(start);
    DeviceRender result = renderPreparedOnCpu(scene, accel, options);
    result.prepareSeconds = prepareSeconds;
    return result;
}

GpuRenderSettings gpuSettingsOf(const CommandLine& cl) {
    GpuRenderSettings settings;
    settings.variant = cl.general ? KernelVariant::General : KernelVariant::Specialised;
    settings.kernel = cl.gpuKernel == "wavefront"    ? GpuKernel::Wavefront
                      : cl.gpuKernel == "megakernel" ? GpuKernel::Megakernel
                                                     : GpuKernel::Auto;
    return settings;
}

DeviceRender renderPreparedOnGpu(GpuRenderer& gpu, const GpuSceneData& data, const RenderOptions& options,
                                 const GpuRenderSettings& settings) {
    GpuRenderStats stats;
    Image image = gpu.render(data, options, &stats, settings);
    warnAboutRadiance(stats.nonFiniteSamples, stats.overflowedPixels, options.quiet);
    if (auto log = gpu.validationLog(); log && log->count() > 0)
        std::cerr << "warning: " << log->count() << " Vulkan validation message(s):\n" << log->joined();
    // The kernel variant that ran: what the scene needed (feature_set.h), and the samples each
    // invocation computed (sample_batching.h), for shader developers.
    // And the device's own time for the submissions (timestamps), where the queue writes them.
    char deviceTime[48] = "";
    if (stats.kernelSeconds >= 0.0) std::snprintf(deviceTime, sizeof deviceTime, "; device time %.3fs", stats.kernelSeconds);
    const std::string kernel = (stats.generalKernel ? "general kernel, " + stats.features : "kernel: " + stats.features) +
                               (stats.wavefront ? "; wavefront stages" : "; samples/dispatch=" + std::to_string(stats.samplesPerDispatch)) +
                               deviceTime;
    return {std::move(image), stats.device + " [" + kernel + "]", 0.0, stats.renderSeconds + stats.readbackSeconds,
            stats.pipelineSeconds + stats.warmUpSeconds, /*onGpu=*/true};
}

DeviceRender renderOnGpu(GpuRenderer& gpu, const Scene& scene, const RenderOptions& options, const GpuRenderSettings& settings) {
    const auto start = std::chrono::steady_clock::now();
    const GpuSceneData data = [&] {
        const ExitAtOnceOnInterrupt scope;
        return GpuRenderer::prepare(scene);
    }();
    const double prepareSeconds = secondsSince(start);
    DeviceRender result = renderPreparedOnGpu(gpu, data, options, settings);
    result.prepareSeconds = prepareSeconds;
    return result;
}

bool asksForVulkan(const CommandLine& cl) {
    return cl.gpuIndex >= 0 || !cl.shaderDir.empty() || cl.general || cl.gpuKernel != "auto" || cl.validate;
}

// --device auto where every Vulkan device runs on the CPU: the CPU reference, said once unless -q.
// Without a loader the answer is no: opening the GPU then says why.
bool autoRendersOnTheCpuReference(const CommandLine& cl) {
    if (cl.device != DeviceChoice::Auto || asksForVulkan(cl)) return false;
    AutoDevice choice;
    try {
        choice = chooseAutoDevice(listDevices());
    } catch (const VulkanUnavailable&) {
        return false;
    }
    if (choice.cpuReference && !cl.render.quiet) std::cerr << "note: " << choice.reason << "\n";
    return choice.cpuReference;
}

// --device auto: the GPU when a Vulkan device exists, else the CPU reference with a message.
std::unique_ptr<GpuRenderer> openGpu(const CommandLine& cl) {
    if (cl.device == DeviceChoice::Cpu || autoRendersOnTheCpuReference(cl)) return nullptr;
    try {
        return std::make_unique<GpuRenderer>(gpuOptions(cl));
    } catch (const VulkanUnavailable& e) {
        if (cl.device == DeviceChoice::Gpu) throw;
        std::cerr << "note: no usable Vulkan device (" << e.what() << "); rendering on the CPU reference\n";
        return nullptr;
    }
}

// The float RGB image every renderer returns: a lower bound on what a render needs.
long long imageMiB(int width, int height) {
    return static_cast<long long>(width) * height * static_cast<long long>(sizeof(glm::vec3)) >> 20;
}

// Refuses, before the scene is loaded, an image whose pixels alone exceed this machine's memory
// (or the process's address-space limit, ulimit -v, when that is lower).
void checkImageFitsInMemory(int width, int height) {
    const long long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGESIZE);
    if (pages <= 0 || pageSize <= 0) return;  // unknown: the allocation itself will say
    long long physicalMiB = (pages * pageSize) >> 20;
    rlimit limit{};
    if (::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
        physicalMiB = std::min(physicalMiB, static_cast<long long>(limit.rlim_cur >> 20));
    if (imageMiB(width, height) > physicalMiB)
        throw std::runtime_error("a " + std::to_string(width) + "x" + std::to_string(height) + " image needs " +
                                 std::to_string(imageMiB(width, height)) + " MiB for its float pixels alone; this " +
                                 "machine has " + std::to_string(physicalMiB) + " MiB (use a smaller -w/-h)");
}

// Before the render, so that a long render is not thrown away for a bad -o.
void checkOutputBeforeRendering(const std::string& output, const std::string& scenePath) {
    checkImageOutputPath(output);
    checkNotTheInput(output, scenePath);
}

// The render itself: load, pick the device, render (what one process or one MPI rank does).
DeviceRender renderScene(CommandLine& cl) {
    const Scene scene = loadWithWarnings(cl);
    std::unique_ptr<GpuRenderer> gpu = openGpu(cl);
    DeviceRender result;
    try {
        result = gpu ? renderOnGpu(*gpu, scene, cl.render, gpuSettingsOf(cl)) : renderOnCpu(scene, cl.render);
    } catch (const GpuKernelError& e) {
        // The kernel refused this scene (e.g. lavapipe's loop limiter): with --device auto the
        // CPU reference computes the same image; with --device gpu the error stands.
        if (cl.device != DeviceChoice::Auto) throw;  // app.cpp names the scene file
        noteCpuFallback(scene.path, e);
        result = renderOnCpu(scene, cl.render);
    }
    return result;
}

GpuKernelError kernelErrorIn(const std::string& scenePath, const GpuKernelError& e) {
    return GpuKernelError(scenePath + ": " + e.what());
}

void noteCpuFallback(const std::string& scenePath, const GpuKernelError& e) {
    std::cerr << "note: " << kernelErrorIn(scenePath, e).what() << "\nnote: rendering on the CPU reference instead\n";
}

}  // namespace vkrt
