// The wide node's box test (wide_slab.h): the AVX path of the default build and the two-SSE-halves
// path of a build without AVX against a scalar transcription of the same float operations, lane
// by lane and bit for bit, so a build of either kind walks the same tree the same way.
#include <gtest/gtest.h>

#include <cfloat>
#include <cstring>
#include <random>

#include "node_layout.h"
#include "wide_slab.h"

namespace vkrt::bvh::test {
namespace {

// The slab test of one child, in the order the SIMD paths compute it: max/min take their second
// operand on a tie or a NaN, as maxps/minps do.
bool scalarSlab(const WideNode& node, int k, const glm::vec3& origin, const glm::vec3& dir, float tmax, float& tEntry) {
    float tn = 0.0f, tf = tmax;
    for (int a = 0; a < 3; ++a) {
        const float d = std::abs(dir[a]) < 0x1p-100f ? (dir[a] < 0.0f ? -0x1p-100f : 0x1p-100f) : dir[a];
        const float inv = 1.0f / d;
        const int nearRow = 2 * a + (d < 0.0f ? 1 : 0);
        const float n = (node.bounds[nearRow][k] - origin[a]) * inv;
        const float f = (node.bounds[nearRow ^ 1][k] - origin[a]) * inv;
        tn = tn > n ? tn : n;
        tf = tf < f ? tf : f;
    }
    tEntry = tn;
    return tn <= tf * kSlabFarScale;
}

float pick(std::mt19937& rng, float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }

// A node of random boxes, a quarter of its slots empty (lo = +FLT_MAX, hi = -FLT_MAX), some flat.
WideNode randomNode(std::mt19937& rng) {
    alignas(64) WideNode node{};
    for (int k = 0; k < kWideWidth; ++k) {
        const bool empty = rng() % 4 == 0;
        for (int a = 0; a < 3; ++a) {
            float lo = pick(rng, -10.0f, 10.0f), hi = lo + (rng() % 8 == 0 ? 0.0f : pick(rng, 0.0f, 10.0f));
            if (empty) lo = FLT_MAX, hi = -FLT_MAX;
            node.bounds[2 * a][k] = lo;
            node.bounds[2 * a + 1][k] = hi;
        }
        node.link[k] = empty ? NODE_NONE : static_cast<std::uint32_t>(k);
        node.count[k] = 0;
    }
    return node;
}

// Directions with zero, -0, tiny and huge components; origins near, inside and far from the boxes.
glm::vec3 randomDirection(std::mt19937& rng) {
    glm::vec3 d;
    for (int a = 0; a < 3; ++a) {
        switch (rng() % 6) {
        case 0: d[a] = 0.0f; break;
        case 1: d[a] = -0.0f; break;
        case 2: d[a] = pick(rng, -1e-30f, 1e-30f); break;
        case 3: d[a] = pick(rng, -1e30f, 1e30f); break;
        default: d[a] = pick(rng, -1.0f, 1.0f); break;
        }
    }
    return d;
}

TEST(WideSlab, AvxAndSseHalvesAgreeWithTheScalarTestBitForBit) {
    std::mt19937 rng(8);
    int hits = 0, misses = 0;
    for (int round = 0; round < 20000; ++round) {
        const WideNode node = randomNode(rng);
        const float scale = rng() % 8 == 0 ? 1e30f : 15.0f;
        const glm::vec3 origin(pick(rng, -scale, scale), pick(rng, -scale, scale), pick(rng, -scale, scale));
        glm::vec3 dir = randomDirection(rng);
        // Half the rays aim at a child's centre (some along a coordinate plane), so that hits are common.
        const int aim = static_cast<int>(rng() % kWideWidth);
        if (rng() % 2 == 0 && node.link[aim] != NODE_NONE) {
            for (int a = 0; a < 3; ++a) dir[a] = 0.5f * (node.bounds[2 * a][aim] + node.bounds[2 * a + 1][aim]) - origin[a];
            if (rng() % 4 == 0) dir[rng() % 3] = rng() % 2 ? 0.0f : -0.0f;
        }
        const float tmax = rng() % 4 == 0 ? INFINITY : pick(rng, 0.0f, 40.0f);
        const NodeRay ray(origin, dir);
        alignas(32) float tWide[kWideWidth], tSse[kWideWidth];
        const int maskWide = slabs(node, ray, tmax, tWide);
        const int maskSse = slabsSse(node, ray, tmax, tSse);
        for (int k = 0; k < kWideWidth; ++k) {
            float t = 0.0f;
            const bool hit = scalarSlab(node, k, origin, dir, tmax, t);
            ASSERT_EQ(((maskWide >> k) & 1) != 0, hit) << "round " << round << " child " << k << " (slabs)";
            ASSERT_EQ(((maskSse >> k) & 1) != 0, hit) << "round " << round << " child " << k << " (slabsSse)";
            ASSERT_EQ(0, std::memcmp(&tWide[k], &t, sizeof t)) << "round " << round << " child " << k;
            ASSERT_EQ(0, std::memcmp(&tSse[k], &t, sizeof t)) << "round " << round << " child " << k;
            if (node.link[k] == NODE_NONE) {
                ASSERT_FALSE(hit) << "round " << round << ": empty slot " << k << " entered";
            }
            (hit ? hits : misses) += 1;
        }
    }
    // Both outcomes well represented, so the comparison tested something.
    EXPECT_GT(hits, 5000);
    EXPECT_GT(misses, 50000);
}

}  // namespace
}  // namespace vkrt::bvh::test
