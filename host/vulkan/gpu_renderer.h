// The GPU renderer: a scene in, the same image as the CPU reference out (docs/RENDERING.md),
// computed by the Vulkan compute kernel (shaders/render.comp). No Vulkan types in this header.
//
//   GpuRenderer gpu({.validation = true});          // device, layouts, kernel: kept across renders
//   Image image = gpu.render(scene, accel, options, &stats);
//
// Errors: VulkanUnavailable (no device: fall back to the CPU), DeviceLimitExceeded (scene too
// large for the device), ShaderCompileError (--shader-dir GLSL), GpuKernelError (the kernel hit
// a budget), RenderCancelled (options.cancel was set), std::invalid_argument (bad options).
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "image.h"
#include "render_options.h"
#include "scene.h"
#include "scene_accel.h"
#include "tile_planner.h"
#include "validation_log.h"

namespace vkrt {

struct GpuRendererOptions {
    int gpu = -1;             // --gpu N (index of listDevices()); -1 chooses discrete > integrated > cpu
    bool validation = false;  // --validate: Khronos validation layers, messages in validationLog()
    std::optional<std::filesystem::path> shaderDir;  // --shader-dir: compile DIR/render.comp at run time
    std::vector<std::uint32_t> kernelSpirv;          // tests: this SPIR-V instead of the render kernel
    std::optional<std::uint64_t> maxBufferBytes;     // tests: cap the per-buffer device limits
    bool forceStaging = false;                       // tests: staging copies even on a CPU device
};

enum class KernelVariant {
    Specialised,  // only the paths the scene uses (the default)
    General       // every feature on: the specialisation benchmark's baseline
};

struct GpuRenderSettings {
    KernelVariant variant = KernelVariant::Specialised;
    TilingPolicy tiling;  // submission target time, or fixed tiles for tests
    std::uint32_t samplesPerDispatch = 0;  // samples per pixel per dispatch; 0: the scene's bound decides
                                           // (sample_batching.h), tests force one
};

struct GpuRenderStats {
    std::string device;
    std::string features;         // the specialisation, FeatureSet::describe()
    bool generalKernel = false;
    double pipelineSeconds = 0.0; // creating the kernel variant (0 when it was cached)
    double warmUpSeconds = 0.0;   // an empty dispatch: lavapipe's LLVM compile of the variant happens
                                  // here (~0.1-1 s) the first time it meets these resources
    double uploadSeconds = 0.0;   // scene tables and BVH into device buffers
    double renderSeconds = 0.0;   // all submissions, first to last
    double readbackSeconds = 0.0;
    std::uint32_t submissions = 0;
    std::uint32_t dispatches = 0;
    std::uint32_t samplesPerDispatch = 1;  // each dispatch's samples per pixel (sample_batching.h)
    double maxSubmissionSeconds = 0.0;
    std::uint64_t sceneBytes = 0;        // device memory of the scene's buffers
    std::uint32_t nonFiniteSamples = 0;  // NaN/Inf radiance samples the kernel replaced by black
};

class GpuRenderer {
public:
    // Creates the device, layouts and loads the kernel (compiling it with --shader-dir).
    explicit GpuRenderer(const GpuRendererOptions& options = {});
    ~GpuRenderer();
    GpuRenderer(const GpuRenderer&) = delete;
    GpuRenderer& operator=(const GpuRenderer&) = delete;

    Image render(const Scene& scene, const SceneAccel& accel, const RenderOptions& options, GpuRenderStats* stats = nullptr,
                 const GpuRenderSettings& settings = {});

    std::string deviceName() const;
    // nullptr unless validation is on; stays readable after the renderer is destroyed.
    std::shared_ptr<const ValidationLog> validationLog() const;
    // Kernel variants created so far (one per distinct feature set).
    std::size_t pipelineCount() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// One render on a fresh GpuRenderer.
Image renderGpu(const Scene& scene, const SceneAccel& accel, const RenderOptions& options, GpuRenderStats* stats = nullptr,
                const GpuRendererOptions& gpu = {});

}  // namespace vkrt
