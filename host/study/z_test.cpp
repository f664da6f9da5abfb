#include "z_test.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "image_compare.h"

namespace vkrt::study {

// By bisection: erfc is monotone.
double zForLevel(double level) {
    double lo = 0.0, hi = 40.0;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (std::erfc(mid / std::sqrt(2.0)) > level ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

// n independent tests at this level have a family-wise false-failure rate of alpha;
// -expm1(log1p(-alpha) / n) is 1 - (1 - alpha)^(1/n) without cancellation.
double sidakLevel(double alpha, std::size_t values) {
    return values == 0 ? alpha : -std::expm1(std::log1p(-alpha) / static_cast<double>(values));
}

ZTestResult zTest(const Image& a, const Image& b, const Image& differenceVariance, const ZTestOptions& options) {
    requireSameSize(a, b, "zTest");
    requireSameSize(a, differenceVariance, "zTest (variance)");
    if (!(options.alpha > 0.0 && options.alpha < 1.0))
        throw std::invalid_argument("zTest: alpha must be in (0, 1), not " + std::to_string(options.alpha));
    if (!(options.passFraction >= 0.0 && options.passFraction <= 1.0))
        throw std::invalid_argument("zTest: pass fraction must be in [0, 1], not " + std::to_string(options.passFraction));
    if (!(options.varianceFloor >= 0.0))
        throw std::invalid_argument("zTest: variance floor must not be negative");

    ZTestResult r;
    r.values = a.pixels.size() * 3;
    r.levelPerValue = sidakLevel(options.alpha, r.values);
    r.zLimit = zForLevel(r.levelPerValue);
    r.map = Image(a.width, a.height);
    for (std::size_t k = 0; k < a.pixels.size(); ++k) {
        double worst = 0.0;
        bool failed = false;
        for (int c = 0; c < 3; ++c) {
            const double diff = static_cast<double>(a.pixels[k][c]) - b.pixels[k][c];
            const double variance = std::max(0.0, static_cast<double>(differenceVariance.pixels[k][c])) + options.varianceFloor;
            double z = variance > 0.0 ? std::abs(diff) / std::sqrt(variance) : (diff == 0.0 ? 0.0 : INFINITY);
            if (std::isnan(z)) z = INFINITY;  // a NaN pixel never agrees
            const double p = std::erfc(z / std::sqrt(2.0));
            if (p > r.levelPerValue) {
                ++r.passed;
            } else {
                failed = true;
            }
            worst = std::max(worst, z);
        }
        r.maxAbsZ = std::max(r.maxAbsZ, worst);
        const float grey = static_cast<float>(std::min(1.0, worst / r.zLimit));
        r.map.pixels[k] = failed ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(grey);
    }
    r.pass = r.passedFraction() >= options.passFraction;
    return r;
}

Image varianceOfMean(const Image& sampleVariance, int samples) {
    if (samples < 1) throw std::invalid_argument("varianceOfMean: sample count must be at least 1, not " + std::to_string(samples));
    Image out = sampleVariance;
    for (glm::vec3& v : out.pixels) v /= static_cast<float>(samples);
    return out;
}

Image sumImages(const Image& a, const Image& b) {
    requireSameSize(a, b, "sumImages");
    Image out = a;
    for (std::size_t k = 0; k < out.pixels.size(); ++k) out.pixels[k] += b.pixels[k];
    return out;
}

SeedStatistics statisticsOverSeeds(const std::vector<Image>& renders) {
    if (renders.size() < 2) throw std::invalid_argument("statisticsOverSeeds: needs at least two renders for a spread");
    for (const Image& r : renders) requireSameSize(r, renders.front(), "statisticsOverSeeds");
    const double n = static_cast<double>(renders.size());
    SeedStatistics s;
    s.count = static_cast<int>(renders.size());
    s.mean = Image(renders.front().width, renders.front().height);
    s.varianceOfMean = Image(renders.front().width, renders.front().height);
    for (std::size_t k = 0; k < s.mean.pixels.size(); ++k)
        for (int c = 0; c < 3; ++c) {
            double sum = 0.0;
            for (const Image& r : renders) sum += r.pixels[k][c];
            const double mean = sum / n;
            double squares = 0.0;
            for (const Image& r : renders) squares += (r.pixels[k][c] - mean) * (r.pixels[k][c] - mean);
            s.mean.pixels[k][c] = static_cast<float>(mean);
            s.varianceOfMean.pixels[k][c] = static_cast<float>(squares / (n - 1.0) / n);
        }
    return s;
}

}  // namespace vkrt::study
