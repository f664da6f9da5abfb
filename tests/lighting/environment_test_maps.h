// What the environment map tests share: synthetic maps (in memory and as files), the course's maps,
// and the seam statistics measured along the cube's edges.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "environment_loading.h"
#include "environment_map.h"
#include "scene.h"

namespace vkrt::test {

// RGB bytes of texel (x, y) of face `face` (0..5, +X..-Z).
using FaceTexels = std::function<glm::u8vec3(int face, int x, int y)>;

std::uint32_t packRgb(glm::u8vec3 c);
Environment syntheticEnvironment(int faceSize, const FaceTexels& texel);

// An 8-bit RGB PNG of w x h texels, texel (x, y) = texel(x, y); creates the folder.
void writePng(const std::string& path, int width, int height, const std::function<glm::u8vec3(int, int)>& texel);
// The six files <prefix>posX.png ... <prefix>negZ.png, faceSize x faceSize each.
void writeCubeFaces(const std::string& prefix, int faceSize, const FaceTexels& texel);

// The course's maps under ../shared (the test skips without them): the 2018 faces
// (upstream/data/reef_), the 2021 faces (json/images/reef_) and the Uffizi vertical cross.
std::string reef2018Prefix();
std::string reef2021Prefix();
std::string uffiziCross();

// One of the cube's 12 edges: `face`'s edge `edge` (0 left, 1 right, 2 top, 3 bottom of its image)
// and the face across it, listed once (face < across).
struct CubeEdge {
    int face;
    int edge;
    int across;
};
std::vector<CubeEdge> cubeEdges();
std::string edgeName(const CubeEdge& edge);  // e.g. "+X/-Z"

// The lookup's steps along one edge, in 0-255 units (mean over RGB, mean over `points` points
// evenly along the edge): `across` between the points half a texel either side of the edge
// (one texel apart), `interior` between the points half and one and a half texels inside each
// face (also one texel apart; the mean of both faces), `atEdge` the largest difference between
// the points `epsilon` texels either side.
struct EdgeSteps {
    double across = 0.0;
    double interior = 0.0;
    double atEdge = 0.0;
};
EdgeSteps edgeSteps(const EnvironmentTexels& map, const CubeEdge& edge, int points, double epsilon);

}  // namespace vkrt::test
