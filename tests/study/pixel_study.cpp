#include "pixel_study.h"

#include <cmath>

#include "cpu_renderer.h"

namespace vkrt::test {

PixelStudy::PixelStudy(const PixelScene& scene) : scene_(scene), accel_(prepareCpuScene(scene.scene)) {}

glm::dvec3 PixelStudy::render(SamplerKind sampler, int rpp, std::uint32_t seed) const {
    RenderOptions o;
    o.width = 1;
    o.height = 1;
    o.samplesPerPixel = rpp;
    o.sampler = sampler;
    o.seed = seed;
    o.threads = 1;
    o.quiet = true;
    return glm::dvec3(renderCpu(scene_.scene, accel_, o).pixels[0]);
}

double PixelStudy::rmse(SamplerKind sampler, int rpp, int seeds, std::uint32_t firstSeed) const {
    double sum = 0.0;
    for (int s = 0; s < seeds; ++s) {
        const glm::dvec3 d = render(sampler, rpp, firstSeed + static_cast<std::uint32_t>(s)) - scene_.expected;
        sum += glm::dot(d, d) / 3.0;
    }
    return std::sqrt(sum / seeds);
}

}  // namespace vkrt::test
