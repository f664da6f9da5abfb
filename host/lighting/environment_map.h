// Scene::environment -> the texels both renderers look the environment map up in, and the CPU's
// lookup (docs/RENDERING.md §10). The GPU reads the same texels (upload `texels` as they are, an
// R32UI texel buffer) through the same footprint (shaders/shared/cube_map.h, cubeFacePoint and
// cubeTexelFootprint), so the two devices filter alike.
//
// Layout: six bordered faces in cube_map.h's order (+X, -X, +Y, -Y, +Z, -Z) and OpenGL orientation,
// face f's texel (x, y) at f * (N + 2)^2 + y * (N + 2) + x, x and y in [0, N + 1], row 0 at the top.
// Texels 1..N are the face's own; the one-texel border holds the neighbouring faces' texels across
// each edge (cubeBorderSource), and each corner the mean of the three texels that meet at that
// corner of the cube. A bilinear lookup inside a bordered face is then continuous across every
// edge and corner of the cube, with no wrapping logic: at an edge both faces blend the same two
// texels with the same weights, and at a corner all three give the mean of the same three.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene.h"

namespace vkrt {

struct EnvironmentTexels {
    std::uint32_t faceSize = 0;          // N; 0: the scene has no environment map (texels empty)
    std::vector<std::uint32_t> texels;   // 6 (N + 2)^2 RGBA8 texels, r in the low byte
};

EnvironmentTexels borderedEnvironment(const Environment& environment);

// The radiance the environment map gives a ray leaving the scene in direction `dir` (any length
// but zero): bilinear between the four nearest texel centres of the face `dir` meets, texel
// bytes used linearly (byte / 255, as textures are; docs/RENDERING.md §7). Needs faceSize > 0.
glm::vec3 environmentRadiance(const EnvironmentTexels& environment, glm::vec3 dir);

// One texel as linear RGB (byte / 255).
glm::vec3 texelRadiance(std::uint32_t rgba8);

}  // namespace vkrt
