// Renders for studies: one interface over the GPU renderer and the CPU reference, timing each
// render the same way (wall time of the render call, the scene prepared once for both devices).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <tuple>

#include "adaptive_render.h"
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

// A scene prepared for every open device, each with its own tree (as `vkrt` renders it), so that
// study times are the times a user gets. Render it as often as needed. The scene must outlive it.
struct PreparedScene {
    const Scene* scene = nullptr;
    SceneAccel cpu;                  // prepareCpuScene: also what region masks probe
    std::optional<GpuSceneData> gpu; // GpuRenderer::prepare, when a GPU renderer is open
    std::uint64_t id = 0;            // unique per prepare: GPU warm-ups are per prepared scene
};

struct TimedRender {
    Image image;
    double seconds = 0.0;  // wall time of the render call
    double meanRpp = 0.0;  // an adaptive render's mean samples per pixel (0 for a uniform one)
};

class StudyRenderer {
public:
    // gpu: open the Vulkan renderer with these options (throws VulkanUnavailable when there is no
    // device); nullopt: CPU only.
    explicit StudyRenderer(const std::optional<GpuRendererOptions>& gpu);

    std::string gpuDeviceName() const;
    // The GPU renderer's validation log (nullptr without GPU or validation).
    std::shared_ptr<const ValidationLog> validationLog() const;

    // Both trees (the GPU's only when a GPU renderer is open), untimed.
    PreparedScene prepare(const Scene& scene) const;

    // One render. `sampleVariance` (CPU only, else std::invalid_argument): the per-pixel sample
    // variance (cpu_renderer.h). GPU renders are timed after the kernel variant for the scene, sampler,
    // estimator and rpp has been created (an untimed one-row warm-up), so pipeline compilation is not counted.
    TimedRender render(Device device, const PreparedScene& scene, const RenderOptions& options,
                       Image* sampleVariance = nullptr);

    // An adaptive render (adaptive_render.h) of options.sampler up to adaptive.maxRpp, timed as
    // render() times: on the GPU after an untimed one-row warm-up of the adaptive kernel.
    TimedRender renderAdaptive(Device device, const PreparedScene& scene, const RenderOptions& options,
                               const adaptive::AdaptiveOptions& adaptive);

private:
    std::unique_ptr<GpuRenderer> gpu_;
    // (PreparedScene::id, sampler, estimator, rpp) of the GPU renders warmed up so far.
    std::set<std::tuple<std::uint64_t, std::uint32_t, std::uint32_t, int>> warmed_;
};

}  // namespace vkrt::study
