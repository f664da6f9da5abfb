// The scene the scale/translation invariance tests move around: spheres (glossy, glass), boxes
// (floor, block, wall, a zero-thickness tile), a loose triangle, a torus mesh instanced three
// times (one non-uniformly scaled), an area light and a point light, seen by a perspective camera.
// Sizes are O(1) at scale 1; the smallest gaps the image depends on are 0.05 (the block before the
// wall, the tile above the floor). No two faces coincide: which of two coincident faces a ray sees
// is a tie (degenerate_test.cpp tests that separately).
#pragma once

#include "scene.h"

namespace vkrt::stability {

Scene invarianceScene();

}  // namespace vkrt::stability
