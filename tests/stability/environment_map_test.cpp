// A mirror sphere under an environment map shows, at every pixel, the texel value a direct lookup
// of the reflected direction gives (issue 20; docs/RENDERING.md §10): computed here in double from
// the raw faces with the OpenGL cube-map table of ../shared/scenes/JSON_FORMAT.md §5.3 and plain
// bilinear filtering, independently of the renderers' shared cube_map.h and of their bordered
// faces. Both devices. A map of unrelated random texels makes any wrong face, mirroring, rotation
// or half-texel shift change most pixels by many 8-bit steps.
#include <cmath>
#include <cstdint>
#include <cstdio>

#include <gtest/gtest.h>

#include "both_paths.h"
#include "scene_building.h"

namespace vkrt::stability {
namespace {

constexpr int kFace = 32;  // texels per face side

std::uint32_t texelOf(int face, int x, int y) {
    // A hash per texel: neighbours are unrelated, so the lookup's position shows in its value.
    std::uint32_t h = static_cast<std::uint32_t>(face * 7919 + y * 131 + x) * 2654435761u;
    h ^= h >> 15;
    h *= 2246822519u;
    h ^= h >> 13;
    return h & 0x00ffffffu;
}

Environment randomEnvironment() {
    Environment e;
    e.faceSize = kFace;
    for (int f = 0; f < 6; ++f) {
        e.faces[f].resize(kFace * kFace);
        for (int y = 0; y < kFace; ++y)
            for (int x = 0; x < kFace; ++x) e.faces[f][y * kFace + x] = texelOf(f, x, y) | 0xff000000u;
    }
    return e;
}

glm::dvec3 texelValue(const Environment& e, int face, int x, int y) {
    const std::uint32_t p = e.faces[face][y * kFace + x];
    return glm::dvec3(p & 0xff, (p >> 8) & 0xff, (p >> 16) & 0xff) / 255.0;
}

struct Lookup {
    glm::dvec3 value{0.0};
    double edgeDistance = 0.0;  // texels from the nearest texel centre row/column at the face's edge
};

// JSON_FORMAT.md §5.3, written out again: the face of the major axis, (sc, tc) per face,
// s = (sc/|ma| + 1)/2 and t = (tc/|ma| + 1)/2 with t = 0 at the top row; then bilinear between the
// four nearest texel centres (texel k's centre at (k + 1/2)/N).
Lookup directLookup(const Environment& e, glm::dvec3 d) {
    const glm::dvec3 a = glm::abs(d);
    int face;
    double sc, tc, ma;
    if (a.x >= a.y && a.x >= a.z) {
        ma = a.x;
        face = d.x >= 0 ? 0 : 1;
        sc = d.x >= 0 ? -d.z : d.z;
        tc = -d.y;
    } else if (a.y >= a.z) {
        ma = a.y;
        face = d.y >= 0 ? 2 : 3;
        sc = d.x;
        tc = d.y >= 0 ? d.z : -d.z;
    } else {
        ma = a.z;
        face = d.z >= 0 ? 4 : 5;
        sc = d.z >= 0 ? d.x : -d.x;
        tc = -d.y;
    }
    const double x = (sc / ma + 1.0) / 2.0 * kFace - 0.5;
    const double y = (tc / ma + 1.0) / 2.0 * kFace - 0.5;
    Lookup l;
    l.edgeDistance = std::min(std::min(x, kFace - 1 - x), std::min(y, kFace - 1 - y));
    if (l.edgeDistance < 0.0) return l;  // between the last texel centre and the edge: the border's job
    const int x0 = std::min(static_cast<int>(std::floor(x)), kFace - 2), y0 = std::min(static_cast<int>(std::floor(y)), kFace - 2);
    const double fx = x - x0, fy = y - y0;
    const glm::dvec3 top = glm::mix(texelValue(e, face, x0, y0), texelValue(e, face, x0 + 1, y0), fx);
    const glm::dvec3 bottom = glm::mix(texelValue(e, face, x0, y0 + 1), texelValue(e, face, x0 + 1, y0 + 1), fx);
    l.value = glm::mix(top, bottom, fy);
    return l;
}

TEST(EnvironmentMap, AMirrorSphereShowsTheTexelsADirectLookupOfTheReflectionGives) {
    constexpr int kSize = 96;
    constexpr double kPlane = 2.2;  // the orthographic image plane's width: the unit sphere and a margin
    Scene scene;
    scene.cameras.push_back(orthographic(glm::vec3(0.0f, 0.0f, 5.0f), glm::vec3(0.0f, 0.0f, -1.0f), static_cast<float>(kPlane)));
    Shape sphere;
    sphere.type = ShapeType::Sphere;
    sphere.center = glm::vec3(0.0f);
    sphere.radius = 1.0f;
    sphere.shader = add(scene, mirror());
    scene.shapes.push_back(sphere);
    scene.environment = randomEnvironment();

    RenderOptions options = smallOptions(kSize, kSize, 1);
    options.sampler = SamplerKind::Regular;  // one sample at each pixel's centre
    options.maxDepth = 1;
    const BothImages images = renderBoth(scene, options);

    int compared = 0, outsideSphere = 0;
    double worst[2] = {0.0, 0.0};
    for (int j = 0; j < kSize; ++j) {
        for (int i = 0; i < kSize; ++i) {
            // RENDERING.md §1, orthographic: gaze -z, so u = +x and v = +y.
            const double a = kPlane * ((i + 0.5) / kSize - 0.5), b = kPlane * (0.5 - (j + 0.5) / kSize);
            const double r2 = a * a + b * b;
            const std::size_t p = static_cast<std::size_t>(j) * kSize + i;
            Lookup l;
            if (r2 >= 1.0) {
                l = directLookup(scene.environment, glm::dvec3(0.0, 0.0, -1.0));  // the camera ray leaves
                ++outsideSphere;
            } else {
                const glm::dvec3 n(a, b, std::sqrt(1.0 - r2));
                // A grazing hit's reflection turns fast with the normal: float's normal then picks
                // a visibly different texel. Past cos 0.2 the direction's error stays ~1e-6.
                if (n.z < 0.2) continue;
                l = directLookup(scene.environment, glm::dvec3(0.0, 0.0, -1.0) + 2.0 * n.z * n);
            }
            // Within a texel of a face edge the lookup blends the neighbouring face's texels through
            // the border: the seam tests (tests/lighting) cover that; here only the faces' insides.
            if (l.edgeDistance < 0.05) continue;
            ++compared;
            const Image* byDevice[2] = {&images.cpu, &images.gpu};
            for (int d = 0; d < 2; ++d)
                for (int c = 0; c < 3; ++c)
                    worst[d] = std::max(worst[d], std::abs(static_cast<double>(byDevice[d]->pixels[p][c]) - l.value[c]));
        }
    }
    std::printf("[environment] mirror sphere %dx%d: %d pixels compared (%d see the map directly), worst |diff| cpu %.2e gpu %.2e\n",
                kSize, kSize, compared, outsideSphere, worst[0], worst[1]);
    EXPECT_GT(compared, kSize * kSize / 2);
    // Texel values are k/255; a direction off by 1e-5 rad moves the lookup by 32 * 1e-5 of a texel
    // between texels up to 1 apart: 3e-4. 1e-3 (a quarter of an 8-bit step) allows that; a face,
    // mirroring or half-texel error changes values by ~0.3 on average.
    EXPECT_LT(worst[0], 1e-3);
    EXPECT_LT(worst[1], 1e-3);
}

}  // namespace
}  // namespace vkrt::stability
