// The kernels' per-pixel sums (the accumulation buffer's first texels) -> images: the final mean
// and a progressive render's image so far. Shared by the megakernel and the wavefront renderer.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "image.h"
#include "tile_planner.h"

namespace vkrt {

// Pixel = sum of its samples (accumulated in sample order on the device) / rpp, the same float
// operations as the CPU reference: no reciprocal multiply, which could differ in the last bit.
Image resolve(const std::vector<glm::vec4>& sums, int width, int height, int samples);

// A progressive render's image so far: tiles before `current` have all their samples, `current`
// has `currentSamples`, later tiles none yet (black). Tiles are in rows-relative coordinates.
Image resolveSoFar(const std::vector<glm::vec4>& sums, int width, int height, const std::vector<TileRect>& tiles,
                   std::size_t current, int currentSamples, int samples, int firstRow);

}  // namespace vkrt
