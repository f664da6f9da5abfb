// Wachter & Binder ray offsets (RENDERING.md §6): the offset point is strictly on the requested
// side of the surface, by an amount that scales with the coordinates, and tiny near the origin.
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

TEST(RayOffset, MovesByIntScaleUlpsAwayFromTheOrigin) {
    // A coordinate of 8 along a +x normal moves by exactly 256 ULPs; the others do not move.
    const glm::vec3 q = offsetRayOrigin({8.0f, 8.0f, -8.0f}, {1, 0, 0});
    EXPECT_EQ(q.x, std::nextafter(8.0f, 16.0f) + 255.0f * std::ldexp(1.0f, 3 - 23));
    EXPECT_EQ(q.y, 8.0f);
    EXPECT_EQ(q.z, -8.0f);
    // Negative coordinates move in the normal's direction too.
    const glm::vec3 r = offsetRayOrigin({-8.0f, 1.0f, 1.0f}, {1, 0, 0});
    EXPECT_GT(r.x, -8.0f);
    EXPECT_EQ(r.x, -8.0f + 256.0f * std::ldexp(1.0f, 2 - 23));  // below 8 in magnitude ULPs halve
}

TEST(RayOffset, NearTheOriginUsesAFixedOffset) {
    const glm::vec3 n = glm::normalize(glm::vec3(1, 1, 0));
    const glm::vec3 q = offsetRayOrigin({0.0f, 0.01f, 0.0f}, n);
    EXPECT_FLOAT_EQ(q.x, n.x / 65536.0f);
    EXPECT_FLOAT_EQ(q.y, 0.01f + n.y / 65536.0f);
    EXPECT_EQ(q.z, 0.0f);
}

TEST(RayOffset, SideOfFollowsTheDirection) {
    const glm::vec3 n(0, 1, 0);
    EXPECT_EQ(sideOf(n, {0.3f, 0.1f, 0}), n);
    EXPECT_EQ(sideOf(n, {0.3f, -0.1f, 0}), -n);
    EXPECT_EQ(sideOf(n, {1, 0, 0}), n);  // tangent directions count as the front
}

}  // namespace
}  // namespace vkrt::cpu
