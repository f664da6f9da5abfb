// Labels drawn into images (heat-map legends) without a font library: a 3x5-pixel font of the
// digits, upper-case letters and a few signs, scaled up by whole pixels. Lower-case text is drawn
// in upper case; a character the font lacks is drawn as a blank.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "image.h"

namespace vkrt {

inline constexpr int kGlyphWidth = 3, kGlyphHeight = 5;

// The width in pixels `text` takes at `scale` (one blank column between characters).
int textWidth(const std::string& text, int scale);

// Draws `text` with its top-left corner at (x, y); pixels outside the image are skipped.
void drawText(Image& image, int x, int y, const std::string& text, int scale, glm::vec3 colour);

}  // namespace vkrt
