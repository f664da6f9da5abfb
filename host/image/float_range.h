// A pixel whose samples were each finite can still sum past float's range (a shape emitter of
// intensity 1e38 at 16 samples a pixel: the sum overflows to +inf, the mean is inf). Both
// renderers divide their sums on the host, and clamp such a mean to the largest float, the
// bound the true mean cannot exceed (every sample was at most that); the caller warns with the
// count. Non-finite samples never reach a sum: the renderers replace them by black (RENDERING.md §8).
#pragma once

#include <cstddef>

#include "image.h"

namespace vkrt {

// Sets every infinite channel to FLT_MAX and returns the number of pixels that had one.
std::size_t clampOverflowedPixels(Image& image);

}  // namespace vkrt
