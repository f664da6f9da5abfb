// Image texture lookup: bilinear filtering with wrap-around addressing (docs/RENDERING.md §7).
#pragma once

#include <glm/glm.hpp>

#include "scene.h"

namespace vkrt::cpu {

// The texture's linear colour at (u, v): v = 0 is the bottom row of the image, v = 1 the top;
// texel centres sit at ((i + 1/2)/width, 1 - (j + 1/2)/height); coordinates wrap (repeat).
glm::vec3 sampleTexture(const Texture& texture, glm::vec2 uv);

}  // namespace vkrt::cpu
