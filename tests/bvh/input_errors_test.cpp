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
