// Rendering to an accuracy or a time (--target-error, --time; docs/SAMPLING.md §7): rounds of
// samples, each round's allocation from the error estimated so far, on any device that can add a
// range of samples to each pixel.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "error_estimate.h"
#include "pixel_accumulation.h"

namespace vkrt::adaptive {

// The smallest --target-error accepted: a pixel's float sum of N samples is exact to about
// sqrt(N) 2^-24 of its size (2e-5 at 65536 samples), so a relative error below 1e-4 would be
// measured in rounding.
inline constexpr double kMinTargetError = 1e-4;

struct AdaptiveOptions {
    std::optional<double> targetError;  // relative RMSE (error_estimate.h); none: spend the time
    std::optional<double> seconds;      // render-time budget; none: until the target or maxRpp
    std::uint32_t minRpp = 16;          // every pixel's first round (even)
    std::uint32_t maxRpp = 4096;        // no pixel goes beyond (even)
};

// Throws std::invalid_argument naming the option and value: neither a target nor a time, a target
// not finite or below kMinTargetError, a time not finite or not above 0, odd or out-of-order
// bounds, a bound beyond 2^20.
void checkAdaptiveOptions(const AdaptiveOptions& options);

enum class StopReason { TargetMet, TimeSpent, MaxRpp, NoNoise, NotFinite };
std::string stopReasonText(StopReason reason);  // "target met", "time budget spent", ...

struct AdaptiveRound {
    int number = 0;                    // 1-based
    ImageErrorEstimate estimate;       // after the round
    std::uint64_t samples = 0;         // all the pixels' samples so far
    std::uint32_t minCount = 0, maxCount = 0;
    double seconds = 0.0;              // rendering so far, the rounds' estimates and plans included
};

struct AdaptiveResult {
    PixelAccumulation acc;
    ImageErrorEstimate estimate;       // of the image returned
    std::vector<glm::dvec3> variance;  // per-sample variance smoothed at kAllocationRadius, at the end
    AdaptiveRound last;
    StopReason stop = StopReason::TargetMet;
};

// Adds samples [acc.count[p], next[p]) to every pixel p, in sample order (sum and oddSum), and sets
// acc.count = next. Throws to end the render (RenderCancelled).
using AddSamples = std::function<void(const std::vector<std::uint32_t>& next, PixelAccumulation& acc)>;
using RoundDone = std::function<void(const AdaptiveRound& round, const PixelAccumulation& acc)>;

// Rounds until the estimated relative error is at most options.targetError, the time budget is
// spent (a round is sized from the samples per second so far to end within it), or every pixel
// has maxRpp. Without a time budget the counts depend only on the samples: the same on every run.
AdaptiveResult renderAdaptive(int width, int height, glm::ivec2 rows, const AdaptiveOptions& options, const AddSamples& add,
                              const RoundDone& onRound = {});

}  // namespace vkrt::adaptive
