#include "study_renderer.h"

#include <atomic>
#include <chrono>
#include <stdexcept>

#include "cpu_renderer.h"

namespace vkrt::study {

std::string deviceName(Device device) { return device == Device::Gpu ? "gpu" : "cpu"; }

StudyRenderer::StudyRenderer(const std::optional<GpuRendererOptions>& gpu) {
    if (gpu) gpu_ = std::make_unique<GpuRenderer>(*gpu);
}

std::string StudyRenderer::gpuDeviceName() const { return gpu_ ? gpu_->deviceName() : std::string("none"); }

std::shared_ptr<const ValidationLog> StudyRenderer::validationLog() const { return gpu_ ? gpu_->validationLog() : nullptr; }

PreparedScene StudyRenderer::prepare(const Scene& scene) const {
    static std::atomic<std::uint64_t> prepared{0};
    PreparedScene p;
    p.scene = &scene;
    p.cpu = prepareCpuScene(scene);
    if (gpu_) p.gpu = GpuRenderer::prepare(scene);
    p.id = ++prepared;
    return p;
}

TimedRender StudyRenderer::render(Device device, const PreparedScene& scene, const RenderOptions& options,
                                  Image* sampleVariance) {
    TimedRender out;
    if (device == Device::Cpu) {
        const auto start = std::chrono::steady_clock::now();
        out.image = renderCpu(*scene.scene, scene.cpu, options, nullptr, sampleVariance);
        out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return out;
    }
    if (!gpu_ || !scene.gpu) throw std::invalid_argument("study: a GPU render was asked for, but no GPU renderer is open");
    if (sampleVariance) throw std::invalid_argument("study: the GPU renderer has no per-pixel variance output");
    // The kernel variant depends on the sampler, the estimator (in a scene with Diffuse surfaces)
    // and, through the samples per dispatch, on the rpp: the first render of each is preceded by an
    // untimed one of the same options on one row, which creates (and compiles) its pipeline at
    // 1/height of the render's cost.
    if (warmed_.insert({scene.id, static_cast<std::uint32_t>(options.sampler), static_cast<std::uint32_t>(options.estimator),
                        options.samplesPerPixel})
            .second) {
        RenderOptions warmUp = options;
        warmUp.rows = glm::ivec2(0, 1);
        warmUp.quiet = true;
        warmUp.checkpoints = 0;
        warmUp.onCheckpoint = nullptr;
        gpu_->render(*scene.gpu, warmUp);
    }
    const auto start = std::chrono::steady_clock::now();
    out.image = gpu_->render(*scene.gpu, options);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

}  // namespace vkrt::study
