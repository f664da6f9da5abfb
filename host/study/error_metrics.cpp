#include "error_metrics.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "image_compare.h"

namespace vkrt::study {

namespace {

void requireMaskSize(const Image& a, const PixelMask* mask, const char* what) {
    if (mask && mask->size() != a.pixels.size())
        throw std::invalid_argument(std::string(what) + ": mask has " + std::to_string(mask->size()) +
                                    " pixels, the image " + std::to_string(a.pixels.size()));
}

}  // namespace

double meanSquaredError(const Image& image, const Image& reference, const PixelMask* mask) {
    requireSameSize(image, reference, "meanSquaredError");
    requireMaskSize(image, mask, "meanSquaredError");
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t k = 0; k < image.pixels.size(); ++k) {
        if (mask && !(*mask)[k]) continue;
        for (int c = 0; c < 3; ++c) {
            const double d = static_cast<double>(image.pixels[k][c]) - reference.pixels[k][c];
            sum += d * d;
        }
        count += 3;
    }
    return count == 0 ? std::numeric_limits<double>::quiet_NaN() : sum / static_cast<double>(count);
}

double meanOverRegion(const Image& values, const PixelMask* mask) {
    requireMaskSize(values, mask, "meanOverRegion");
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t k = 0; k < values.pixels.size(); ++k) {
        if (mask && !(*mask)[k]) continue;
        sum += static_cast<double>(values.pixels[k].r) + values.pixels[k].g + values.pixels[k].b;
        count += 3;
    }
    return count == 0 ? std::numeric_limits<double>::quiet_NaN() : sum / static_cast<double>(count);
}

ErrorMetrics measureError(const Image& image, const Image& reference, const RegionMasks& masks) {
    requireSameSize(image, reference, "measureError");
    ErrorMetrics e;
    e.rmse = std::sqrt(meanSquaredError(image, reference));
    e.rmseEdge = std::sqrt(meanSquaredError(image, reference, &masks.edge));
    e.rmsePenumbra = std::sqrt(meanSquaredError(image, reference, &masks.penumbra));
    e.rmseGloss = std::sqrt(meanSquaredError(image, reference, &masks.gloss));
    e.rmseDefocus = std::sqrt(meanSquaredError(image, reference, &masks.defocus));
    e.rmseMotion = std::sqrt(meanSquaredError(image, reference, &masks.motion));
    e.rmseIndirect = std::sqrt(meanSquaredError(image, reference, &masks.indirect));
    e.rmseEmitter = std::sqrt(meanSquaredError(image, reference, &masks.emitter));
    double rel = 0.0;
    for (std::size_t k = 0; k < image.pixels.size(); ++k)
        for (int c = 0; c < 3; ++c) {
            const double r = reference.pixels[k][c];
            const double d = static_cast<double>(image.pixels[k][c]) - r;
            rel += d * d / (r * r + kRelMseEpsilon);
        }
    e.relMse = image.pixels.empty() ? 0.0 : rel / (3.0 * static_cast<double>(image.pixels.size()));
    return e;
}

}  // namespace vkrt::study
