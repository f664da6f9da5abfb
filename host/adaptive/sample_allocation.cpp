#include "sample_allocation.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vkrt::adaptive {

std::vector<double> noiseScales(const PixelAccumulation& acc, const std::vector<glm::dvec3>& variance) {
    std::vector<double> sigma(acc.pixels(), 0.0);
    for (std::size_t p = 0; p < acc.pixels(); ++p) sigma[p] = std::sqrt((variance[p].x + variance[p].y + variance[p].z) / 3.0);
    return sigma;
}

std::vector<std::uint32_t> plannedCounts(const PixelAccumulation& acc, const std::vector<double>& sigma, double scale,
                                         std::uint32_t maxRpp, bool perRoundCap) {
    std::vector<std::uint32_t> next = acc.count;
    for (int y = acc.rows.x; y < acc.rows.y; ++y)
        for (int x = 0; x < acc.width; ++x) {
            const std::size_t p = acc.index(x, y);
            const std::uint32_t have = acc.count[p];
            const std::uint32_t cap = perRoundCap ? std::min<std::uint32_t>(maxRpp, 2u * have) : maxRpp;
            if (sigma[p] <= 0.0 || cap <= have) continue;
            const double want = scale * sigma[p];  // inf when scale is; never NaN as sigma > 0
            if (!(want > have)) continue;
            const double even = 2.0 * std::ceil(want / 2.0);
            next[p] = even >= cap ? cap : static_cast<std::uint32_t>(even);
        }
    return next;
}

std::uint64_t addedSamples(const PixelAccumulation& acc, const std::vector<std::uint32_t>& planned) {
    std::uint64_t added = 0;
    for (std::size_t p = 0; p < acc.pixels(); ++p) added += planned[p] - acc.count[p];
    return added;
}

double scaleForTarget(const PixelAccumulation& acc, const std::vector<double>& sigma, double targetMse) {
    double sum = 0.0;
    std::size_t pixels = 0;
    for (int y = acc.rows.x; y < acc.rows.y; ++y)
        for (int x = 0; x < acc.width; ++x, ++pixels) sum += sigma[acc.index(x, y)];
    if (!(targetMse > 0.0)) return std::numeric_limits<double>::infinity();
    return sum / (static_cast<double>(pixels) * targetMse);
}

double scaleForBudget(const PixelAccumulation& acc, const std::vector<double>& sigma, std::uint32_t maxRpp, double budget,
                      bool perRoundCap) {
    const auto adds = [&](double scale) {
        return static_cast<double>(addedSamples(acc, plannedCounts(acc, sigma, scale, maxRpp, perRoundCap)));
    };
    double lo = 0.0, hi = 1.0;
    // Grow hi until its plan exceeds the budget or is the largest there is (every pixel capped).
    const double most = adds(std::numeric_limits<double>::infinity());
    if (most <= budget) return std::numeric_limits<double>::infinity();
    while (adds(hi) <= budget) {
        lo = hi;
        hi *= 4.0;
    }
    while (hi - lo > 1e-3 * hi) {
        const double mid = 0.5 * (lo + hi);
        (adds(mid) <= budget ? lo : hi) = mid;
    }
    return lo;
}

}  // namespace vkrt::adaptive
