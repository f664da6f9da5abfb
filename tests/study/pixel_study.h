// Error statistics of one pixel over many seeds, rendered by the CPU reference (1x1 images of
// study_scenes.h): the measurements the sampler tests assert on.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "render_options.h"
#include "scene_accel.h"
#include "study_scenes.h"

namespace vkrt::test {

class PixelStudy {
public:
    explicit PixelStudy(const PixelScene& scene);

    // The pixel's value for one (sampler, rpp, seed).
    glm::dvec3 render(SamplerKind sampler, int rpp, std::uint32_t seed) const;
    // RMSE against the exact value over seeds firstSeed .. firstSeed + seeds - 1 (squared errors
    // pooled over the three channels and the seeds).
    double rmse(SamplerKind sampler, int rpp, int seeds, std::uint32_t firstSeed = 1000) const;

    const glm::dvec3& expected() const { return scene_.expected; }

private:
    const PixelScene& scene_;
    SceneAccel accel_;
};

}  // namespace vkrt::test
