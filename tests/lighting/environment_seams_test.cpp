// The course's environment maps, loaded as vkrt reads them, have no seams: across each of the
// cube's 12 edges the lookup steps no more than it does between neighbouring texels inside the
// faces there, and it is continuous at the edges and corners themselves (the bordered faces).
// The -Z rule and the vertical cross's cell orientations are the ones the seams measure.
#include <algorithm>
#include <array>
#include <cstdio>
#include <limits>

#include <gtest/gtest.h>

#include "cube_map.h"
#include "environment_loading.h"
#include "environment_map.h"
#include "environment_test_maps.h"
#include "test_paths.h"
#include "texture_loading.h"

namespace vkrt::test {
namespace {

Environment loadFaces(const std::string& prefix, NegZRule rule) {
    EnvironmentProblem problem;
    std::optional<Environment> environment = loadCubeFaceEnvironment(prefix, rule, problem);
    EXPECT_TRUE(environment) << problem.problem << " " << problem.value;
    return environment ? std::move(*environment) : Environment{};
}

Environment loadCross(const std::string& path) {
    EnvironmentProblem problem;
    std::optional<Environment> environment = loadVerticalCrossEnvironment(path, problem);
    EXPECT_TRUE(environment) << problem.problem << " " << problem.value;
    return environment ? std::move(*environment) : Environment{};
}

// The seam bound. A seamless map's step across an edge is a step between neighbouring texels like
// any other, so its mean along the edge is close to the interior's there; the course's maps were
// resampled into faces one by one (and stored in 8 bits), which adds a little: across / interior
// measured 0.58-1.33 on the 36 edges of the three maps as vkrt reads them. A mirrored face puts
// unrelated texels side by side instead: 2.99 (-Y/-Z, a dark, smooth edge) to 103 (+Y/-Z) on the
// four -Z edges of the 2021 set read as OpenGL. The bound, 2, sits between, with room both sides.
constexpr double kSeamRatio = 2.0;
bool withinSeamBound(const EdgeSteps& s) { return s.across <= kSeamRatio * s.interior; }

// 2000 points per edge: about two per texel of a 1024 face. At a thousandth of a texel either side
// of an edge, a continuous bilinear lookup differs by at most its slope (255/255 per texel at the
// very most) times 2e-3 texel: 0.51 in 0-255 units (measured up to 0.41), plus float rounding.
// A lookup without the borders (clamped at the face's own edge texels) would differ there by the
// full step across the edge, 0.2-69 on these maps.
constexpr int kPoints = 2000;
constexpr double kEpsilon = 1e-3;
constexpr double kContinuity = 0.6;

void reportAndCheck(const char* name, const EnvironmentTexels& map, bool expectSeamless) {
    double worstRatio = 0.0;
    for (const CubeEdge& edge : cubeEdges()) {
        const EdgeSteps s = edgeSteps(map, edge, kPoints, kEpsilon);
        std::printf("%s %s: across %.2f interior %.2f ratio %.2f at-edge %.3f\n", name, edgeName(edge).c_str(), s.across,
                    s.interior, s.across / s.interior, s.atEdge);
        worstRatio = std::max(worstRatio, s.across / s.interior);
        if (expectSeamless) EXPECT_TRUE(withinSeamBound(s)) << name << " " << edgeName(edge) << ": across " << s.across << ", interior " << s.interior;
        EXPECT_LE(s.atEdge, kContinuity) << name << " " << edgeName(edge);
    }
    std::printf("%s: worst across/interior %.2f\n", name, worstRatio);
}

TEST(EnvironmentSeams, The2018FacesHaveNoSeams) {
    VKRT_SKIP_WITHOUT(reef2018Prefix() + "negZ.png");
    reportAndCheck("reef 2018", borderedEnvironment(loadFaces(reef2018Prefix(), NegZRule::Measure)), true);
}

TEST(EnvironmentSeams, The2021FacesHaveNoSeams) {
    VKRT_SKIP_WITHOUT(reef2021Prefix() + "negZ.png");
    reportAndCheck("reef 2021", borderedEnvironment(loadFaces(reef2021Prefix(), NegZRule::Measure)), true);
}

TEST(EnvironmentSeams, TheUffiziCrossHasNoSeams) {
    VKRT_SKIP_WITHOUT(uffiziCross());
    reportAndCheck("uffizi", borderedEnvironment(loadCross(uffiziCross())), true);
}

// The -Z rule matters: read as plain OpenGL, the 2021 set breaks the bound on exactly the four
// -Z edges (and the lookup stays continuous at them: the border copies whatever is across).
TEST(EnvironmentSeams, The2021FacesReadAsOpenGlBreakTheNegZEdges) {
    VKRT_SKIP_WITHOUT(reef2021Prefix() + "negZ.png");
    const EnvironmentTexels map = borderedEnvironment(loadFaces(reef2021Prefix(), NegZRule::OpenGL));
    reportAndCheck("reef 2021 as OpenGL", map, false);
    for (const CubeEdge& edge : cubeEdges()) {
        const bool negZ = edge.across == static_cast<int>(cubemap::CUBE_NEG_Z) || edge.face == static_cast<int>(cubemap::CUBE_NEG_Z);
        EXPECT_EQ(withinSeamBound(edgeSteps(map, edge, kPoints, kEpsilon)), !negZ) << edgeName(edge);
    }
}

// The measurement the load makes: the 2018 -Z face joins its neighbours as OpenGL reads it, the 2021
// one mirrored; read so, the 2021 face is the 2018 face texel for texel (JSON_FORMAT.md §5.3: the
// new file is the old one mirrored).
TEST(EnvironmentSeams, TheNegZRuleReadsEachSetTheWayItsSeamsJoin) {
    VKRT_SKIP_WITHOUT(reef2018Prefix() + "negZ.png");
    VKRT_SKIP_WITHOUT(reef2021Prefix() + "negZ.png");
    const Environment old = loadFaces(reef2018Prefix(), NegZRule::Measure);
    const Environment current = loadFaces(reef2021Prefix(), NegZRule::Measure);
    std::printf("-Z seam error, 2018 set: as OpenGL %.2f, mirrored %.2f\n", old.negZSeamErrorAsOpenGL, old.negZSeamErrorMirrored);
    std::printf("-Z seam error, 2021 set: as OpenGL %.2f, mirrored %.2f\n", current.negZSeamErrorAsOpenGL,
                current.negZSeamErrorMirrored);
    EXPECT_FALSE(old.negZMirrored);
    EXPECT_TRUE(current.negZMirrored);
    EXPECT_LT(old.negZSeamErrorAsOpenGL, old.negZSeamErrorMirrored);
    EXPECT_LT(current.negZSeamErrorMirrored, current.negZSeamErrorAsOpenGL);
    EXPECT_TRUE(old.faces[cubemap::CUBE_NEG_Z] == current.faces[cubemap::CUBE_NEG_Z]);
    for (std::uint32_t face = 0; face < 5; ++face) EXPECT_TRUE(old.faces[face] == current.faces[face]) << face;
    // Forced, the rule is obeyed and nothing is measured.
    const Environment forced = loadFaces(reef2018Prefix(), NegZRule::Mirrored);
    EXPECT_TRUE(forced.negZMirrored);
    EXPECT_EQ(forced.negZSeamErrorAsOpenGL, 0.0);
}

// At each of the cube's 8 corners the three faces meet in one value: the points a thousandth of a
// texel from the corner on each face agree to the lookup's slope times that distance.
TEST(EnvironmentSeams, TheLookupIsContinuousAtEveryCorner) {
    VKRT_SKIP_WITHOUT(reef2021Prefix() + "negZ.png");
    const EnvironmentTexels map = borderedEnvironment(loadFaces(reef2021Prefix(), NegZRule::Measure));
    const float e = 1e-3f / float(map.faceSize);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 c((corner & 1) ? 1.0f : -1.0f, (corner & 2) ? 1.0f : -1.0f, (corner & 4) ? 1.0f : -1.0f);
        glm::vec3 seen[3];
        for (int axis = 0; axis < 3; ++axis) {
            glm::vec3 d = c * (1.0f - e);  // just inside the face of this axis, near the corner
            d[axis] = c[axis];
            const cubemap::CubeFacePoint p = cubemap::cubeFacePoint(d);
            ASSERT_EQ(p.face, static_cast<std::uint32_t>(2 * axis + (c[axis] < 0.0f ? 1 : 0)));
            seen[axis] = environmentRadiance(map, d);
        }
        EXPECT_LT(glm::length(seen[0] - seen[1]) * 255.0f, kContinuity) << corner;
        EXPECT_LT(glm::length(seen[0] - seen[2]) * 255.0f, kContinuity) << corner;
    }
}

// The vertical cross's cells: for the layout's face assignment (JSON_FORMAT.md §5.4), each cell
// may lie any of 8 ways on its face; the seam error over the cube's 12 edges is smallest for
// exactly the orientations kVerticalCross gives, among all 8^6 combinations.
TEST(VerticalCross, TheCellsOrientationsAreTheOnesItsSeamsMeasure) {
    VKRT_SKIP_WITHOUT(uffiziCross());
    std::string problem;
    const std::optional<Texture> image = loadTextureImage(uffiziCross(), problem);
    ASSERT_TRUE(image) << problem;
    const int k = image->width / 3;
    auto orientation = [](int o, CrossCell cell) {
        cell.transpose = (o & 4) != 0;
        cell.flipX = (o & 1) != 0;
        cell.flipY = (o & 2) != 0;
        return cell;
    };
    std::array<std::array<std::vector<std::uint32_t>, 8>, 6> oriented;
    for (int face = 0; face < 6; ++face)
        for (int o = 0; o < 8; ++o) oriented[face][o] = crossFace(*image, orientation(o, kVerticalCross[face]), k);
    const std::vector<CubeEdge> edges = cubeEdges();
    // seam[e][oFace][oAcross]
    std::vector<std::array<std::array<double, 8>, 8>> seam(edges.size());
    for (std::size_t e = 0; e < edges.size(); ++e) {
        for (int a = 0; a < 8; ++a) {
            for (int b = 0; b < 8; ++b) {
                CubeFaces faces;
                faces[edges[e].face] = oriented[edges[e].face][a];
                faces[edges[e].across] = oriented[edges[e].across][b];
                seam[e][a][b] = edgeSeamError(faces, k, edges[e].face, edges[e].edge);
            }
        }
    }
    double best = std::numeric_limits<double>::max(), second = best;
    int bestCombo = -1;
    for (int combo = 0; combo < (1 << 18); ++combo) {
        double sum = 0.0;
        for (std::size_t e = 0; e < edges.size(); ++e)
            sum += seam[e][(combo >> (3 * edges[e].face)) & 7][(combo >> (3 * edges[e].across)) & 7];
        if (sum < best) {
            second = best;
            best = sum;
            bestCombo = combo;
        } else if (sum < second) {
            second = sum;
        }
    }
    std::printf("vertical cross: best mean seam error %.2f, next best %.2f\n", best / 12.0, second / 12.0);
    for (std::size_t e = 0; e < edges.size(); ++e)
        std::printf("  %s: %.2f\n", edgeName(edges[e]).c_str(),
                    seam[e][(bestCombo >> (3 * edges[e].face)) & 7][(bestCombo >> (3 * edges[e].across)) & 7]);
    for (int face = 0; face < 6; ++face) {
        const int o = (bestCombo >> (3 * face)) & 7;
        std::printf("  face %d: transpose %d flipX %d flipY %d\n", face, (o >> 2) & 1, o & 1, (o >> 1) & 1);
        EXPECT_EQ((o & 4) != 0, kVerticalCross[face].transpose) << face;
        EXPECT_EQ((o & 1) != 0, kVerticalCross[face].flipX) << face;
        EXPECT_EQ((o & 2) != 0, kVerticalCross[face].flipY) << face;
    }
}

}  // namespace
}  // namespace vkrt::test
