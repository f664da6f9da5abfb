// The error of an adaptive render's image, estimated from the two halves of every pixel's samples
// (docs/SAMPLING.md §7). With sobol2 (or random) the even- and the odd-numbered samples of a pixel
// are two independent estimates of it, each from N/2 samples; half their difference d has
// E[d^2] = Var(mean of all N), whatever stratification each half has. So the sum of d^2 over the
// image is an unbiased estimate of its squared error, and N d^2 of the per-sample variance.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "pixel_accumulation.h"

namespace vkrt::adaptive {

// Rec. 709 luminance, the relative error's denominator.
double luminance(const glm::dvec3& c);

struct ImageErrorEstimate {
    double rmse = 0.0;           // root mean square over the rows' pixels and the 3 channels
    double meanLuminance = 0.0;  // of the image so far
    // rmse / meanLuminance: the relative RMSE --target-error asks for (0 for an exact black image).
    double relative() const;
};

// Over the rows' pixels; every one of them needs an even count >= 2.
ImageErrorEstimate estimateImageError(const PixelAccumulation& acc);

// Half the difference of the pixel's two halves, per channel (its 1-sample error estimate).
glm::dvec3 halfDifference(const PixelAccumulation& acc, std::size_t p);

// Per pixel and channel, the per-sample variance N d^2 averaged over the (2 radius + 1)^2
// neighbourhood inside the rows: one pixel's d^2 has one degree of freedom (a lucky pixel would
// look converged). The allocation takes radius 2 (25 pixels: steering needs locality, a penumbra
// is a few pixels wide); the error map radius 3, whose 49 pixels keep a path-traced pixel's z-score
// spread near 1 (1.02-1.19 against 1.12-1.31 at radius 2, docs/SAMPLING.md §7): 1 / se^2 grows
// with the spread of se.
inline constexpr int kAllocationRadius = 2;
inline constexpr int kErrorMapRadius = 3;
std::vector<glm::dvec3> smoothedSampleVariance(const PixelAccumulation& acc, int radius);

// The estimated standard error of each pixel's mean: sqrt(smoothed variance / N) per channel.
std::vector<glm::vec3> standardErrors(const PixelAccumulation& acc, const std::vector<glm::dvec3>& variance);
// --error-map: standardErrors of the variance smoothed at kErrorMapRadius.
std::vector<glm::vec3> errorMap(const PixelAccumulation& acc);

}  // namespace vkrt::adaptive
