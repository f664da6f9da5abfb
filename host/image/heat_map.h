// The difference heat maps of `vkrt compare` and `vkrt check`: one colour per 8-bit step of
// difference, and a legend strip under the map that says what the colours mean in /255.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "image.h"

namespace vkrt {

// The colour scale saturates at this many 8-bit steps: beyond 16/255 a difference is plain to the eye.
inline constexpr int kHeatMapFullScale = 16;

// 0 steps black, 1-2 dark red, growing through red to yellow at kHeatMapFullScale steps and beyond.
glm::vec3 differenceColour(int steps);

// A swatch the legend explains besides the scale (e.g. check's "within noise" grey).
using LegendSwatch = std::pair<glm::vec3, std::string>;

// `map` with a legend under it: the colour bar of differenceColour from 0 to kHeatMapFullScale+
// with its ticks labelled in /255, then each swatch with its label. The result is at least as wide
// as the legend needs (a narrow map is padded with black on the right).
Image withDifferenceLegend(const Image& map, const std::vector<LegendSwatch>& swatches = {});

}  // namespace vkrt
