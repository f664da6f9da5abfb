// DIR/report.md: what was swept, the fitted convergence slopes per device, sampler, estimator and
// region, the estimators' errors at equal time, and the cheapest setting that reaches a target error.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "convergence_fit.h"
#include "sweep_types.h"

namespace vkrt::study {

// Settings whose MSE in a region is below this multiple of the reference's own MSE there measure
// the reference more than the render, and are left out of the slope fit.
inline constexpr double kReferenceFloorFactor = 4.0;

struct ConvergenceSlope {
    Series series;
    Region region = Region::All;
    LogLogFit fit;
};

// Slopes of log RMSE against log rpp per (series, region), over the points whose MSE exceeds
// kReferenceFloorFactor x referenceMse[region].
std::vector<ConvergenceSlope> fitSlopes(const std::vector<SweepPoint>& points, const std::array<double, kRegionCount>& referenceMse);

// Equal time: the estimators of one device and sampler compared at the same render time. The time
// is the longest that every one of their series reached (the least of their longest mean times),
// so no series is extrapolated; NaN when some series' shortest time is above it.
double commonTime(const std::vector<SweepPoint>& points, Device device, SamplerKind sampler, bool adaptive = false);
// A series' RMSE in `region` at `seconds`: linear in log time and log RMSE between the two points
// (ordered by time) around it; NaN outside the series' times or where the region is empty.
double rmseAtTime(const std::vector<SweepPoint>& points, const Series& series, Region region, double seconds);

// The cheapest (least mean time) point whose RMSE in `region` is <= target; nullopt if none.
std::optional<SweepPoint> cheapestReaching(const std::vector<SweepPoint>& points, Region region, double target);

struct SweepReportInput {
    std::string scenePath;
    std::string settings;                  // one line: size, depth, light/gloss samples, seeds
    std::string referenceLine;             // how the reference was made and where it is cached
    std::array<double, kRegionCount> referenceMse{};  // the reference's own estimated MSE per region
    std::array<std::size_t, kRegionCount> regionPixels{};
    std::vector<SweepPoint> points;
    double targetRmse = 0.01;
    std::vector<std::string> files;        // output files, relative to DIR
};

void writeSweepReport(const SweepReportInput& input, const std::filesystem::path& path);

}  // namespace vkrt::study
