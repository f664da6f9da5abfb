#include "region_checks.h"

#include <cstdlib>
#include <sstream>

namespace vkrt::stability {

namespace {

int steps(const Image& image, int x, int y, int c) { return quantize8(image.at(x, y)[c]); }

bool smoothAt(const Image& image, int x, int y, int smoothSteps) {
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            for (int c = 0; c < 3; ++c)
                if (std::abs(steps(image, x + dx, y + dy, c) - steps(image, x, y, c)) > smoothSteps) return false;
    return true;
}

}  // namespace

SmoothRegionResult compareSmoothRegions(const Image& reference, const Image& image, int smoothSteps,
                                        int toleranceSteps) {
    SmoothRegionResult r;
    int worstSteps = -1;
    for (int y = 1; y + 1 < reference.height; ++y)
        for (int x = 1; x + 1 < reference.width; ++x) {
            if (!smoothAt(reference, x, y, smoothSteps)) continue;
            ++r.smoothPixels;
            int diff = 0;
            for (int c = 0; c < 3; ++c) diff = std::max(diff, std::abs(steps(image, x, y, c) - steps(reference, x, y, c)));
            if (diff <= toleranceSteps) continue;
            ++r.differing;
            if (diff > worstSteps) {
                worstSteps = diff;
                std::ostringstream s;
                s << "pixel (" << x << "," << y << ") differs by " << diff << "/255 in a smooth region";
                r.worst = s.str();
            }
        }
    return r;
}

}  // namespace vkrt::stability
