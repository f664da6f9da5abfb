// The GPU renderer: a scene in, the same image as the CPU reference out (docs/RENDERING.md),
// computed by the Vulkan compute kernel (shaders/render.comp). No Vulkan types in this header.
//
//   GpuRenderer gpu({.validation = true});          // device, layouts, kernel: kept across renders
//   const GpuSceneData data = GpuRenderer::prepare(scene);   // the GPU's tree and tables, once
//   Image image = gpu.render(data, options, &stats);         // as often as needed
//
// Errors: VulkanUnavailable (no device: fall back to the CPU), DeviceLimitExceeded (scene too
// large for the device), ShaderCompileError (--shader-dir GLSL), GpuKernelError (the kernel hit
// a budget), RenderCancelled (options.cancel was set), std::invalid_argument (bad options).
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "device_list.h"
#include "gpu_options.h"
#include "image.h"
#include "kernel_error.h"
#include "kernel_inputs.h"
#include "pixel_accumulation.h"
#include "render_options.h"
#include "scene.h"
#include "tile_planner.h"
#include "validation_log.h"
#include "vulkan_errors.h"

namespace vkrt {

class SceneUpload;

// How the GPU computes a render: the megakernel (render.comp: one invocation computes a sample's
// whole path) or the wavefront stages (wavefront_renderer.h: waves of paths, one stage per kernel).
// Auto picks by device (chooseGpuKernel).
enum class GpuKernel { Auto, Megakernel, Wavefront };

// Auto's choice: the megakernel on lavapipe, where it renders 1.6-3.1 times faster than the stages
// (a CPU runs one lane group per core and hides no latency with occupancy, so every stage's trip
// through memory is pure cost); the wavefront stages on every other device, whose compilers give the
// megakernel 232-256 registers per lane, spills and 4 waves per SIMD but the stages at most 120
// registers, no spills and 8-32 waves (RADV, docs/BENCHMARKS.md "Kernel registers").
GpuKernel chooseGpuKernel(const DeviceInfo& device);

struct GpuRenderSettings {
    KernelVariant variant = KernelVariant::Specialised;
    GpuKernel kernel = GpuKernel::Auto;
    std::uint64_t wavePaths = 0;  // wavefront: paths in flight per wave; 0: the device's (wavefront_renderer.h),
                                  // tests force fewer (the image does not depend on it)
    TilingPolicy tiling;  // submission target time, or fixed tiles for tests
    std::uint32_t samplesPerDispatch = 0;  // samples per pixel per dispatch; 0: the scene's bound decides
                                           // (sample_batching.h), tests force one
};

struct GpuRenderStats {
    std::string device;
    std::string features;         // the specialisation, FeatureSet::describe()
    bool wavefront = false;       // computed by the wavefront stages (GpuKernel::Wavefront)
    bool generalKernel = false;
    double pipelineSeconds = 0.0; // creating the kernel variant (0 when it was cached)
    double warmUpSeconds = 0.0;   // an empty dispatch: lavapipe's LLVM compile of the variant happens
                                  // here (~0.1-1 s) the first time it meets these resources
    double uploadSeconds = 0.0;   // the prepared scene's arrays into device buffers (or only the frame)
    bool sceneUploaded = false;   // the tables were uploaded by this render (else kept from the last)
    double renderSeconds = 0.0;   // all submissions, first to last (wall clock)
    double kernelSeconds = -1.0;  // the submissions' device time, by timestamps; -1 without them
    double readbackSeconds = 0.0;
    std::uint32_t submissions = 0;
    std::uint32_t dispatches = 0;
    std::uint32_t samplesPerDispatch = 1;  // each dispatch's samples per pixel (sample_batching.h)
    double maxSubmissionSeconds = 0.0;
    std::uint64_t sceneBytes = 0;        // device memory of the scene's buffers
    std::uint32_t nonFiniteSamples = 0;  // NaN/Inf radiance samples the kernel replaced by black
    std::uint64_t overflowedPixels = 0;  // finite samples summed past float: clamped (float_range.h)
};

// One submission's times into the render's stats: its wall-clock seconds, and the device's own
// (timestamps; negative where the queue writes none). The renderer's loops (megakernel passes,
// adaptive passes, wavefront waves) all count through this.
void countSubmission(GpuRenderStats& stats, double wallSeconds, double deviceSeconds);

class GpuRenderer {
public:
    // Creates the device, layouts and loads the kernel (compiling it with --shader-dir).
    explicit GpuRenderer(const GpuRendererOptions& options = {}, const GpuTestHooks& hooks = {});
    ~GpuRenderer();
    GpuRenderer(const GpuRenderer&) = delete;
    GpuRenderer& operator=(const GpuRenderer&) = delete;

    // The GPU's own tree and the kernel's tables (kernel_inputs.h); needs no device. The scene
    // must outlive the result.
    static GpuSceneData prepare(const Scene& scene) { return prepareGpuScene(scene); }

    Image render(const GpuSceneData& data, const RenderOptions& options, GpuRenderStats* stats = nullptr,
                 const GpuRenderSettings& settings = {});

    // Adaptive sampling's round on the GPU (adaptive_render.h AddSamples): adds samples
    // [acc.count[p], next[p]) of every pixel p to acc.sum and acc.oddSum, in sample order, as
    // render() computes them, and sets acc.count = next. Only the pixels with samples to add are
    // dispatched: a work list, sorted by samples to add, whose pass j covers the entries with more
    // than j k samples. options.samplesPerPixel is the most any pixel will have (--max-rpp). With the
    // wavefront stages (`kernel`, Auto: chooseGpuKernel), waves of entries times sample offsets.
    void addSampleRanges(const GpuSceneData& data, const RenderOptions& options, const std::vector<std::uint32_t>& next,
                         adaptive::PixelAccumulation& acc, GpuRenderStats* stats = nullptr, GpuKernel kernel = GpuKernel::Auto);

    // Loads the kernel again (with --shader-dir, compiles the GLSL as it is now) and drops the
    // pipelines made from the old one; returns the seconds it took. On an error in render.comp
    // (ShaderCompileError) the old kernel stays; the wavefront stages' files are compiled at their
    // next use, so an error there is thrown by the next wavefront render (kernel_modules.h).
    double reloadKernel();

    std::string deviceName() const;
    // The device's description (device_list.h): its driver, whether it is lavapipe, its limits.
    const DeviceInfo& deviceInfo() const;
    // nullptr unless validation is on; stays readable after the renderer is destroyed.
    std::shared_ptr<const ValidationLog> validationLog() const;
    // Kernel variants created so far (one per distinct feature set).
    std::size_t pipelineCount() const;

private:
    // addSampleRanges' dispatches on the megakernel (its ADAPTIVE variant): `contents` the buffer's
    // sums and work list, `work` the list alone.
    void addSampleRangesMegakernel(SceneUpload& gpuScene, const KernelInputs& in, const RenderOptions& options,
                                   const std::vector<glm::uvec4>& contents, const std::vector<glm::uvec4>& work, int width,
                                   GpuRenderStats& stats);
    Image renderWavefront(const GpuSceneData& data, const KernelInputs& in, const RenderOptions& options, std::uint64_t wavePaths,
                          GpuRenderStats& stats, GpuRenderStats* statsOut);

    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace vkrt
