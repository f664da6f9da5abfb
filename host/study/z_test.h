// A statistical image comparison for renders that use different random numbers (other seeds,
// samplers or devices): a per-pixel, per-channel z-test of the difference against its variance,
// as Mitsuba 3's render tests do (docs/SAMPLING.md §5).
//
//   z = (a - b) / sqrt(var(a - b) + floor),  p = erfc(|z| / sqrt 2)
//   a value passes when p exceeds the Sidak-corrected level 1 - (1 - alpha)^(1/n), n = values;
//   the images agree when at least passFraction of the values pass.
#pragma once

#include <cstddef>
#include <vector>

#include "image.h"

namespace vkrt::study {

struct ZTestOptions {
    double alpha = 0.01;           // family-wise rate of false failures over the whole image
    double passFraction = 0.9975;  // Mitsuba 3: a handful of failing values is tolerated
    // Added to every value's variance. Pixels whose samples all agree (flat lit areas, background)
    // have zero sample variance, yet two devices legitimately differ there by float rounding
    // (~1e-6); (1e-4)^2 makes differences below ~5e-4 (an eighth of an 8-bit step) pass there.
    double varianceFloor = 1e-8;
};

struct ZTestResult {
    std::size_t values = 0;        // pixels x 3 channels
    std::size_t passed = 0;
    double levelPerValue = 0.0;    // the Sidak-corrected significance level
    double zLimit = 0.0;           // |z| at that level
    double maxAbsZ = 0.0;
    bool pass = false;
    Image map;                     // per pixel: grey = max |z| / zLimit (1 = at the limit), red = a failing value

    double passedFraction() const { return values == 0 ? 1.0 : static_cast<double>(passed) / static_cast<double>(values); }
};

// The Sidak-corrected per-value significance level for n values at family-wise rate alpha, and
// the |z| whose two-sided p-value equals it.
double sidakLevel(double alpha, std::size_t values);
double zForLevel(double level);

// var(a - b) per pixel and channel is `differenceVariance`. Throws std::invalid_argument when the
// sizes differ or an option is out of range.
ZTestResult zTest(const Image& a, const Image& b, const Image& differenceVariance, const ZTestOptions& options = {});

// The variance of a pixel mean of `samples` independent samples whose variance is sampleVariance.
Image varianceOfMean(const Image& sampleVariance, int samples);

// a + b per pixel and channel (variances of independent estimates add).
Image sumImages(const Image& a, const Image& b);

// The mean of renders with different seeds, and the variance of that mean estimated from their
// spread (unbiased sample variance / count): honest for any sampler, stratified or not.
struct SeedStatistics {
    Image mean;
    Image varianceOfMean;
    int count = 0;
};
SeedStatistics statisticsOverSeeds(const std::vector<Image>& renders);

}  // namespace vkrt::study
