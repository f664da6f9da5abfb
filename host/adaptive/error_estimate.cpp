#include "error_estimate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace vkrt::adaptive {

double luminance(const glm::dvec3& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }

double ImageErrorEstimate::relative() const {
    if (meanLuminance > 0.0) return rmse / meanLuminance;
    return rmse > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
}

glm::dvec3 halfDifference(const PixelAccumulation& acc, std::size_t p) {
    const double half = 0.5 * acc.count[p];
    // The float sums are exact to ~sqrt(N) 2^-24 of their size: far below any target allowed
    // (adaptive_render.h kMinTargetError).
    const glm::dvec3 odd(acc.oddSum[p]), even = glm::dvec3(acc.sum[p]) - odd;
    return 0.5 * (even - odd) / half;
}

ImageErrorEstimate estimateImageError(const PixelAccumulation& acc) {
    double squares = 0.0, lum = 0.0;
    std::size_t pixels = 0;
    for (int y = acc.rows.x; y < acc.rows.y; ++y)
        for (int x = 0; x < acc.width; ++x) {
            const std::size_t p = acc.index(x, y);
            if (acc.count[p] < 2 || acc.count[p] % 2 != 0)
                throw std::logic_error("pixel " + std::to_string(x) + "," + std::to_string(y) + " has " +
                                       std::to_string(acc.count[p]) + " samples; the estimate needs an even count >= 2");
            const glm::dvec3 d = halfDifference(acc, p);
            squares += glm::dot(d, d);
            lum += luminance(glm::dvec3(acc.sum[p]) / static_cast<double>(acc.count[p]));
            ++pixels;
        }
    ImageErrorEstimate e;
    if (pixels == 0) return e;
    e.rmse = std::sqrt(squares / (3.0 * pixels));
    e.meanLuminance = lum / pixels;
    return e;
}

std::vector<glm::dvec3> smoothedSampleVariance(const PixelAccumulation& acc, int radius) {
    std::vector<glm::dvec3> own(acc.pixels(), glm::dvec3(0.0)), rowSums(acc.pixels(), glm::dvec3(0.0)),
        out(acc.pixels(), glm::dvec3(0.0));
    for (int y = acc.rows.x; y < acc.rows.y; ++y)
        for (int x = 0; x < acc.width; ++x) {
            const std::size_t p = acc.index(x, y);
            const glm::dvec3 d = halfDifference(acc, p);
            own[p] = static_cast<double>(acc.count[p]) * d * d;
        }
    // Separable box: along rows, then along columns, each clipped to the image and the rows (the
    // window shrinks at the border rather than counting pixels it does not have).
    for (int y = acc.rows.x; y < acc.rows.y; ++y)
        for (int x = 0; x < acc.width; ++x) {
            glm::dvec3 s(0.0);
            const int x0 = std::max(0, x - radius), x1 = std::min(acc.width - 1, x + radius);
            for (int i = x0; i <= x1; ++i) s += own[acc.index(i, y)];
            rowSums[acc.index(x, y)] = s / static_cast<double>(x1 - x0 + 1);
        }
    for (int y = acc.rows.x; y < acc.rows.y; ++y)
        for (int x = 0; x < acc.width; ++x) {
            glm::dvec3 s(0.0);
            const int y0 = std::max(acc.rows.x, y - radius), y1 = std::min(acc.rows.y - 1, y + radius);
            for (int j = y0; j <= y1; ++j) s += rowSums[acc.index(x, j)];
            out[acc.index(x, y)] = s / static_cast<double>(y1 - y0 + 1);
        }
    return out;
}

std::vector<glm::vec3> standardErrors(const PixelAccumulation& acc, const std::vector<glm::dvec3>& variance) {
    std::vector<glm::vec3> out(acc.pixels(), glm::vec3(0.0f));
    for (std::size_t p = 0; p < acc.pixels(); ++p)
        if (acc.count[p] > 0) out[p] = glm::vec3(glm::sqrt(variance[p] / static_cast<double>(acc.count[p])));
    return out;
}

std::vector<glm::vec3> errorMap(const PixelAccumulation& acc) {
    return standardErrors(acc, smoothedSampleVariance(acc, kErrorMapRadius));
}

}  // namespace vkrt::adaptive
