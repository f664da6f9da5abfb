// Adaptive sampling's --sample-map as a picture: each pixel's sample count on a logarithmic colour
// scale, with a legend under the map naming the counts.
#pragma once

#include <cstdint>
#include <vector>

#include "image.h"

namespace vkrt {

// counts: width * height, row-major; pixels with 0 samples (outside a render's rows) are black.
// The scale runs from the smallest non-zero count (dark blue) to the largest (white), log2.
Image sampleCountHeatMap(const std::vector<std::uint32_t>& counts, int width, int height);

}  // namespace vkrt
