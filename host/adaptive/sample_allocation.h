// Where an adaptive render's next round puts its samples. An image's squared error is the mean of
// v_p / N_p over its pixels (v_p: pixel p's per-sample variance, N_p its samples); for a given
// total of samples it is smallest with N_p proportional to sqrt(v_p) (a Lagrange multiplier), and
// the factor that meets a target mean T is sum(sqrt(v)) / (P T). Rounds move each pixel toward
// that count: never fewer samples than it has (they are spent), at most twice as many per round
// (its estimate is refreshed before it grows again), even counts (the halves pair up).
#pragma once

#include <cstdint>
#include <vector>

#include "pixel_accumulation.h"

namespace vkrt::adaptive {

// Per pixel, sqrt of the per-sample variance averaged over the three channels (the MSE's weight).
std::vector<double> noiseScales(const PixelAccumulation& acc, const std::vector<glm::dvec3>& variance);

// Each rendered pixel's count for the next round: scale * sigma_p rounded up to even, kept within
// [its count, min(2 count, maxRpp)] (without perRoundCap: [its count, maxRpp], the final counts
// that scale means). A pixel without noise (sigma 0) stays where it is.
std::vector<std::uint32_t> plannedCounts(const PixelAccumulation& acc, const std::vector<double>& sigma, double scale,
                                         std::uint32_t maxRpp, bool perRoundCap = true);

// The samples a plan adds to what the pixels have.
std::uint64_t addedSamples(const PixelAccumulation& acc, const std::vector<std::uint32_t>& planned);

// sum(sigma) / (P targetMse) over the rendered pixels: the scale whose counts meet targetMse.
double scaleForTarget(const PixelAccumulation& acc, const std::vector<double>& sigma, double targetMse);

// The largest scale (to 0.1%) whose plan (plannedCounts with perRoundCap) adds at most `budget`
// samples; 0 when none does, infinity when every plan fits.
double scaleForBudget(const PixelAccumulation& acc, const std::vector<double>& sigma, std::uint32_t maxRpp, double budget,
                      bool perRoundCap = true);

}  // namespace vkrt::adaptive
