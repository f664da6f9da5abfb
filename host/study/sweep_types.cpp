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

Series seriesOf(const SweepRow& row) { return {row.device, row.sampler, row.estimator}; }
Series seriesOf(const SweepPoint& point) { return {point.device, point.sampler, point.estimator}; }

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

    std::vector<SweepPoint> points;
    for (const Series& s : series) {
        std::vector<int> rpps;
        for (const SweepRow& r : rows)
            if (seriesOf(r) == s && std::find(rpps.begin(), rpps.end(), r.rpp) == rpps.end()) rpps.push_back(r.rpp);
        std::sort(rpps.begin(), rpps.end());
        for (int rpp : rpps) {
            SweepPoint p;
            p.device = s.device;
            p.sampler = s.sampler;
            p.estimator = s.estimator;
            p.rpp = rpp;
            std::array<double, kRegionCount> mse{};
            for (const SweepRow& r : rows) {
                if (!(seriesOf(r) == s) || r.rpp != rpp) continue;
                ++p.seeds;
                p.seconds += r.seconds;
                p.relMse += r.error.relMse;
                for (Region g : kRegions) mse[static_cast<int>(g)] += rmseIn(r.error, g) * rmseIn(r.error, g);
            }
            p.seconds /= p.seeds;
            p.relMse /= p.seeds;
            for (std::size_t g = 0; g < kRegionCount; ++g) p.rmse[g] = std::sqrt(mse[g] / p.seeds);
            points.push_back(p);
        }
    }
    return points;
}

}  // namespace vkrt::study
