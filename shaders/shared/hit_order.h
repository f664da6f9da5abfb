// Which of two closest-hit candidates a ray reports, for the CPU reference and the GLSL kernels
// alike (valid C++ and valid GLSL): one rule, so that coincident surfaces (two instances whose
// faces coincide, a scaled instance's face on a loose shape's) show the same surface on both
// devices. Their distances differ by rounding only, and the devices round differently (the CPU
// moves a ray into an instance in double, a GPU may fuse multiply-adds), so "the smaller t" alone
// picks by chance, pixel by pixel, and differently on each device (issue 38, item 8).
//
// The rule: distances are compared in buckets of 256 units in the last place (t's float bits
// with the low HIT_BUCKET_BITS = 8 cleared: 2^-15 = 3.1e-5 of the distance at most); within one
// bucket the lower (instance, primitive) wins, both indices being the same on both devices (one
// build gives both their arrays, bvh.h). Surfaces farther apart than 2^-15 of their distance are
// ordered by distance as before (a sheet 1 mm in front of a wall, seen from 10 m, is seen).
// Devices still differ where the two distances straddle a bucket's edge: about Delta t / 256 ulps
// of the coincident pixels (measured: 0.11% of a view filled with coincident faces, against 2-5%
// by distance alone; 64-ulp buckets left 0.48%, 1024-ulp 0.03%).
// docs/STABILITY.md ("Coincident faces") gives the measured agreement.
#ifndef VKRT_HIT_ORDER_H
#define VKRT_HIT_ORDER_H

#ifdef __cplusplus
#include <glm/glm.hpp>
#include "device_host.h"
namespace vkrt::gpu {
using glm::floatBitsToUint;
using glm::uintBitsToFloat;
#endif

VKRT_CONST uint HIT_BUCKET_BITS = 8u;
VKRT_CONST uint HIT_BUCKET_MASK = (1u << HIT_BUCKET_BITS) - 1u;

// The first distance past t's bucket (t > 0): a candidate below it may still win on its indices,
// so traversal culls at it rather than at t (+inf past the largest float's bucket).
VKRT_FN float hitBucketLimit(float t) { return uintBitsToFloat((floatBitsToUint(t) | HIT_BUCKET_MASK) + 1u); }

// Whether a candidate at t (0 < t < hitBucketLimit(bestT)) of (instance, prim) replaces the best so far.
VKRT_FN bool hitWins(float t, uint instance, uint prim, float bestT, uint bestInstance, uint bestPrim) {
    uint bucket = floatBitsToUint(t) >> HIT_BUCKET_BITS;
    uint bestBucket = floatBitsToUint(bestT) >> HIT_BUCKET_BITS;
    if (bucket != bestBucket) return bucket < bestBucket;
    return instance < bestInstance || (instance == bestInstance && prim < bestPrim);
}

#ifdef __cplusplus
}  // namespace vkrt::gpu
#endif

#endif
