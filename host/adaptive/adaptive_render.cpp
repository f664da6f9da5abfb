#include "adaptive_render.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "sample_allocation.h"

namespace vkrt::adaptive {

namespace {

std::string text(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

void checkBound(const char* name, std::uint32_t value) {
    if (value < 2 || value > (1u << 20) || value % 2 != 0)
        throw std::invalid_argument(std::string(name) + " " + std::to_string(value) +
                                    ": must be an even number from 2 to 1048576 (the error estimate pairs a pixel's even "
                                    "and odd samples)");
}

}  // namespace

void checkAdaptiveOptions(const AdaptiveOptions& o) {
    if (!o.targetError && !o.seconds) throw std::invalid_argument("adaptive sampling needs --target-error E or --time SECONDS");
    if (o.targetError && !(std::isfinite(*o.targetError) && *o.targetError >= kMinTargetError))
        throw std::invalid_argument("--target-error " + text(*o.targetError) + ": must be a relative RMSE of at least " +
                                    text(kMinTargetError) + " (float per-pixel sums cannot resolve less; docs/SAMPLING.md §7)");
    if (o.seconds && !(std::isfinite(*o.seconds) && *o.seconds > 0.0))
        throw std::invalid_argument("--time " + text(*o.seconds) + ": must be a number of seconds above 0");
    checkBound("--min-rpp", o.minRpp);
    checkBound("--max-rpp", o.maxRpp);
    if (o.maxRpp < o.minRpp)
        throw std::invalid_argument("--max-rpp " + std::to_string(o.maxRpp) + " is below --min-rpp " + std::to_string(o.minRpp));
}

std::string stopReasonText(StopReason reason) {
    switch (reason) {
    case StopReason::TargetMet: return "target met";
    case StopReason::TimeSpent: return "time budget spent";
    case StopReason::MaxRpp: return "--max-rpp reached";
    case StopReason::NoNoise: return "no pixel has noise left";
    case StopReason::NotFinite: return "the error estimate is not finite (radiance past float's range)";
    }
    return "unknown";
}

AdaptiveResult renderAdaptive(int width, int height, glm::ivec2 rows, const AdaptiveOptions& options, const AddSamples& add,
                              const RoundDone& onRound) {
    checkAdaptiveOptions(options);
    AdaptiveResult result;
    PixelAccumulation& acc = result.acc;
    acc = PixelAccumulation(width, height, rows);
    std::vector<std::uint32_t> next = acc.count;
    for (int y = rows.x; y < rows.y; ++y)
        for (int x = 0; x < width; ++x) next[acc.index(x, y)] = options.minRpp;
    // The time counts everything from here: the samples and each round's estimates and plan.
    const auto start = std::chrono::steady_clock::now();
    double seconds = 0.0;
    std::uint64_t samples = 0;
    for (int round = 1;; ++round) {
        samples += addedSamples(acc, next);
        add(next, acc);
        seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

        AdaptiveRound& r = result.last;
        r.number = round;
        r.estimate = estimateImageError(acc);
        r.samples = samples;
        r.seconds = seconds;
        r.minCount = std::numeric_limits<std::uint32_t>::max();
        r.maxCount = 0;
        for (int y = rows.x; y < rows.y; ++y)
            for (int x = 0; x < width; ++x) {
                r.minCount = std::min(r.minCount, acc.count[acc.index(x, y)]);
                r.maxCount = std::max(r.maxCount, acc.count[acc.index(x, y)]);
            }
        result.estimate = r.estimate;
        result.variance = smoothedSampleVariance(acc, kAllocationRadius);
        if (onRound) onRound(r, acc);

        const double targetMse =
            options.targetError ? std::pow(*options.targetError * r.estimate.meanLuminance, 2.0) : 0.0;
        if (!std::isfinite(r.estimate.rmse) || !std::isfinite(r.estimate.meanLuminance)) {
            result.stop = StopReason::NotFinite;  // sums past float's range: no estimate can be trusted
            break;
        }
        if (options.targetError && r.estimate.rmse * r.estimate.rmse <= targetMse) {
            result.stop = StopReason::TargetMet;
            break;
        }
        if (options.seconds && seconds >= *options.seconds) {
            result.stop = StopReason::TimeSpent;
            break;
        }
        if (r.minCount >= options.maxRpp) {
            result.stop = StopReason::MaxRpp;
            break;
        }
        const std::vector<double> sigma = noiseScales(acc, result.variance);
        const double targetScale =
            options.targetError ? scaleForTarget(acc, sigma, targetMse) : std::numeric_limits<double>::infinity();
        // With a time budget: the remaining time at the samples per second so far, spent on the
        // final allocation (counts proportional to sigma, not capped per round) whose scale this is;
        // the round then moves each pixel toward it, at most doubling it. So the samples follow
        // the noise from the first round on, and no round plans more than the time left.
        double budget = std::numeric_limits<double>::infinity(), timeScale = std::numeric_limits<double>::infinity();
        if (options.seconds) {
            budget = static_cast<double>(samples) / seconds * (*options.seconds - seconds);
            if (budget < 2.0) {  // not even one pixel's pair
                result.stop = StopReason::TimeSpent;
                break;
            }
            timeScale = scaleForBudget(acc, sigma, options.maxRpp, budget, /*perRoundCap=*/false);
        }
        double scale = std::min(targetScale, timeScale);
        next = plannedCounts(acc, sigma, scale, options.maxRpp);
        // A target not met by a plan that adds nothing (the smoothed variances promise the target,
        // the pixels' own halves do not yet): raise the scale until the plan adds samples, but
        // not past what the time allows.
        for (int tries = 0; options.targetError && addedSamples(acc, next) == 0 && scale < timeScale && tries < 64; ++tries) {
            scale = std::min(scale * 2.0, timeScale);
            next = plannedCounts(acc, sigma, scale, options.maxRpp);
        }
        if (addedSamples(acc, next) == 0) {
            const bool capped = r.maxCount >= options.maxRpp;
            result.stop = std::isfinite(timeScale) && timeScale <= targetScale ? StopReason::TimeSpent
                          : capped                                            ? StopReason::MaxRpp
                                                                              : StopReason::NoNoise;
            break;
        }
    }
    return result;
}

}  // namespace vkrt::adaptive
