// Axis-aligned bounding boxes for the builder, in two forms:
//  - Aabb: glm vec3 pair, for code that reads like maths (top level, flattening, tests);
//  - Box4: the same box in two SSE registers, for the builder's hot loops (binning, partitioning),
//    where a primitive reference is 32 bytes and one min/max instruction grows all three axes.
// The empty box is lo = +FLT_MAX, hi = -FLT_MAX (the convention of shaders/shared/device_host.h):
// growing it by any box gives that box, and a slab test against it never succeeds.
#pragma once

#include <immintrin.h>

#include <bit>
#include <cfloat>
#include <cstdint>

#include <glm/glm.hpp>

namespace vkrt::bvh {

struct Aabb {
    glm::vec3 lo{FLT_MAX};
    glm::vec3 hi{-FLT_MAX};

    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    void grow(const glm::vec3& p) { lo = glm::min(lo, p); hi = glm::max(hi, p); }
    void grow(const Aabb& b) { lo = glm::min(lo, b.lo); hi = glm::max(hi, b.hi); }
    bool contains(const Aabb& b) const {
        return glm::all(glm::lessThanEqual(lo, b.lo)) && glm::all(glm::greaterThanEqual(hi, b.hi));
    }
    // Half the surface area: the SAH only ever compares ratios of areas.
    float halfArea() const {
        if (empty()) return 0.0f;
        const glm::vec3 e = hi - lo;
        return e.x * e.y + e.y * e.z + e.z * e.x;
    }
};

// Box in SSE registers; lane 3 is carried along but never read.
struct Box4 {
    __m128 lo = _mm_set1_ps(FLT_MAX);
    __m128 hi = _mm_set1_ps(-FLT_MAX);

    void grow(__m128 l, __m128 h) { lo = _mm_min_ps(lo, l); hi = _mm_max_ps(hi, h); }
    void grow(const Box4& b) { grow(b.lo, b.hi); }
    void growPoint(__m128 p) { grow(p, p); }
    float halfArea() const {
        alignas(16) float e[4];
        _mm_store_ps(e, _mm_max_ps(_mm_sub_ps(hi, lo), _mm_setzero_ps()));
        return e[0] * e[1] + e[1] * e[2] + e[2] * e[0];
    }
    Aabb toAabb() const {
        alignas(16) float l[4], h[4];
        _mm_store_ps(l, lo);
        _mm_store_ps(h, hi);
        return {{l[0], l[1], l[2]}, {h[0], h[1], h[2]}};
    }
};

// A primitive as the builder sees it: its box, and in lane 3 of lo the index it came from.
// 32 bytes, moved (not indexed) during partitioning so every pass streams through memory.
struct alignas(32) PrimRef {
    __m128 lo;
    __m128 hi;

    static PrimRef make(const Aabb& b, std::uint32_t id) {
        PrimRef r;
        r.lo = _mm_setr_ps(b.lo.x, b.lo.y, b.lo.z, std::bit_cast<float>(id));
        r.hi = _mm_setr_ps(b.hi.x, b.hi.y, b.hi.z, 0.0f);
        return r;
    }
    std::uint32_t id() const {
        return static_cast<std::uint32_t>(_mm_cvtsi128_si32(_mm_shuffle_epi32(_mm_castps_si128(lo), 3)));
    }
    // Twice the centroid: binning only needs it up to a constant factor.
    __m128 centroid2() const { return _mm_add_ps(lo, hi); }
};

}  // namespace vkrt::bvh
