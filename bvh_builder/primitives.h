// A PrimitiveInput's bounds, its check, and its gpu::Primitive record (layout in device_host.h).
#pragma once

#include <cstddef>
#include <cstdint>

#include "aabb.h"
#include "bvh.h"

namespace vkrt::bvh {

Aabb boundsOf(const PrimitiveInput& p);

// Throws std::invalid_argument naming the group, the primitive and the bad value: an unknown kind,
// a non-finite coordinate, a negative radius, or a box whose min exceeds its max.
void validate(const PrimitiveInput& p, std::size_t group, std::size_t index);

// The reference of a triangle with finite corners, computed in SSE registers: the same bits as
// PrimRef::make(boundsOf(p), id) (min/max with boundsOf's operand order, which decides between +0
// and -0). Returns false, writing nothing, for anything else: those take validate() and boundsOf().
// It takes most of the reference pass's time away (commit 33fd124, docs/lab/2026-12-02-bvh-build.md).
inline bool triangleRef(const PrimitiveInput& p, std::uint32_t id, PrimRef& out) {
    static_assert(sizeof(PrimitiveInput) == 40 && offsetof(PrimitiveInput, a) == 4 && offsetof(PrimitiveInput, b) == 16 &&
                  offsetof(PrimitiveInput, c) == 28);
    if (p.kind != gpu::PRIM_KIND_TRIANGLE) return false;
    const auto* bytes = reinterpret_cast<const char*>(&p);
    const __m128 kindA = _mm_loadu_ps(reinterpret_cast<const float*>(bytes));       // kind, a.xyz
    const __m128 b = _mm_loadu_ps(reinterpret_cast<const float*>(bytes + 16));      // b.xyz, c.x
    const __m128 bzC = _mm_loadu_ps(reinterpret_cast<const float*>(bytes + 24));    // b.z, c.xyz
    const __m128 a = _mm_shuffle_ps(kindA, kindA, _MM_SHUFFLE(0, 3, 2, 1));         // a.xyz, -
    const __m128 c = _mm_shuffle_ps(bzC, bzC, _MM_SHUFFLE(0, 3, 2, 1));             // c.xyz, -
    // Finite: x * 0 is 0 (NaN for an infinity or a NaN); lanes 0-2 of each corner.
    const __m128 zero = _mm_setzero_ps();
    const int finite = _mm_movemask_ps(_mm_cmpeq_ps(_mm_mul_ps(a, zero), zero)) &
                       _mm_movemask_ps(_mm_cmpeq_ps(_mm_mul_ps(b, zero), zero)) &
                       _mm_movemask_ps(_mm_cmpeq_ps(_mm_mul_ps(c, zero), zero));
    if ((finite & 7) != 7) return false;
    // Aabb::grow from the empty box: lo = (p < lo) ? p : lo, which _mm_min_ps(p, lo) is.
    const __m128 lo = _mm_min_ps(c, _mm_min_ps(b, a));
    const __m128 hi = _mm_max_ps(c, _mm_max_ps(b, a));
    const __m128 idLane = _mm_castsi128_ps(_mm_setr_epi32(0, 0, 0, static_cast<int>(id)));
    const __m128 keep = _mm_castsi128_ps(_mm_setr_epi32(-1, -1, -1, 0));
    out.lo = _mm_or_ps(_mm_and_ps(lo, keep), idLane);
    out.hi = _mm_and_ps(hi, keep);
    return true;
}

gpu::Primitive encode(const PrimitiveInput& p);
// The inverse of encode (the traversal and the tests read primitives back through it).
PrimitiveInput decode(const gpu::Primitive& p);

}  // namespace vkrt::bvh
