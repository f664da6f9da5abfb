#include "float_range.h"

#include <cfloat>
#include <cmath>

namespace vkrt {

std::size_t clampOverflowedPixels(Image& image) {
    std::size_t pixels = 0;
    for (glm::vec3& p : image.pixels) {
        bool overflowed = false;
        for (int c = 0; c < 3; ++c)
            if (std::isinf(p[c])) {
                p[c] = p[c] > 0.0f ? FLT_MAX : -FLT_MAX;
                overflowed = true;
            }
        pixels += overflowed;
    }
    return pixels;
}

}  // namespace vkrt
