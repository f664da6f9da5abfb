#include "environment_test_maps.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "cube_map.h"
#include "image.h"
#include "test_paths.h"

namespace vkrt::test {

std::uint32_t packRgb(glm::u8vec3 c) {
    return std::uint32_t(c.r) | std::uint32_t(c.g) << 8 | std::uint32_t(c.b) << 16 | 0xff000000u;
}

Environment syntheticEnvironment(int faceSize, const FaceTexels& texel) {
    Environment environment;
    environment.faceSize = faceSize;
    for (int face = 0; face < 6; ++face)
        for (int y = 0; y < faceSize; ++y)
            for (int x = 0; x < faceSize; ++x) environment.faces[face].push_back(packRgb(texel(face, x, y)));
    return environment;
}

void writePng(const std::string& path, int width, int height, const std::function<glm::u8vec3(int, int)>& texel) {
    Image image(width, height);
    // quantize8 truncates c * 255: the centre of each byte's interval writes that byte.
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) image.at(x, y) = (glm::vec3(texel(x, y)) + 0.5f) / 255.0f;
    std::filesystem::create_directories(std::filesystem::path(path).parent_path());
    writeImage(image, path);
}

void writeCubeFaces(const std::string& prefix, int faceSize, const FaceTexels& texel) {
    const char* suffix[6] = {"posX", "negX", "posY", "negY", "posZ", "negZ"};
    for (int face = 0; face < 6; ++face)
        writePng(prefix + suffix[face] + ".png", faceSize, faceSize, [&](int x, int y) { return texel(face, x, y); });
}

std::string reef2018Prefix() { return upstreamDir() + "/data/reef_"; }
std::string reef2021Prefix() { return jsonSceneDir() + "/images/reef_"; }
std::string uffiziCross() { return jsonSceneDir() + "/images/uffizi_cross.png"; }

namespace {

// The point `texels` texels from the middle-of-edge parameter `u` of `edge`, inwards (> 0) or
// outwards (< 0: past the edge, on the face's extended plane, which cubeFacePoint puts on the
// face across), as a direction.
glm::vec3 nearEdge(int face, int edge, double u, double texels, int faceSize) {
    const double d = texels / faceSize;
    glm::dvec2 st = edge == 0 ? glm::dvec2(d, u) : edge == 1 ? glm::dvec2(1.0 - d, u) : edge == 2 ? glm::dvec2(u, d) : glm::dvec2(u, 1.0 - d);
    return cubemap::cubeFaceDirection(static_cast<std::uint32_t>(face), glm::vec2(st));
}

double meanAbs(glm::vec3 a, glm::vec3 b) {
    const glm::vec3 d = glm::abs(a - b) * 255.0f;
    return (d.x + d.y + d.z) / 3.0;
}

}  // namespace

std::vector<CubeEdge> cubeEdges() {
    std::vector<CubeEdge> edges;
    for (int face = 0; face < 6; ++face) {
        for (int edge = 0; edge < 4; ++edge) {
            const glm::vec3 past = nearEdge(face, edge, 0.5, -0.5, 2);
            const int across = static_cast<int>(cubemap::cubeFacePoint(past).face);
            if (across > face) edges.push_back({face, edge, across});
        }
    }
    return edges;
}

std::string edgeName(const CubeEdge& edge) {
    const char* names[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
    return std::string(names[edge.face]) + "/" + names[edge.across];
}

EdgeSteps edgeSteps(const EnvironmentTexels& map, const CubeEdge& edge, int points, double epsilon) {
    const int n = static_cast<int>(map.faceSize);
    EdgeSteps steps;
    for (int i = 0; i < points; ++i) {
        const double u = (i + 0.5) / points;
        auto at = [&](double texels) { return environmentRadiance(map, nearEdge(edge.face, edge.edge, u, texels, n)); };
        const glm::vec3 inHalf = at(0.5), inOneAndHalf = at(1.5), outHalf = at(-0.5), outOneAndHalf = at(-1.5);
        steps.across += meanAbs(inHalf, outHalf);
        steps.interior += 0.5 * (meanAbs(inHalf, inOneAndHalf) + meanAbs(outHalf, outOneAndHalf));
        steps.atEdge = std::max(steps.atEdge, meanAbs(at(epsilon), at(-epsilon)));
    }
    steps.across /= points;
    steps.interior /= points;
    return steps;
}

}  // namespace vkrt::test
