// The CPU traversal's four-triangle leaves (triangle_groups.h, traverse.cpp) against the
// one-triangle watertight test (intersectTriangle): the leaf computes the same float operations
// lane by lane, so for every ray the hit it reports must be that triangle's own hit bit for bit
// (t, u, v), hits and misses must be brute force's, and no ray through a shared vertex or edge of
// a closed mesh may slip through (the double fallback for exactly-zero edge functions).
#include <array>
#include <bit>
#include <random>

#include <gtest/gtest.h>

#include "brute_force.h"
#include "hit_order.h"
#include "intersect.h"
#include "scene_gen.h"

namespace vkrt::bvh::test {
namespace {

PrimitiveInput triangle(glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    PrimitiveInput p;
    p.kind = gpu::PRIM_KIND_TRIANGLE;
    p.a = a, p.b = b, p.c = c;
    return p;
}

std::array<glm::vec3, 3> corners(const gpu::Primitive& p) {
    const auto f = [](std::uint32_t u) { return std::bit_cast<float>(u); };
    return {glm::vec3(f(p.a.x), f(p.a.y), f(p.a.z)), glm::vec3(f(p.b.x), f(p.b.y), f(p.b.z)),
            glm::vec3(f(p.c.x), f(p.c.y), f(p.c.z))};
}

// A closed box's six faces, each an n x n grid of integer-cornered triangles, so rays aimed at
// corners and edge midpoints from dyadic origins give exactly-zero edge functions; plus two
// collinear triangles inside it (never hit).
std::vector<PrimitiveInput> gridBox(int n) {
    std::vector<PrimitiveInput> prims;
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side)
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    const auto at = [&](int a, int b) {
                        glm::vec3 v;
                        v[axis] = static_cast<float>(side * n);
                        v[(axis + 1) % 3] = static_cast<float>(a);
                        v[(axis + 2) % 3] = static_cast<float>(b);
                        return v;
                    };
                    prims.push_back(triangle(at(i, j), at(i + 1, j), at(i + 1, j + 1)));
                    prims.push_back(triangle(at(i, j), at(i + 1, j + 1), at(i, j + 1)));
                }
    prims.push_back(triangle({1, 1, 1}, {2, 2, 2}, {3, 3, 3}));
    prims.push_back(triangle({1, 2, 1}, {1, 2, 1}, {3, 2, 1}));
    return prims;
}

// Every ray: the leaf's hit is its triangle's own, bit for bit, and hit or miss agrees with brute
// force; returns how many rays hit.
int expectLeafHitsAreTheTrianglesOwn(const TestScene& scene, const std::vector<Ray>& rays, const BuildOptions& options) {
    const SceneBvh bvh = buildSceneBvh(scene.groups, scene.instances, options);
    EXPECT_FALSE(bvh.cpu.triangles.groups.empty()) << "no leaf of two or more triangles: the test tests nothing";
    const FlatIndex flat = flatIndexOf(bvh);
    int hits = 0;
    for (const Ray& ray : rays) {
        Hit hit;
        BruteHit ref;
        const bool got = intersectClosest(bvh, ray, hit);
        EXPECT_EQ(got, bruteClosest(scene, bvh.instances, flat, ray, ref));
        EXPECT_EQ(intersectAny(bvh, ray), got);
        if (!got) continue;
        ++hits;
        const auto v = corners(bvh.prims[hit.prim]);
        PrimHit own;
        if (!intersectTriangle(WatertightRay(ray.origin, ray.dir), v[0], v[1], v[2], ray.tmax, own)) {
            ADD_FAILURE() << "prim " << hit.prim << " reported, but the one-triangle test misses it";
            continue;
        }
        EXPECT_EQ(std::bit_cast<std::uint32_t>(hit.t), std::bit_cast<std::uint32_t>(own.t));
        EXPECT_EQ(std::bit_cast<std::uint32_t>(hit.u), std::bit_cast<std::uint32_t>(own.u));
        EXPECT_EQ(std::bit_cast<std::uint32_t>(hit.v), std::bit_cast<std::uint32_t>(own.v));
    }
    return hits;
}

TEST(TriangleLeaves, ReportTheOneTriangleTestsHitsBitForBitAndNoRaySlipsThroughAClosedMesh) {
    const int n = 6;
    const TestScene scene = singleGroup(gridBox(n));
    // From dyadic points inside the box towards its faces' corners and edge midpoints: a ray that
    // finds no face has slipped through a shared vertex or edge.
    std::mt19937 rng(5);
    std::uniform_int_distribution<int> cell(1, 4 * n - 1);
    std::vector<Ray> rays;
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side)
            for (int j = 0; j <= 2 * n; ++j)
                for (int i = 0; i <= 2 * n; ++i) {
                    glm::vec3 target;
                    target[axis] = static_cast<float>(side * n);
                    target[(axis + 1) % 3] = 0.5f * static_cast<float>(i);
                    target[(axis + 2) % 3] = 0.5f * static_cast<float>(j);
                    Ray r;
                    r.origin = glm::vec3(cell(rng), cell(rng), cell(rng)) * 0.25f;
                    r.dir = target - r.origin;
                    r.tmax = 2.0f;
                    rays.push_back(r);
                }
    for (float traversalCost : {1.0f, 4.0f}) {  // 4: leaves of up to 8 triangles (two groups)
        BuildOptions options;
        options.traversalCost = traversalCost;
        EXPECT_EQ(expectLeafHitsAreTheTrianglesOwn(scene, rays, options), static_cast<int>(rays.size()))
            << "rays slipped through the closed box (C_trav " << traversalCost << ")";
    }
}

TEST(TriangleLeaves, RandomSoupsAgreeWithTheOneTriangleTest) {
    std::mt19937 rng(11);
    const TestScene scene = singleGroup(randomTriangles(rng, 3000, 10.0f, 1.0f));
    const std::vector<Ray> rays = randomRays(rng, scene, 4000);
    for (float traversalCost : {1.0f, 4.0f}) {
        BuildOptions options;
        options.traversalCost = traversalCost;
        EXPECT_GT(expectLeafHitsAreTheTrianglesOwn(scene, rays, options), 1000);
    }
}

}  // namespace
}  // namespace vkrt::bvh::test
