// Ray/primitive routines of intersect.h against double-precision references and exact cases.
#include <gtest/gtest.h>

#include <random>

#include "intersect.h"

namespace vkrt::bvh::test {
namespace {

// Watertightness: rays aimed exactly at the shared vertices and edge points of a jittered grid
// mesh must hit at least one triangle (a leaky test lets some through).
TEST(Intersect, TriangleMeshIsWatertight) {
    std::mt19937 rng(31);
    std::uniform_real_distribution<float> jitter(-0.3f, 0.3f);
    const int n = 24;
    std::vector<glm::vec3> grid((n + 1) * (n + 1));
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
            grid[j * (n + 1) + i] = glm::vec3(i + (i > 0 && i < n ? jitter(rng) : 0.0f),
                                              j + (j > 0 && j < n ? jitter(rng) : 0.0f), 0.1f * jitter(rng));
    std::vector<std::array<glm::vec3, 3>> tris;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const glm::vec3 a = grid[j * (n + 1) + i], b = grid[j * (n + 1) + i + 1];
            const glm::vec3 c = grid[(j + 1) * (n + 1) + i], d = grid[(j + 1) * (n + 1) + i + 1];
            tris.push_back({a, b, d});
            tris.push_back({a, d, c});
        }
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    int misses = 0, rays = 0;
    for (int j = 1; j < n; ++j)
        for (int i = 1; i < n; ++i) {
            const glm::vec3 v = grid[j * (n + 1) + i];
            const glm::vec3 w = grid[j * (n + 1) + i + 1];
            for (const glm::vec3 target : {v, 0.5f * (v + w), v + 0.37f * (w - v)}) {
                const glm::vec3 origin(3.0f * u(rng) - 1.5f + target.x, 2.0f * u(rng) - 1.0f + target.y, 5.0f + u(rng));
                const glm::vec3 dir = target - origin;  // not normalised
                const WatertightRay wr(origin, dir);
                bool hit = false;
                for (const auto& t : tris) {
                    PrimHit h;
                    hit = hit || intersectTriangle(wr, t[0], t[1], t[2], 1e30f, h);
                }
                misses += hit ? 0 : 1;
                ++rays;
            }
        }
    EXPECT_EQ(misses, 0) << "of " << rays << " rays through vertices and edges";
}

// t and barycentrics against a double-precision Moller-Trumbore solve of the same ray.
TEST(Intersect, TriangleMatchesDoubleReference) {
    std::mt19937 rng(32);
    std::uniform_real_distribution<float> u(-10.0f, 10.0f);
    int hits = 0;
    for (int k = 0; k < 20000; ++k) {
        const glm::vec3 v0(u(rng), u(rng), u(rng)), v1(u(rng), u(rng), u(rng)), v2(u(rng), u(rng), u(rng));
        const glm::vec3 o(u(rng), u(rng), u(rng));
        const glm::vec3 d = (v0 + v1 + v2) / 3.0f + glm::vec3(u(rng), u(rng), u(rng)) * 0.3f - o;
        const glm::dvec3 e1 = glm::dvec3(v1) - glm::dvec3(v0), e2 = glm::dvec3(v2) - glm::dvec3(v0);
        const glm::dvec3 p = glm::cross(glm::dvec3(d), e2);
        const double det = glm::dot(e1, p);
        const glm::dvec3 s = glm::dvec3(o) - glm::dvec3(v0);
        const double bu = glm::dot(s, p) / det;
        const glm::dvec3 q = glm::cross(s, e1);
        const double bv = glm::dot(glm::dvec3(d), q) / det;
        const double t = glm::dot(e2, q) / det;
        const bool inside = bu > 1e-4 && bv > 1e-4 && bu + bv < 1.0 - 1e-4 && t > 1e-4;
        const bool outside = bu < -1e-4 || bv < -1e-4 || bu + bv > 1.0 + 1e-4 || t < -1e-4;
        PrimHit h;
        const bool got = intersectTriangle(WatertightRay(o, d), v0, v1, v2, 1e30f, h);
        if (inside) {
            ASSERT_TRUE(got) << k;
            ++hits;
            // Relative 1e-4: the float test's rounding scales with the condition of the triangle.
            EXPECT_NEAR(h.t, t, 1e-4 * t + 1e-5) << k;
            EXPECT_NEAR(h.u, bu, 1e-4) << k;
            EXPECT_NEAR(h.v, bv, 1e-4) << k;
        } else if (outside) {
            EXPECT_FALSE(got) << k;
        }
    }
    EXPECT_GT(hits, 5000);
}

TEST(Intersect, ZeroAreaTrianglesNeverHit) {
    std::mt19937 rng(33);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    const glm::vec3 a(0.0f), b(1.0f, 2.0f, 3.0f);
    const std::array<std::array<glm::vec3, 3>, 4> degenerate{{{a, a, a}, {a, b, b}, {a, b, a}, {a, 2.0f * b, b}}};
    for (const auto& tri : degenerate)
        for (int k = 0; k < 2000; ++k) {
            const glm::vec3 target = tri[0] + (tri[1] - tri[0]) * (0.5f + 0.5f * u(rng));
            const glm::vec3 o(u(rng) * 5.0f, u(rng) * 5.0f, 5.0f);
            PrimHit h;
            EXPECT_FALSE(intersectTriangle(WatertightRay(o, target - o), tri[0], tri[1], tri[2], 1e30f, h));
        }
}

TEST(Intersect, TriangleRespectsOpenInterval) {
    const glm::vec3 v0(-1.0f, -1.0f, 0.0f), v1(1.0f, -1.0f, 0.0f), v2(0.0f, 1.0f, 0.0f);
    const WatertightRay wr(glm::vec3(0.0f, 0.0f, 2.0f), glm::vec3(0.0f, 0.0f, -1.0f));
    PrimHit h;
    EXPECT_TRUE(intersectTriangle(wr, v0, v1, v2, 2.0001f, h));
    EXPECT_FLOAT_EQ(h.t, 2.0f);
    EXPECT_FALSE(intersectTriangle(wr, v0, v1, v2, 2.0f, h));  // t < tmax is strict
    const WatertightRay onPlane(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f));
    EXPECT_FALSE(intersectTriangle(onPlane, v0, v1, v2, 10.0f, h));  // t = 0 is not a hit
    const WatertightRay behind(glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 0.0f, -1.0f));
    EXPECT_FALSE(intersectTriangle(behind, v0, v1, v2, 10.0f, h));
}

// Ray/sphere in configurations where the textbook formula loses most digits: a far origin aimed
// at a small sphere, and a huge sphere (like an upstream "floor" sphere) seen from close by.
TEST(Intersect, SphereIsPreciseForFarOriginsAndLargeRadii) {
    std::mt19937 rng(34);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    struct Case {
        float distance, radius;
    };
    for (const Case c : {Case{1e4f, 1.0f}, Case{1e5f, 10.0f}, Case{50.0f, 1e5f}, Case{3.0f, 1.0f}}) {
        for (int k = 0; k < 500; ++k) {
            const glm::vec3 centre(u(rng) * 10.0f, u(rng) * 10.0f, u(rng) * 10.0f);
            const glm::vec3 o = centre + glm::vec3(0.3f * u(rng), 0.3f * u(rng), 1.0f) * (c.radius + c.distance);
            const glm::vec3 target = centre + glm::vec3(u(rng), u(rng), u(rng)) * (0.5f * c.radius);
            const glm::vec3 d = (target - o) * (0.5f + std::abs(u(rng)));
            // Reference in double from the same float inputs.
            const glm::dvec3 f = glm::dvec3(o) - glm::dvec3(centre), dd(d);
            const double a = glm::dot(dd, dd), b = glm::dot(f, dd), cc = glm::dot(f, f) - double(c.radius) * c.radius;
            const double disc = b * b - a * cc;
            ASSERT_GT(disc, 0.0);
            const double t = (-b - std::sqrt(disc)) / a;
            PrimHit h;
            ASSERT_TRUE(intersectSphere(o, d, centre, c.radius, 1e30f, h)) << c.distance << " " << c.radius;
            // Error of the hit point relative to the scene scale: a few float ulps of |o - centre|.
            const double scale = glm::length(f);
            EXPECT_NEAR(h.t * std::sqrt(a), t * std::sqrt(a), 4e-7 * scale + 1e-6 * c.radius)
                << "distance " << c.distance << " radius " << c.radius;
        }
    }
}

TEST(Intersect, SphereFromInsideAndBehind) {
    PrimHit h;
    ASSERT_TRUE(intersectSphere(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, 2.0f), glm::vec3(0.0f), 1.0f, 10.0f, h));
    EXPECT_FLOAT_EQ(h.t, 0.5f);  // exit point, in units of |dir|
    EXPECT_FALSE(intersectSphere(glm::vec3(0.0f, 0.0f, 5.0f), glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(0.0f), 1.0f, 10.0f, h));
    EXPECT_FALSE(intersectSphere(glm::vec3(0.0f, 0.0f, 5.0f), glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f), 1.0f, 3.9f, h));
    EXPECT_FALSE(intersectSphere(glm::vec3(0.0f, 2.0f, 5.0f), glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f), 1.0f, 10.0f, h));
    EXPECT_FALSE(intersectSphere(glm::vec3(0.0f, 0.0f, 5.0f), glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f), 0.0f, 10.0f, h));
}

TEST(Intersect, BoxFacesAndAxisParallelRays) {
    const glm::vec3 lo(-1.0f, -2.0f, -3.0f), hi(1.0f, 2.0f, 3.0f);
    PrimHit h;
    for (int axis = 0; axis < 3; ++axis)
        for (int sign : {-1, 1}) {
            glm::vec3 o(0.2f, -0.3f, 0.4f), d(0.0f);
            o[axis] = 10.0f * sign;
            d[axis] = -2.0f * sign;  // axis-parallel: the other two components are exactly 0
            ASSERT_TRUE(intersectBox(o, d, lo, hi, 100.0f, h));
            EXPECT_EQ(h.face, 2 * axis + (sign > 0 ? 1 : 0));
            EXPECT_FLOAT_EQ(h.t, (10.0f - hi[axis]) / 2.0f);
            EXPECT_EQ(boxFaceNormal(h.face)[axis], static_cast<float>(sign));
            // From inside: the exit face.
            ASSERT_TRUE(intersectBox(glm::vec3(0.0f), d, lo, hi, 100.0f, h));
            EXPECT_EQ(h.face, 2 * axis + (sign > 0 ? 0 : 1));
            EXPECT_FLOAT_EQ(h.t, hi[axis] / 2.0f);
        }
    // Origin exactly on a face plane, running along it (0 * inf would be NaN in a naive test).
    ASSERT_TRUE(intersectBox(glm::vec3(-1.0f, 0.0f, -10.0f), glm::vec3(0.0f, 0.0f, 1.0f), lo, hi, 100.0f, h));
    EXPECT_FLOAT_EQ(h.t, 7.0f);
    EXPECT_EQ(h.face, 4);
    // Parallel to a slab and outside it: a miss, not NaN.
    EXPECT_FALSE(intersectBox(glm::vec3(-1.5f, 0.0f, -10.0f), glm::vec3(0.0f, 0.0f, 1.0f), lo, hi, 100.0f, h));
    // A flat box (zero thickness) is still hit.
    ASSERT_TRUE(intersectBox(glm::vec3(0.0f, 0.0f, 5.0f), glm::vec3(0.1f, 0.0f, -1.0f), glm::vec3(-1.0f, -1.0f, 0.0f),
                             glm::vec3(1.0f, 1.0f, 0.0f), 100.0f, h));
    EXPECT_FLOAT_EQ(h.t, 5.0f);
    EXPECT_EQ(h.face, 5);
    // tmax is exclusive, and boxes behind the origin are not hit.
    EXPECT_FALSE(intersectBox(glm::vec3(0.0f, 0.0f, 10.0f), glm::vec3(0.0f, 0.0f, -1.0f), lo, hi, 7.0f, h));
    EXPECT_FALSE(intersectBox(glm::vec3(0.0f, 0.0f, 10.0f), glm::vec3(0.0f, 0.0f, 1.0f), lo, hi, 100.0f, h));
}

}  // namespace
}  // namespace vkrt::bvh::test
