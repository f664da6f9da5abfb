#include "sweep_types.h"

#include <algorithm>
#include <cmath>

namespace vkrt::study {

std::string regionName(Region region) {
    switch (region) {
    case Region::All: return "all";
    case Region::Edge: return "edge";
    case Region::Penumbra: return "penumbra";
    case Region::Gloss: return "gloss";
    case Region::Defocus: return "defocus";
    case Region::Motion: return "motion";
    case Region::Indirect: return "indirect";
    case Region::Emitter: return "emitter";
    }
    return "unknown";
}

double rmseIn(const ErrorMetrics& e, Region region) {
    switch (region) {
    case Region::All: return e.rmse;
    case Region::Edge: return e.rmseEdge;
    case Region::Penumbra: return e.rmsePenumbra;
    case Region::Gloss: return e.rmseGloss;
    case Region::Defocus: return e.rmseDefocus;
    case Region::Motion: return e.rmseMotion;
    case Region::Indirect: return e.rmseIndirect;
    case Region::Emitter: return e.rmseEmitter;
    }
    return e.rmse;
}

Series seriesOf(const SweepRow& row) { return {row.device, row.sampler, row.estimator, row.adaptiveTarget > 0.0}; }
Series seriesOf(const SweepPoint& point) { return {point.device, point.sampler, point.estimator, point.adaptiveTarget > 0.0}; }

std::string samplerLabel(const Series& series) { return samplerName(series.sampler) + (series.adaptive ? " adaptive" : ""); }

std::vector<Series> seriesIn(const std::vector<SweepPoint>& points) {
    std::vector<Series> series;
    for (const SweepPoint& p : points)
        if (std::find(series.begin(), series.end(), seriesOf(p)) == series.end()) series.push_back(seriesOf(p));
    return series;
}

std::vector<SweepPoint> summarize(const std::vector<SweepRow>& rows) {
    std::vector<Series> series;
    for (const SweepRow& r : rows)
        if (std::find(series.begin(), series.end(), seriesOf(r)) == series.end()) series.push_back(seriesOf(r));

    // A uniform series' points are its rpps; an adaptive series' its targets (whose renders'
    // counts differ from seed to seed), ordered by their mean rpp.
    const auto keyOf = [](const SweepRow& r) { return r.adaptiveTarget > 0.0 ? r.adaptiveTarget : static_cast<double>(r.rpp); };
    std::vector<SweepPoint> points;
    for (const Series& s : series) {
        std::vector<double> keys;
        for (const SweepRow& r : rows)
            if (seriesOf(r) == s && std::find(keys.begin(), keys.end(), keyOf(r)) == keys.end()) keys.push_back(keyOf(r));
        std::vector<SweepPoint> own;
        for (double key : keys) {
            SweepPoint p;
            p.device = s.device;
            p.sampler = s.sampler;
            p.estimator = s.estimator;
            p.adaptiveTarget = s.adaptive ? key : 0.0;
            double rpp = 0.0;
            std::array<double, kRegionCount> mse{};
            for (const SweepRow& r : rows) {
                if (!(seriesOf(r) == s) || keyOf(r) != key) continue;
                ++p.seeds;
                rpp += r.rpp;
                p.seconds += r.seconds;
                p.relMse += r.error.relMse;
                for (Region g : kRegions) mse[static_cast<int>(g)] += rmseIn(r.error, g) * rmseIn(r.error, g);
            }
            p.rpp = static_cast<int>(std::lround(rpp / p.seeds));
            p.seconds /= p.seeds;
            p.relMse /= p.seeds;
            for (std::size_t g = 0; g < kRegionCount; ++g) p.rmse[g] = std::sqrt(mse[g] / p.seeds);
            own.push_back(p);
        }
        std::stable_sort(own.begin(), own.end(), [](const SweepPoint& a, const SweepPoint& b) { return a.rpp < b.rpp; });
        points.insert(points.end(), own.begin(), own.end());
    }
    return points;
}

}  // namespace vkrt::study
