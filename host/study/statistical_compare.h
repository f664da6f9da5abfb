// `vkrt compare --stat`: the GPU and the CPU reference render the same scene with different seeds,
// and a z-test (z_test.h) decides whether the two images agree up to their noise.
#pragma once

#include <cstdint>
#include <string>

#include "render_options.h"
#include "scene.h"
#include "study_renderer.h"
#include "z_test.h"

namespace vkrt::study {

// The CPU renders the reference with kReferenceRppFactor x the rpp (at least kMinReferenceRpp):
// the per-pixel sample variance must come from many samples, or a pixel whose few samples happen
// to agree (a highlight or a shadow hit by 1 sample in 50) gets a near-zero variance and fails.
inline constexpr int kReferenceRppFactor = 16;
inline constexpr int kMinReferenceRpp = 256;

struct StatisticalComparison {
    ZTestResult test;
    std::uint32_t gpuSeed = 0;   // options.seed + 1
    std::uint32_t cpuSeed = 0;   // options.seed
    int gpuRpp = 0, cpuRpp = 0;
    double gpuSeconds = 0.0, cpuSeconds = 0.0;
};

// Mitsuba 3's scheme with the CPU as the reference: the variance of the difference is
// s^2 / gpuRpp + s^2 / cpuRpp per pixel and channel, s^2 the CPU render's sample variance (both
// devices compute the same estimator, RENDERING.md, and the GPU has no variance output). For
// independent samples (the random sampler) that is exact; for stratified samplers s^2 / rpp
// over-estimates the variance of a mean, which only makes the test more lenient. The regular
// sampler is a fixed pattern, not an unbiased estimator: at two different rpp it converges to
// different values near edges, and the test may rightly reject it. `renderer` must have a GPU.
StatisticalComparison compareDevicesStatistically(StudyRenderer& renderer, const PreparedScene& scene,
                                                  const RenderOptions& options, const ZTestOptions& test = {});

}  // namespace vkrt::study
