#include "study_renderer.h"

#include <chrono>
#include <stdexcept>

#include "cpu_renderer.h"
#include "gpu_build_options.h"

namespace vkrt::study {

std::string deviceName(Device device) { return device == Device::Gpu ? "gpu" : "cpu"; }

StudyRenderer::StudyRenderer(const std::optional<GpuRendererOptions>& gpu) {
    if (gpu) gpu_ = std::make_unique<GpuRenderer>(*gpu);
}

std::string StudyRenderer::gpuDeviceName() const { return gpu_ ? gpu_->deviceName() : std::string("none"); }

std::shared_ptr<const ValidationLog> StudyRenderer::validationLog() const { return gpu_ ? gpu_->validationLog() : nullptr; }

TimedRender StudyRenderer::render(Device device, const Scene& scene, const SceneAccel& accel, const RenderOptions& options,
                                  Image* sampleVariance) {
    TimedRender out;
    if (device == Device::Cpu) {
        const auto start = std::chrono::steady_clock::now();
        out.image = renderCpu(scene, accel, options, nullptr, sampleVariance);
        out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return out;
    }
    if (!gpu_) throw std::invalid_argument("study: a GPU render was asked for, but no GPU renderer is open");
    if (sampleVariance) throw std::invalid_argument("study: the GPU renderer has no per-pixel variance output");
    // Built for every render, untimed: a cache keyed on the scene's address would hand a later
    // scene at the same address (a loop's local) the previous scene's tree.
    const SceneAccel gpuAccel = buildSceneAccel(scene, gpuBuildOptions());
    if (warmedScene_ != &scene) {
        RenderOptions warmUp = options;
        warmUp.samplesPerPixel = 1;
        warmUp.quiet = true;
        gpu_->render(scene, gpuAccel, warmUp);
        warmedScene_ = &scene;
    }
    const auto start = std::chrono::steady_clock::now();
    out.image = gpu_->render(scene, gpuAccel, options);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

}  // namespace vkrt::study
