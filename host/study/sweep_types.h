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

// One render of the sweep. An adaptive render (--targets, docs/SAMPLING.md §7) has its target
// and, as rpp, its mean samples per pixel rounded.
struct SweepRow {
    Device device = Device::Cpu;
    SamplerKind sampler = SamplerKind::Jittered;
    Estimator estimator = Estimator::MisPower;
    double adaptiveTarget = 0.0;  // 0: a uniform render of rpp samples per pixel
    int rpp = 1;
    std::uint32_t seed = 0;
    double seconds = 0.0;
    ErrorMetrics error;
};

double rmseIn(const ErrorMetrics& e, Region region);

// One setting (device, sampler, estimator, rpp or adaptive target) over its seeds: mean time (and
// for an adaptive target the mean rpp, rounded), and the RMSE of the pooled squared errors (sqrt of
// the mean MSE over seeds), per region.
struct SweepPoint {
    Device device = Device::Cpu;
    SamplerKind sampler = SamplerKind::Jittered;
    Estimator estimator = Estimator::MisPower;
    double adaptiveTarget = 0.0;
    int rpp = 1;
    int seeds = 0;
    double seconds = 0.0;
    double relMse = 0.0;
    std::array<double, kRegionCount> rmse{};  // indexed by Region
};

// A curve of the sweep: the settings that differ only in rpp, or the adaptive renders of every
// target of a device, sampler and estimator.
struct Series {
    Device device = Device::Cpu;
    SamplerKind sampler = SamplerKind::Jittered;
    Estimator estimator = Estimator::MisPower;
    bool adaptive = false;
    bool operator==(const Series&) const = default;
};
// The series' sampler as tables and plots name it: "sobol2", or "sobol2 adaptive".
std::string samplerLabel(const Series& series);
Series seriesOf(const SweepRow& row);
Series seriesOf(const SweepPoint& point);
// The series of `points` in the order of their first appearance.
std::vector<Series> seriesIn(const std::vector<SweepPoint>& points);

// Points in the order of first appearance of their series, rpp ascending.
std::vector<SweepPoint> summarize(const std::vector<SweepRow>& rows);

}  // namespace vkrt::study
