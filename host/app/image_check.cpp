#include "image_check.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

#include "heat_map.h"
#include "image_compare.h"
#include "z_test.h"

namespace vkrt {

namespace {

double zLimitFor(const Image& image, const PixelTestOptions& options) {
    return study::zForLevel(study::sidakLevel(options.alpha, image.pixels.size() * 3));
}

bool pixelPasses(const Image& yours, const CheckReference& reference, std::size_t k, double zLimit,
                 const PixelTestOptions& options) {
    // Your image counts as at least one sample per pixel; the reference's mean as rpp samples.
    const double varianceScale = 1.0 + 1.0 / static_cast<double>(reference.rpp);
    for (int c = 0; c < 3; ++c) {
        double expected = reference.mean.pixels[k][c];
        if (options.clampReference) expected = std::clamp(expected, 0.0, 1.0);
        const double excess = std::abs(static_cast<double>(yours.pixels[k][c]) - expected) - options.slack;
        if (std::isnan(excess)) return false;  // a NaN in either image never agrees
        if (excess <= 0.0) continue;
        const double variance = std::max(0.0, static_cast<double>(reference.sampleVariance.pixels[k][c])) * varianceScale;
        if (!(excess <= zLimit * std::sqrt(variance))) return false;
    }
    return true;
}

// Visits every pixel that fails, with its index.
template <class Visit>
void forEachFailingPixel(const Image& yours, const CheckReference& reference, const PixelTestOptions& options, Visit visit) {
    requireSameSize(yours, reference.mean, "check");
    const double zLimit = zLimitFor(yours, options);
    for (std::size_t k = 0; k < yours.pixels.size(); ++k)
        if (!pixelPasses(yours, reference, k, zLimit, options)) visit(k);
}

// A geometric transform applies to the mean and the variance alike.
template <Image (*Transform)(const Image&)>
CheckReference geometric(const CheckReference& r) {
    return {Transform(r.mean), Transform(r.sampleVariance), r.rpp};
}

Image rotated180(const Image& image) { return mirrored(flippedVertically(image)); }
// Clockwise: the bottom-left corner comes to the top left. Square images only (imageMistakes).
Image rotatedClockwise(const Image& image) { return mirrored(transposed(image)); }
Image rotatedCounterClockwise(const Image& image) { return flippedVertically(transposed(image)); }

// A tone curve f applies to the mean; the variance scales by f'(mean)^2 (first order). The mean
// is clamped first: that is what an 8-bit writer sees.
template <float (*Curve)(float)>
CheckReference toneMapped(const CheckReference& r) {
    CheckReference out = r;
    for (std::size_t k = 0; k < r.mean.pixels.size(); ++k)
        for (int c = 0; c < 3; ++c) {
            const float m = std::clamp(r.mean.pixels[k][c], 0.0f, 1.0f);
            // A one-sided difference over 1/255 keeps the slope finite where a power curve's is not (at 0).
            const float h = 1.0f / 255.0f;
            const float lo = std::max(0.0f, m - h), hi = std::min(1.0f, lo + h);
            const float slope = (Curve(hi) - Curve(lo)) / (hi - lo);
            out.mean.pixels[k][c] = Curve(m);
            out.sampleVariance.pixels[k][c] = r.sampleVariance.pixels[k][c] * slope * slope;
        }
    return out;
}

float gamma22Encode(float linear) { return std::pow(linear, 1.0f / 2.2f); }

// Rays through a pixel corner instead of its centre: each pixel shows the point where four pixels
// meet, so its expected value is about their mean; one sample there may be any of them, so its
// variance is the largest of theirs plus the spread of their means.
template <int Dx, int Dy>
CheckReference halfPixelOffset(const CheckReference& r) {
    CheckReference out = r;
    const int w = r.mean.width, h = r.mean.height;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int x2 = std::clamp(x + Dx, 0, w - 1), y2 = std::clamp(y + Dy, 0, h - 1);
            const glm::vec3 means[4] = {r.mean.at(x, y), r.mean.at(x2, y), r.mean.at(x, y2), r.mean.at(x2, y2)};
            const glm::vec3 variances[4] = {r.sampleVariance.at(x, y), r.sampleVariance.at(x2, y),
                                            r.sampleVariance.at(x, y2), r.sampleVariance.at(x2, y2)};
            const glm::vec3 mean = 0.25f * (means[0] + means[1] + means[2] + means[3]);
            glm::vec3 spread(0.0f), largest(0.0f);
            for (int i = 0; i < 4; ++i) {
                spread += (means[i] - mean) * (means[i] - mean) * 0.25f;
                largest = glm::max(largest, variances[i]);
            }
            out.mean.at(x, y) = mean;
            // Scaled up by the reference's rpp: testPixels divides the mean's share by it.
            out.sampleVariance.at(x, y) = largest + spread * static_cast<float>(r.rpp);
        }
    return out;
}

}  // namespace

PixelTestResult testPixels(const Image& yours, const CheckReference& reference, const PixelTestOptions& options) {
    requireSameSize(yours, reference.mean, "check");
    requireSameSize(yours, reference.sampleVariance, "check (variance)");
    if (reference.rpp < 1) throw std::invalid_argument("check: the reference needs at least 1 rpp");
    PixelTestResult r;
    r.pixels = yours.pixels.size();
    r.zLimit = zLimitFor(yours, options);
    double signedSum = 0.0;
    for (std::size_t k = 0; k < yours.pixels.size(); ++k) {
        if (pixelPasses(yours, reference, k, r.zLimit, options)) ++r.passed;
        for (int c = 0; c < 3; ++c) {
            double expected = reference.mean.pixels[k][c];
            if (options.clampReference) expected = std::clamp(expected, 0.0, 1.0);
            const double d = static_cast<double>(yours.pixels[k][c]) - expected;
            if (std::isfinite(d)) signedSum += d;
        }
    }
    r.meanSignedDifference = r.pixels == 0 ? 0.0 : signedSum / static_cast<double>(3 * r.pixels);
    r.same = r.passedFraction() >= options.requiredFraction;
    return r;
}

Image flippedVertically(const Image& image) {
    Image out(image.width, image.height);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) out.at(x, y) = image.at(x, image.height - 1 - y);
    return out;
}

Image mirrored(const Image& image) {
    Image out(image.width, image.height);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) out.at(x, y) = image.at(image.width - 1 - x, y);
    return out;
}

Image transposed(const Image& image) {
    Image out(image.height, image.width);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) out.at(x, y) = image.at(y, x);
    return out;
}

float srgbEncode(float linear) {
    return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

float srgbDecode(float encoded) {
    return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

const std::vector<Mistake>& imageMistakes() {
    static const std::vector<Mistake> mistakes = {
        {"flipped vertically", "your rows are upside down: row 0 of an image file is its top, so the ray of row y goes "
                               "through v = top - (y + 0.5) * pixel height",
         geometric<flippedVertically>},
        {"mirrored left to right", "your columns are reversed: check the sign of u in your camera basis (u points to "
                                   "the image's right)",
         geometric<mirrored>},
        {"rotated 180 degrees", "both axes are reversed: check the signs of u and v in your camera basis",
         geometric<rotated180>},
        {"rows and columns swapped", "you index pixels as (row, column) where the file wants (column, row)",
         geometric<transposed>, true},
        {"rotated 90 degrees clockwise", "your camera's up vector is turned: for a camera looking straight down, vkrt "
                                         "and the course take up = (1,0,0) (docs/RENDERING.md §1; vkrt --up overrides it)",
         geometric<rotatedClockwise>, true},
        {"rotated 90 degrees counter-clockwise", "your camera's up vector is turned: for a camera looking straight down, "
                                                 "vkrt and the course take up = (1,0,0) (docs/RENDERING.md §1; vkrt --up "
                                                 "overrides it)",
         geometric<rotatedCounterClockwise>, true},
        {"sRGB gamma applied", "your values went through the sRGB curve (brighter mid-tones); the course writes the "
                               "clamped linear value, int(255 * c)",
         toneMapped<srgbEncode>},
        {"gamma 2.2 applied", "your values went through pow(c, 1/2.2) (brighter mid-tones); the course writes the "
                              "clamped linear value, int(255 * c)",
         toneMapped<gamma22Encode>},
        {"sRGB decoding applied", "your values went through the inverse sRGB curve (darker mid-tones), as when an "
                                  "image library treats linear values as sRGB",
         toneMapped<srgbDecode>},
        {"half-pixel offset (up-left)", "your rays go through a pixel corner, not its centre: use (x + 0.5, y + 0.5)",
         halfPixelOffset<-1, -1>},
        {"half-pixel offset (up-right)", "your rays go through a pixel corner, not its centre: use (x + 0.5, y + 0.5)",
         halfPixelOffset<1, -1>},
        {"half-pixel offset (down-left)", "your rays go through a pixel corner, not its centre: use (x + 0.5, y + 0.5)",
         halfPixelOffset<-1, 1>},
        {"half-pixel offset (down-right)", "your rays go through a pixel corner, not its centre: use (x + 0.5, y + 0.5)",
         halfPixelOffset<1, 1>},
    };
    return mistakes;
}

Image checkMap(const Image& yours, const CheckReference& reference, const PixelTestOptions& options) {
    requireSameSize(yours, reference.mean, "check");
    Image map(yours.width, yours.height);
    const double zLimit = zLimitFor(yours, options);
    for (std::size_t k = 0; k < yours.pixels.size(); ++k) {
        glm::vec3 expected = reference.mean.pixels[k];
        if (options.clampReference) expected = glm::clamp(expected, 0.0f, 1.0f);
        const glm::vec3 d = glm::abs(yours.pixels[k] - expected);
        const float largest = std::max({d.x, d.y, d.z});
        if (!pixelPasses(yours, reference, k, zLimit, options))
            map.pixels[k] = differenceColour(std::isnan(largest) ? kHeatMapFullScale : static_cast<int>(std::lround(largest * 255.0f)));
        else if (largest > static_cast<float>(options.slack))
            map.pixels[k] = glm::vec3(kWithinNoiseGrey);
    }
    return map;
}

ColourCount commonFailingColour(const Image& yours, const CheckReference& reference, const PixelTestOptions& options) {
    std::unordered_map<std::uint32_t, std::size_t> counts;
    auto byte = [](float v) { return static_cast<std::uint32_t>(std::clamp(std::lround(v * 255.0f), 0L, 255L)); };
    forEachFailingPixel(yours, reference, options, [&](std::size_t k) {
        const glm::vec3& p = yours.pixels[k];
        ++counts[byte(p.x) << 16 | byte(p.y) << 8 | byte(p.z)];
    });
    ColourCount best;
    std::uint32_t bestKey = 0;
    for (const auto& [key, count] : counts)
        if (count > best.count || (count == best.count && key < bestKey)) {  // ties: the smaller key, deterministically
            best.count = count;
            bestKey = key;
        }
    best.colour = glm::vec3(static_cast<float>(bestKey >> 16 & 255u), static_cast<float>(bestKey >> 8 & 255u),
                            static_cast<float>(bestKey & 255u)) / 255.0f;
    return best;
}

double fractionFailingWhereReferenceBlack(const Image& yours, const CheckReference& reference, const PixelTestOptions& options) {
    std::size_t failing = 0, black = 0;
    forEachFailingPixel(yours, reference, options, [&](std::size_t k) {
        ++failing;
        const glm::vec3 expected = glm::clamp(reference.mean.pixels[k], 0.0f, 1.0f);
        const glm::vec3& p = yours.pixels[k];
        if (glm::all(glm::lessThan(expected, glm::vec3(1.0f / 255.0f))) &&
            std::max({p.x, p.y, p.z}) > static_cast<float>(options.slack))
            ++black;
    });
    return failing == 0 ? 0.0 : static_cast<double>(black) / static_cast<double>(failing);
}

}  // namespace vkrt
