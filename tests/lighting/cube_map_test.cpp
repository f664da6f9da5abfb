// shaders/shared/cube_map.h against the OpenGL cube-map table written out independently here
// (../shared/scenes/JSON_FORMAT.md §5.3), and host/lighting's lookup against synthetic maps whose
// every texel says where it is.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "cube_map.h"
#include "environment_map.h"
#include "environment_test_maps.h"

namespace vkrt::test {
namespace {

using cubemap::cubeFaceDirection;
using cubemap::cubeFacePoint;

// JSON_FORMAT.md §5.3, per face: the axes sc, tc and the major axis, as vectors.
struct GlFace {
    glm::vec3 sc, tc, ma;
};
const GlFace kGlTable[6] = {
    {{0, 0, -1}, {0, -1, 0}, {1, 0, 0}},   // +X: sc -z, tc -y
    {{0, 0, 1}, {0, -1, 0}, {-1, 0, 0}},   // -X: sc +z, tc -y
    {{1, 0, 0}, {0, 0, 1}, {0, 1, 0}},     // +Y: sc +x, tc +z
    {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}},   // -Y: sc +x, tc -z
    {{1, 0, 0}, {0, -1, 0}, {0, 0, 1}},    // +Z: sc +x, tc -y
    {{-1, 0, 0}, {0, -1, 0}, {0, 0, -1}},  // -Z: sc -x, tc -y
};
// The table's point at (s, t): u = (sc / |ma| + 1) / 2 and v = (tc / |ma| + 1) / 2 solved for the
// point on the cube.
glm::vec3 tablePoint(int face, glm::vec2 st) {
    const GlFace& f = kGlTable[face];
    return f.ma + (2.0f * st.x - 1.0f) * f.sc + (2.0f * st.y - 1.0f) * f.tc;
}

TEST(CubeMap, FaceCentresAndCornersFollowTheOpenGlTable) {
    const glm::vec2 points[] = {{0.5f, 0.5f}, {0, 0}, {1, 0}, {0, 1}, {1, 1}, {0.25f, 0.75f}};
    for (int face = 0; face < 6; ++face) {
        for (const glm::vec2 st : points) {
            SCOPED_TRACE(testing::Message() << "face " << face << " at " << st.x << "," << st.y);
            EXPECT_EQ(cubeFaceDirection(static_cast<std::uint32_t>(face), st), tablePoint(face, st));  // exact: +-1 and 0 only
            // Pulled a hundredth towards the centre, the table's point is on this face again (a corner
            // itself is shared by three faces, a tie), at that (s, t).
            const glm::vec2 inside = glm::mix(st, glm::vec2(0.5f), 0.01f);
            const cubemap::CubeFacePoint p = cubeFacePoint(tablePoint(face, inside));
            EXPECT_EQ(p.face, static_cast<std::uint32_t>(face));
            EXPECT_NEAR(p.st.x, inside.x, 1e-6f);
            EXPECT_NEAR(p.st.y, inside.y, 1e-6f);
        }
    }
}

TEST(CubeMap, EveryDirectionRoundTripsThroughItsFacePoint) {
    std::mt19937 rng(20);
    std::normal_distribution<float> gauss;
    for (int i = 0; i < 100000; ++i) {
        const glm::vec3 d = glm::normalize(glm::vec3(gauss(rng), gauss(rng), gauss(rng)));
        const cubemap::CubeFacePoint p = cubeFacePoint(d * 3.0f);  // any length
        ASSERT_GE(p.st.x, 0.0f);
        ASSERT_LE(p.st.x, 1.0f);
        ASSERT_GE(p.st.y, 0.0f);
        ASSERT_LE(p.st.y, 1.0f);
        const glm::vec3 back = glm::normalize(cubeFaceDirection(p.face, p.st));
        // A few float roundings of values <= 1 (a divide, a multiply-add each way): 1e-6 is ~8 ulp.
        ASSERT_LT(glm::length(back - d), 1e-6f) << d.x << " " << d.y << " " << d.z;
        // The face is the largest |component|'s, with the component's sign.
        const glm::vec3 a = glm::abs(d);
        const int axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
        ASSERT_EQ(p.face, static_cast<std::uint32_t>(2 * axis + (d[axis] < 0.0f ? 1 : 0)));
    }
}

TEST(CubeMap, TiesGoToXThenYAndZeroIsPositive) {
    EXPECT_EQ(cubeFacePoint(glm::vec3(1, 1, 0)).face, cubemap::CUBE_POS_X);
    EXPECT_EQ(cubeFacePoint(glm::vec3(-1, 1, 1)).face, cubemap::CUBE_NEG_X);
    EXPECT_EQ(cubeFacePoint(glm::vec3(0, -1, 1)).face, cubemap::CUBE_NEG_Y);
    EXPECT_EQ(cubeFacePoint(glm::vec3(0.5f, 1, -1)).face, cubemap::CUBE_POS_Y);
    EXPECT_EQ(cubeFacePoint(glm::vec3(-0.0f, 0, 0.5f)).face, cubemap::CUBE_POS_Z);
    EXPECT_EQ(cubeFacePoint(glm::vec3(-0.0f, 0, 0)).face, cubemap::CUBE_POS_X);
}

TEST(CubeMap, SolidAngleDensityIntegratesToASixthOfTheSphere) {
    const double faceSolidAngle = 4.0 * std::numbers::pi / 6.0;
    // Midpoint rule on 512^2 cells: error O(h^2) ~ 1e-6 relative for this smooth density.
    const int n = 512;
    double sum = 0.0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) sum += cubemap::cubeFaceSolidAngleDensity(glm::vec2((x + 0.5f) / n, (y + 0.5f) / n));
    EXPECT_NEAR(sum / (n * n), faceSolidAngle, 1e-5);
    // The closed form over the face and over a 4 x 4 grid of its cells (float: a few ulp of ~1).
    EXPECT_NEAR(cubemap::cubeFaceRectSolidAngle(glm::vec2(0), glm::vec2(1)), faceSolidAngle, 1e-6);
    double cells = 0.0;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) cells += cubemap::cubeFaceRectSolidAngle(glm::vec2(x, y) / 4.0f, glm::vec2(x + 1, y + 1) / 4.0f);
    EXPECT_NEAR(cells, faceSolidAngle, 4e-6);
    // A corner cell sees less of the sphere than a centre cell: 0.77 / 4 of the density ratio.
    EXPECT_LT(cubemap::cubeFaceRectSolidAngle(glm::vec2(0), glm::vec2(0.25f)),
              cubemap::cubeFaceRectSolidAngle(glm::vec2(0.25f), glm::vec2(0.5f)));
}

// Each face a flat colour of its own: a ray along each axis sees that axis's face, in the
// files' order.
TEST(EnvironmentLookup, ARayAlongEachAxisSeesThatFacesColour) {
    const glm::u8vec3 colours[6] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 0}, {0, 255, 255}, {255, 0, 255}};
    const EnvironmentTexels map =
        borderedEnvironment(syntheticEnvironment(8, [&](int face, int, int) { return colours[face]; }));
    const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int face = 0; face < 6; ++face)
        EXPECT_EQ(environmentRadiance(map, axes[face]), glm::vec3(colours[face]) / 255.0f) << "face " << face;
}

// Every texel its own colour (face, x, y): at each texel's centre, taken from the independent
// table, the lookup returns that texel; halfway between two texels of a row, their mean.
TEST(EnvironmentLookup, TexelCentresFromTheOpenGlTableReturnThatTexel) {
    const int n = 6;
    const FaceTexels texel = [](int face, int x, int y) { return glm::u8vec3(40 * face + 3, 40 * x + 1, 40 * y + 2); };
    const EnvironmentTexels map = borderedEnvironment(syntheticEnvironment(n, texel));
    for (int face = 0; face < 6; ++face) {
        for (int y = 0; y < n; ++y) {
            for (int x = 0; x < n; ++x) {
                const glm::vec3 want = glm::vec3(texel(face, x, y)) / 255.0f;
                const glm::vec3 got = environmentRadiance(map, tablePoint(face, glm::vec2(x + 0.5f, y + 0.5f) / float(n)));
                // A centre's weight is 0 or 1 up to rounding of (x + 0.5) / n * n + 0.5: 1e-5 of a
                // neighbour at most 200/255 away.
                ASSERT_LT(glm::length(got - want), 1e-5f) << face << " " << x << " " << y;
                if (x + 1 < n) {
                    const glm::vec3 mean = (want + glm::vec3(texel(face, x + 1, y)) / 255.0f) * 0.5f;
                    const glm::vec3 between = environmentRadiance(map, tablePoint(face, glm::vec2(x + 1.0f, y + 0.5f) / float(n)));
                    ASSERT_LT(glm::length(between - mean), 1e-5f) << face << " " << x << " " << y;
                }
            }
        }
    }
}

// Loaded from files (the OpenGL rule forced: these faces have no seams to measure), the faces keep
// the files' order and rows: posX is +X, row 0 of each file is its top (t = 0).
TEST(EnvironmentLookup, FacesLoadInTheFilesOrderTopRowFirst) {
    const std::string prefix = (std::filesystem::temp_directory_path() / ("vkrt_env_order_" + std::to_string(getpid())) / "sky_").string();
    const FaceTexels texel = [](int face, int x, int y) { return glm::u8vec3(40 * face, 60 * x, 60 * y); };
    writeCubeFaces(prefix, 4, texel);
    EnvironmentProblem problem;
    const std::optional<Environment> environment = loadCubeFaceEnvironment(prefix, NegZRule::OpenGL, problem);
    std::filesystem::remove_all(std::filesystem::path(prefix).parent_path());
    ASSERT_TRUE(environment) << problem.problem << " " << problem.value;
    EXPECT_FALSE(environment->negZMirrored);
    const EnvironmentTexels map = borderedEnvironment(*environment);
    for (int face = 0; face < 6; ++face)
        EXPECT_LT(glm::length(environmentRadiance(map, tablePoint(face, glm::vec2(0.125f, 0.875f))) - glm::vec3(texel(face, 0, 3)) / 255.0f),
                  1e-5f)
            << face;
}

}  // namespace
}  // namespace vkrt::test
