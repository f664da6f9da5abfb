// Ray offsets (RENDERING.md §6): the offset point is strictly on the requested side of the surface,
// by 2^-20 of the error magnitude (the larger of the point's own and the primitive's).
#include <cmath>
#include <cstdint>

#include <gtest/gtest.h>

#include "ray_offset.h"

namespace vkrt::cpu {
namespace {

// Signed distance of q from the plane through p with unit normal n, in double.
double side(glm::vec3 q, glm::vec3 p, glm::vec3 n) {
    return glm::dot(glm::dvec3(q) - glm::dvec3(p), glm::dvec3(n));
}

TEST(RayOffset, LeavesOnTheRequestedSideAtEveryScale) {
    const glm::vec3 normals[] = {glm::normalize(glm::vec3(0.3f, 0.9f, -0.2f)), glm::vec3(0, 0, 1),
                                 glm::normalize(glm::vec3(-1, -1, 1))};
    for (float scale : {1e-3f, 0.5f, 1.0f, 37.0f, 1e4f})
        for (const glm::vec3& n : normals)
            for (const glm::vec3& dir : {glm::vec3(1, 2, 3), glm::vec3(-3, 1, -2), glm::vec3(2, -5, 1)}) {
                const glm::vec3 p = scale * dir;
                EXPECT_GT(side(offsetRayOrigin(p, n), p, n), 0.0) << "scale " << scale;
                EXPECT_LT(side(offsetRayOrigin(p, -n), p, n), 0.0) << "scale " << scale;
            }
}

TEST(RayOffset, MovesAlongTheNormalByTheMagnitudeBound) {
    // |p| = 8 is the magnitude: 8 * 2^-20 = 2^-17 along +x, computed exactly in float.
    const glm::vec3 q = offsetRayOrigin({8.0f, 8.0f, -8.0f}, {1, 0, 0});
    EXPECT_EQ(q.x, 8.0f + std::ldexp(1.0f, -17));
    EXPECT_EQ(q.y, 8.0f);
    EXPECT_EQ(q.z, -8.0f);
    // A larger primitive magnitude wins over the point's own.
    const glm::vec3 r = offsetRayOrigin({0.0f, 0.0f, 0.0f}, {0, 1, 0}, 1024.0f);
    EXPECT_EQ(r, glm::vec3(0.0f, 1024.0f * std::ldexp(1.0f, -20), 0.0f));
}

TEST(RayOffset, ScalesWithTheScene) {
    // The same configuration scaled by a power of two moves by exactly the scaled offset, also
    // near the origin (where the Wachter & Binder offset used a fixed 2^-16).
    const glm::vec3 n = glm::normalize(glm::vec3(1, 1, 0));
    for (float scale : {0x1p-14f, 1.0f, 0x1p17f}) {
        const glm::vec3 p = scale * glm::vec3(0.0f, 0.01f, 0.0f);
        const glm::vec3 q = offsetRayOrigin(p, n, scale * 2.0f);
        EXPECT_FLOAT_EQ(q.x, scale * 2.0f * n.x * std::ldexp(1.0f, -20)) << "scale " << scale;
        EXPECT_GT(q.y, p.y) << "scale " << scale;
        EXPECT_EQ(q.z, 0.0f);
    }
}

TEST(RayOffset, SideOfFollowsTheDirection) {
    const glm::vec3 n(0, 1, 0);
    EXPECT_EQ(sideOf(n, {0.3f, 0.1f, 0}), n);
    EXPECT_EQ(sideOf(n, {0.3f, -0.1f, 0}), -n);
    EXPECT_EQ(sideOf(n, {1, 0, 0}), n);  // tangent directions count as the front
}

}  // namespace
}  // namespace vkrt::cpu
