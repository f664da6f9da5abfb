// Environment map files -> Scene::environment (docs/RENDERING.md §10): six cube faces
// `<prefix>{posX,negX,posY,negY,posZ,negZ}.png`, or one vertical-cross image, turned into the six
// faces of shaders/shared/cube_map.h's OpenGL orientation. Both loaders call these and report a
// problem as a SceneError at the element that named the file.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "scene.h"

namespace vkrt {

// How the -Z cube face file is read (docs/RENDERING.md §10.2). The course's 2018 faces are
// seamless under the OpenGL convention; its 2021 `reef_negZ.png` is that face mirrored left-right.
// Measure reads it whichever way its four edges join its neighbours with the smaller seam error.
enum class NegZRule { Measure, OpenGL, Mirrored };

// What is wrong with an environment map file: the problem, and the value the message quotes
// (the file's resolved path).
struct EnvironmentProblem {
    std::string problem;
    std::string value;
};

// The warning at envMapVertCross when envMapPrefix is given too (value: the cross's path as written).
inline constexpr const char* kIgnoredVertCross = "ignored, the environment map is envMapPrefix's cube faces";

using CubeFaces = std::array<std::vector<std::uint32_t>, 6>;

// The six faces `<prefix>posX.png` ... `<prefix>negZ.png` (any format loadTextureImage reads):
// each must exist, be square and have the others' size. nullopt with `problem` set otherwise.
// `where` is left for the caller.
std::optional<Environment> loadCubeFaceEnvironment(const std::string& prefix, NegZRule negZ, EnvironmentProblem& problem);

// A vertical cross: a 3k x 4k image of k x k cells, each face's cell and orientation from
// kVerticalCross (measured, docs/RENDERING.md §10.3).
std::optional<Environment> loadVerticalCrossEnvironment(const std::string& path, EnvironmentProblem& problem);

// Where a face sits in a vertical cross and how its cell maps onto it: the face's texel (x, y)
// is the cell's texel (x', y') with (u, v) = transpose ? (y, x) : (x, y), x' = flipX ? k-1-u : u,
// y' = flipY ? k-1-v : v (the eight ways a square can lie).
struct CrossCell {
    int column = 0;
    int row = 0;
    bool transpose = false;
    bool flipX = false;
    bool flipY = false;
};
extern const std::array<CrossCell, 6> kVerticalCross;  // +X, -X, +Y, -Y, +Z, -Z

// The face a cross cell gives (k x k texels, from `image`, 3k wide).
std::vector<std::uint32_t> crossFace(const Texture& image, const CrossCell& cell, int k);

// Seam error of one edge of `face` (0 left, 1 right, 2 top, 3 bottom of its image): the mean,
// over the face's N texels along that edge, of the mean absolute difference per channel (0-255)
// between the texel and the neighbouring face's texel across the edge (cube_map.h,
// cubeBorderSource). Reads only `face` and the face across that edge.
double edgeSeamError(const CubeFaces& faces, int faceSize, int face, int edge);

// The -Z face's four edges together (their mean), read as in `faces` and mirrored left-right.
// `faces` is the same on return (its -Z face is mirrored in place for the second figure, and back).
struct NegZSeams {
    double asOpenGL = 0.0;
    double mirrored = 0.0;
};
NegZSeams measureNegZSeams(CubeFaces& faces, int faceSize);

}  // namespace vkrt
