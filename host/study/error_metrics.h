// How far a render is from a reference: root-mean-square error over all pixels and inside each
// region mask, and relative MSE (docs/SAMPLING.md).
#pragma once

#include "image.h"
#include "region_masks.h"

namespace vkrt::study {

// Relative MSE's epsilon: (x - r)^2 / (r^2 + kRelMseEpsilon), the convention of pbrt and Mitsuba;
// it keeps near-black pixels from dominating.
inline constexpr double kRelMseEpsilon = 1e-2;

struct ErrorMetrics {
    double rmse = 0.0;          // over every pixel and channel
    double relMse = 0.0;
    double rmseEdge = 0.0;      // NaN when the region is empty
    double rmsePenumbra = 0.0;
    double rmseGloss = 0.0;
    double rmseDefocus = 0.0;
    double rmseMotion = 0.0;
    double rmseIndirect = 0.0;
    double rmseEmitter = 0.0;
};

// Squared errors are of linear radiance (not clamped or quantised). Throws std::invalid_argument
// when the sizes differ.
ErrorMetrics measureError(const Image& image, const Image& reference, const RegionMasks& masks);

// Mean squared error per channel over the pixels of `mask` (every pixel when mask is null): NaN
// when the mask is empty.
double meanSquaredError(const Image& image, const Image& reference, const PixelMask* mask = nullptr);

// The mean over the pixels of `mask` (every pixel when null) of a per-pixel, per-channel value
// image, e.g. a variance image: what that quantity adds to meanSquaredError over the same region.
double meanOverRegion(const Image& values, const PixelMask* mask = nullptr);

}  // namespace vkrt::study
