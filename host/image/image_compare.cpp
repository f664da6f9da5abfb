#include "image_compare.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "heat_map.h"

namespace vkrt {

void requireSameSize(const Image& a, const Image& b, const char* what) {
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument(std::string(what) + ": images differ in size (" + std::to_string(a.width) + "x" +
                                    std::to_string(a.height) + " vs " + std::to_string(b.width) + "x" +
                                    std::to_string(b.height) + ")");
}

ImageDifference compareImages(const Image& a, const Image& b) {
    requireSameSize(a, b, "compareImages");
    ImageDifference d;
    d.width = a.width;
    d.height = a.height;
    d.heatMap = Image(a.width, a.height);
    const std::size_t n = a.pixels.size();
    if (n == 0) return d;

    double sumAbs = 0.0, sumSq = 0.0;
    std::size_t over1 = 0, over2 = 0;
    int maxSteps = 0;
    for (std::size_t i = 0; i < n; ++i) {
        int pixelMax = 0;
        for (int c = 0; c < 3; ++c) {
            const int diff = std::abs(int(quantize8(a.pixels[i][c])) - int(quantize8(b.pixels[i][c])));
            pixelMax = std::max(pixelMax, diff);
            sumAbs += diff;
            sumSq += double(diff) * diff;
        }
        maxSteps = std::max(maxSteps, pixelMax);
        over1 += pixelMax > 1;
        over2 += pixelMax > 2;
        d.heatMap.pixels[i] = differenceColour(pixelMax);
    }
    d.maxAbs = maxSteps / 255.0;
    d.meanAbs = sumAbs / (3.0 * n) / 255.0;
    d.fractionOver1 = double(over1) / n;
    d.fractionOver2 = double(over2) / n;
    const double mse = sumSq / (3.0 * n);
    d.psnr = mse == 0.0 ? std::numeric_limits<double>::infinity() : 10.0 * std::log10(255.0 * 255.0 / mse);
    return d;
}

bool meetsAgreementRule(const ImageDifference& d) { return d.fractionOver2 <= 0.005 && d.meanAbs <= 0.5 / 255.0; }

}  // namespace vkrt
