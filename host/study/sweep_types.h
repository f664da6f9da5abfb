// What a sweep measures: one row per render, and the rows summarised per setting.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "error_metrics.h"
#include "render_options.h"
#include "study_renderer.h"

namespace vkrt::study {

// The regions errors are reported for (region_masks.h); All = every pixel.
enum class Region { All = 0, Edge = 1, Penumbra = 2, Gloss = 3, Defocus = 4, Motion = 5, Indirect = 6, Emitter = 7 };
inline constexpr std::size_t kRegionCount = 8;
inline constexpr std::array<Region, kRegionCount> kRegions = {Region::All,     Region::Edge,   Region::Penumbra,
                                                              Region::Gloss,   Region::Defocus, Region::Motion,
                                                              Region::Indirect, Region::Emitter};
// "all", "edge", "penumbra", "gloss", "defocus", "motion", "indirect", "emitter"
std::string regionName(Region region);

// One render of the sweep.
struct SweepRow {
    Device device = Device::Cpu;
    SamplerKind sampler = SamplerKind::Jittered;
    Estimator estimator = Estimator::MisPower;
    int rpp = 1;
    std::uint32_t seed = 0;
    double seconds = 0.0;
    ErrorMetrics error;
};

double rmseIn(const ErrorMetrics& e, Region region);

// One setting (device, sampler, estimator, rpp) over its seeds: mean time, and the RMSE of the
// pooled squared errors (sqrt of the mean MSE over seeds), per region.
struct SweepPoint {
    Device device = Device::Cpu;
    SamplerKind sampler = SamplerKind::Jittered;
    Estimator estimator = Estimator::MisPower;
    int rpp = 1;
    int seeds = 0;
    double seconds = 0.0;
    double relMse = 0.0;
    std::array<double, kRegionCount> rmse{};  // indexed by Region
};

// A curve of the sweep: the settings that differ only in rpp.
struct Series {
    Device device = Device::Cpu;
    SamplerKind sampler = SamplerKind::Jittered;
    Estimator estimator = Estimator::MisPower;
    bool operator==(const Series&) const = default;
};
Series seriesOf(const SweepRow& row);
Series seriesOf(const SweepPoint& point);
// The series of `points` in the order of their first appearance.
std::vector<Series> seriesIn(const std::vector<SweepPoint>& points);

// Points in the order of first appearance of their series, rpp ascending.
std::vector<SweepPoint> summarize(const std::vector<SweepRow>& rows);

}  // namespace vkrt::study
