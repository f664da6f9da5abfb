// The CPU traversal's box test of a wide node (wide_bvh.h): all 8 children against one ray.
// Its own header so that tests hold the AVX path and the SSE path (the build without AVX) to the
// same answers (tests/bvh/wide_slab_test.cpp).
//
// Slab test (Kay & Kajiya 1986) with each axis's near plane chosen by the sign of the direction
// (Williams et al. 2005), so an empty slot, stored as lo = +FLT_MAX > hi = -FLT_MAX, always gives
// tNear > tFar. Direction components of magnitude below 2^-100 are replaced by +-2^-100: the
// inverse is then finite, so (plane - origin) * inverse is never 0 * inf = NaN, and the slab of an
// axis-parallel ray is (-huge, +huge) inside the slab and entirely on one side outside it
// (conservative at worst).
#pragma once

#include <immintrin.h>

#include <cmath>

#include <glm/glm.hpp>

#include "wide_bvh.h"

namespace vkrt::bvh {

static_assert(kWideWidth == 8, "the slab tests below test 8 children");

// The ray's origin and inverse direction broadcast to every lane: 8 lanes with AVX, 4 without.
#if defined(__AVX__)
using SlabLanes = __m256;
inline SlabLanes broadcastLanes(float x) { return _mm256_set1_ps(x); }
inline __m128 lowLanes(SlabLanes v) { return _mm256_castps256_ps128(v); }
#else
using SlabLanes = __m128;
inline SlabLanes broadcastLanes(float x) { return _mm_set1_ps(x); }
inline __m128 lowLanes(SlabLanes v) { return v; }
#endif

struct NodeRay {
    SlabLanes o[3], inv[3];
    int nearRow[3];  // bounds row of each axis's near plane: lo (2a) or hi (2a + 1)

    NodeRay(const glm::vec3& origin, const glm::vec3& dir) {
        for (int a = 0; a < 3; ++a) {
            // -0 counts as positive, as in the box test and the GLSL kernel (RENDERING.md §3).
            const float d = std::abs(dir[a]) < 0x1p-100f ? (dir[a] < 0.0f ? -0x1p-100f : 0x1p-100f) : dir[a];
            o[a] = broadcastLanes(origin[a]);
            inv[a] = broadcastLanes(1.0f / d);
            nearRow[a] = 2 * a + (d < 0.0f ? 1 : 0);
        }
    }
};

// Rounding in the slab test can shrink the interval by a few ulps and miss a primitive that
// touches its box's boundary; widening tFar by 1 + 2*gamma(3) makes the test conservative
// (Ize 2013, "Robust BVH Ray Traversal", JCGT 2(2)).
inline constexpr float kSlabFarScale = 1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f);

// Mask of the children whose box the ray enters within [0, tmax] (bit k: child k); tEntry gets
// the entry distances. Two SSE halves: the test of a build without AVX.
inline int slabsSse(const WideNode& node, const NodeRay& r, float tmax, float tEntry[kWideWidth]) {
    int mask = 0;
    for (int half = 0; half < kWideWidth; half += 4) {
        __m128 tn = _mm_setzero_ps(), tf = _mm_set1_ps(tmax);
        for (int a = 0; a < 3; ++a) {
            const __m128 o = lowLanes(r.o[a]), inv = lowLanes(r.inv[a]);
            const __m128 n = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(node.bounds[r.nearRow[a]] + half), o), inv);
            const __m128 f = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(node.bounds[r.nearRow[a] ^ 1] + half), o), inv);
            tn = _mm_max_ps(tn, n);
            tf = _mm_min_ps(tf, f);
        }
        _mm_store_ps(tEntry + half, tn);
        mask |= _mm_movemask_ps(_mm_cmple_ps(tn, _mm_mul_ps(tf, _mm_set1_ps(kSlabFarScale)))) << half;
    }
    return mask;
}

// The same in one AVX instruction per step where the build has AVX (the default x86-64-v3),
// else slabsSse.
inline int slabs(const WideNode& node, const NodeRay& r, float tmax, float tEntry[kWideWidth]) {
#if defined(__AVX__)
    __m256 tn = _mm256_setzero_ps(), tf = _mm256_set1_ps(tmax);
    for (int a = 0; a < 3; ++a) {
        const __m256 n = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(node.bounds[r.nearRow[a]]), r.o[a]), r.inv[a]);
        const __m256 f = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(node.bounds[r.nearRow[a] ^ 1]), r.o[a]), r.inv[a]);
        tn = _mm256_max_ps(tn, n);
        tf = _mm256_min_ps(tf, f);
    }
    _mm256_store_ps(tEntry, tn);
    // Ordered, non-signalling <=: the same mask as SSE's _mm_cmple_ps, NaN lanes included.
    return _mm256_movemask_ps(_mm256_cmp_ps(tn, _mm256_mul_ps(tf, _mm256_set1_ps(kSlabFarScale)), _CMP_LE_OQ));
#else
    return slabsSse(node, r, tmax, tEntry);
#endif
}

}  // namespace vkrt::bvh
