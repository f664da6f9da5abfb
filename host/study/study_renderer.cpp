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

TimedRender StudyRenderer::renderAdaptive(Device device, const PreparedScene& scene, const RenderOptions& options,
                                          const adaptive::AdaptiveOptions& adaptive) {
    RenderOptions o = options;
    o.samplesPerPixel = static_cast<int>(adaptive.maxRpp);
    const auto run = [&](const RenderOptions& render) {
        if (device == Device::Cpu) {
            CpuSampleRanges cpu(*scene.scene, scene.cpu, render);
            return adaptive::renderAdaptive(render.width, render.height, rowsOf(render), adaptive,
                                            [&](const std::vector<std::uint32_t>& next, adaptive::PixelAccumulation& acc) {
                                                cpu.add(next, acc);
                                            });
        }
        if (!gpu_ || !scene.gpu) throw std::invalid_argument("study: a GPU render was asked for, but no GPU renderer is open");
        return adaptive::renderAdaptive(render.width, render.height, rowsOf(render), adaptive,
                                        [&](const std::vector<std::uint32_t>& next, adaptive::PixelAccumulation& acc) {
                                            gpu_->addSampleRanges(*scene.gpu, render, next, acc);
                                        });
    };
    if (device == Device::Gpu &&
        warmed_.insert({scene.id, static_cast<std::uint32_t>(o.sampler) | 0x80000000u, static_cast<std::uint32_t>(o.estimator),
                        o.samplesPerPixel})
            .second) {
        RenderOptions warmUp = o;
        warmUp.rows = glm::ivec2(0, 1);
        warmUp.quiet = true;
        run(warmUp);
    }
    const auto start = std::chrono::steady_clock::now();
    const adaptive::AdaptiveResult result = run(o);
    TimedRender out;
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out.image = Image(o.width, o.height);
    for (std::size_t p = 0; p < result.acc.pixels(); ++p) out.image.pixels[p] = result.acc.mean(p);
    const glm::ivec2 rows = rowsOf(o);
    out.meanRpp = static_cast<double>(result.last.samples) / (static_cast<double>(o.width) * (rows.y - rows.x));
    return out;
}

}  // namespace vkrt::study
