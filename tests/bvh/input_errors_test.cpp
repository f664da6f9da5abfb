// Bad input gets a one-line std::invalid_argument naming where and what, never a crash.
#include <gtest/gtest.h>

#include <cmath>

#include "bvh.h"

namespace vkrt::bvh::test {
namespace {

std::string buildError(const std::vector<std::vector<PrimitiveInput>>& groups, const std::vector<InstanceInput>& instances,
                       const BuildOptions& options = {}) {
    try {
        buildSceneBvh(groups, instances, options);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

const InstanceInput kIdentity{0, glm::mat4(1.0f), gpu::MATERIAL_NONE};

TEST(InputErrors, BadPrimitivesNameGroupAndIndex) {
    const PrimitiveInput good{gpu::PRIM_KIND_TRIANGLE, glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f)};
    std::vector<PrimitiveInput> prims(50, good);
    prims[17].b.y = NAN;
    EXPECT_NE(buildError({{good}, prims}, {kIdentity}).find("group 1, primitive 17"), std::string::npos);
    prims[17] = {gpu::PRIM_KIND_SPHERE, glm::vec3(0.0f), glm::vec3(-2.0f), {}};
    EXPECT_NE(buildError({prims}, {kIdentity}).find("radius must be finite and >= 0, got -2"), std::string::npos);
    prims[17] = {gpu::PRIM_KIND_BOX, glm::vec3(0.0f, 5.0f, 0.0f), glm::vec3(1.0f), {}};
    EXPECT_NE(buildError({prims}, {kIdentity}).find("primitive 17: box min (0, 5, 0) exceeds max"), std::string::npos);
    prims[17].kind = 3;
    EXPECT_NE(buildError({prims}, {kIdentity}).find("unknown primitive kind 3"), std::string::npos);
}

TEST(InputErrors, BadInstances) {
    const std::vector<std::vector<PrimitiveInput>> groups(2);
    EXPECT_NE(buildError(groups, {{5, glm::mat4(1.0f), gpu::MATERIAL_NONE}}).find("instance 0 refers to group 5"),
              std::string::npos);
    glm::mat4 singular(1.0f);
    singular[1][1] = 0.0f;
    EXPECT_NE(buildError(groups, {kIdentity, {1, singular, 0}}).find("instance 1: transform is singular"), std::string::npos);
    glm::mat4 projective(1.0f);
    projective[2][3] = 1.0f;
    EXPECT_NE(buildError(groups, {{1, projective, 0}}).find("not affine"), std::string::npos);
    glm::mat4 nan(1.0f);
    nan[3][0] = NAN;
    EXPECT_NE(buildError(groups, {{1, nan, 0}}).find("non-finite entry at row 0, column 3"), std::string::npos);
}

// Issue 38, item 1: finite primitives whose bounds' lo + hi overflows float (a sphere centred at
// 1.8e38, a triangle at 3e38) made the single-axis binning compute inf - inf = NaN and cast it to a
// bin index of -2^31 (a crash, UBSan's report in Bins::addAxis). Every finite input must build, and
// the tree must still find the ordinary primitives beside the huge ones.
TEST(InputErrors, BoundsThatOverflowFloatStillBuildATreeThatFindsTheRest) {
    std::vector<PrimitiveInput> prims;
    for (int i = 0; i < 40; ++i) {
        const float x = static_cast<float>(i);
        prims.push_back({gpu::PRIM_KIND_TRIANGLE, glm::vec3(x, 0.0f, 5.0f), glm::vec3(x + 0.5f, 0.0f, 5.0f), glm::vec3(x, 0.5f, 5.0f)});
    }
    prims.push_back({gpu::PRIM_KIND_SPHERE, glm::vec3(1.8e38f, 0.0f, 0.0f), glm::vec3(1.0f), {}});
    prims.push_back({gpu::PRIM_KIND_TRIANGLE, glm::vec3(3e38f), glm::vec3(3e38f, 3.1e38f, 3e38f), glm::vec3(3.2e38f, 3e38f, 3e38f)});
    prims.push_back({gpu::PRIM_KIND_BOX, glm::vec3(-3.4e38f), glm::vec3(-3e38f), {}});
    for (int bins : {4, 16}) {
        BuildOptions options;
        options.bins = bins;
        options.threads = 1;
        const SceneBvh bvh = buildSceneBvh({prims}, {kIdentity}, options);
        for (int i = 0; i < 40; ++i) {
            const Ray ray{glm::vec3(static_cast<float>(i) + 0.1f, 0.1f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f), 1e30f};
            Hit hit;
            ASSERT_TRUE(intersectClosest(bvh, ray, hit)) << "triangle " << i << ", " << bins << " bins";
            EXPECT_NEAR(hit.t, 5.0f, 1e-5f);
            EXPECT_EQ(bvh.primSource[hit.prim], static_cast<std::uint32_t>(i)) << bins << " bins";
        }
    }
    // The same at the top level: instances of one triangle, a few translated by 2e38 or more.
    const std::vector<PrimitiveInput> one = {prims[0]};
    std::vector<InstanceInput> instances;
    for (int i = 0; i < 40; ++i) {
        glm::mat4 m(1.0f);
        m[3] = glm::vec4(static_cast<float>(i), 0.0f, 0.0f, 1.0f);
        instances.push_back({0, m, gpu::MATERIAL_NONE});
    }
    for (float far : {2e38f, -2.5e38f, 3.3e38f}) {
        glm::mat4 m(1.0f);
        m[3] = glm::vec4(far, far, 0.0f, 1.0f);
        instances.push_back({0, m, gpu::MATERIAL_NONE});
    }
    const SceneBvh top = buildSceneBvh({one}, instances, {});
    for (int i = 0; i < 40; ++i) {
        Hit hit;
        ASSERT_TRUE(intersectClosest(top, Ray{glm::vec3(static_cast<float>(i) + 0.1f, 0.1f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f), 1e30f}, hit))
            << "instance " << i;
        EXPECT_EQ(hit.instance, static_cast<std::uint32_t>(i));
    }
}

TEST(InputErrors, BadOptions) {
    BuildOptions o;
    o.bins = 1;
    EXPECT_NE(buildError({{}}, {kIdentity}, o).find("bins must be in"), std::string::npos);
    o = {};
    o.maxLeafSize = 0;
    EXPECT_NE(buildError({{}}, {kIdentity}, o).find("maxLeafSize"), std::string::npos);
    o = {};
    o.maxBottomDepth = 0;
    EXPECT_NE(buildError({{}}, {kIdentity}, o).find("maxBottomDepth"), std::string::npos);
}

}  // namespace
}  // namespace vkrt::bvh::test
