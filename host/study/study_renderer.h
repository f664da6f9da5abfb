// Renders for studies: one interface over the GPU renderer and the CPU reference, timing each
// render the same way (wall time of the render call, scene and BVH already built).
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "gpu_renderer.h"
#include "image.h"
#include "render_options.h"
#include "scene.h"
#include "scene_accel.h"

namespace vkrt::study {

enum class Device { Gpu, Cpu };

std::string deviceName(Device device);             // "gpu", "cpu"
using vkrt::parseSampler;  // render_options.h
using vkrt::samplerName;

struct TimedRender {
    Image image;
    double seconds = 0.0;  // wall time of the render call
};

class StudyRenderer {
public:
    // gpu: open the Vulkan renderer with these options (throws VulkanUnavailable when there is no
    // device); nullopt: CPU only.
    explicit StudyRenderer(const std::optional<GpuRendererOptions>& gpu);

    bool hasGpu() const { return gpu_ != nullptr; }
    std::string gpuDeviceName() const;
    // The GPU renderer's validation log (nullptr without GPU or validation).
    std::shared_ptr<const ValidationLog> validationLog() const;

    // One render. `sampleVariance` (CPU only, else std::invalid_argument): the per-pixel sample
    // variance (cpu_renderer.h). GPU renders are timed after the kernel variant for the scene has
    // been created once (an untimed 1-rpp warm-up), so pipeline compilation is not counted.
    // `accel` is the CPU's tree; a GPU render builds (untimed) and uses the tree `vkrt` builds for
    // the GPU (gpu_build_options.h), so study times are the times a user gets.
    TimedRender render(Device device, const Scene& scene, const SceneAccel& accel, const RenderOptions& options,
                       Image* sampleVariance = nullptr);

private:
    std::unique_ptr<GpuRenderer> gpu_;
    const Scene* warmedScene_ = nullptr;
};

}  // namespace vkrt::study
