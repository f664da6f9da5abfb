// The one place that defines vkrt's random numbers and sample patterns, for the CPU reference and
// the GLSL kernels alike (this file is valid C++ and valid GLSL).
//
// Every random number is a pure function of (pixel, sample index, dimension, seed): a
// counter-based hash (pcg4d, Jarzynski & Olano 2020, "Hash Functions for GPU Rendering"), so there
// is no per-thread state and an image does not depend on thread count, tile order or device.
// Integer results are identical on every device; conversion to float is exact (24-bit mantissa).
// The stratum arithmetic multiplies by a host-computed reciprocal instead of dividing, because
// Vulkan only requires 2.5 ULP for division but correct rounding for add and multiply.
//
// Dimensions (what a 2D sample is used for) are numbered by dimCamera/dimGloss/dimLight below:
// every bounce depth and every area light gets its own decorrelated stream.
#ifndef VKRT_SAMPLING_H
#define VKRT_SAMPLING_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
#include "device_host.h"
namespace vkrt::gpu {
#define VKRT_FN inline
using glm::min;
using uvec2 = glm::uvec2;
#else
#define VKRT_FN
#endif

// pcg4d: four 32-bit outputs from four 32-bit inputs, all lanes mixed into each other.
VKRT_FN uvec4 pcg4d(uvec4 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * v.w;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v.w += v.y * v.z;
    v = v ^ (v >> 16u);
    v.x += v.y * v.w;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v.w += v.y * v.z;
    return v;
}

// Uniform float in [0, 1 - 2^-24], exactly representable, identical on every device.
VKRT_FN float unitFloat(uint x) {
    return float(x >> 8u) * (1.0f / 16777216.0f);
}

// Largest float below 1, to keep stratified coordinates inside [0, 1).
VKRT_CONST float ONE_MINUS_EPSILON = 0.99999994f;

// Sample dimensions. Depth is the recursion depth of the hit being shaded (0 = primary hit).
VKRT_CONST uint DIM_CAMERA = 0u;
VKRT_FN uint dimGloss(uint depth) { return ((depth + 1u) << 16u) | 0u; }
VKRT_FN uint dimLight(uint depth, uint areaLightOrdinal) { return ((depth + 1u) << 16u) | (1u + areaLightOrdinal); }

// A pseudo-random permutation of [0, n): a bijection on the enclosing power of two, built from
// steps that are each invertible modulo 2^k (xor with a key, multiply by an odd constant,
// xorshift right, add a key), walked until it lands inside [0, n) (cycle walking keeps it a
// bijection; fewer than two rounds are expected because 2^k < 2n).
VKRT_FN uint permuteIndex(uint i, uint n, uint key) {
    if (n <= 1u) return 0u;
    uint mask = n - 1u;
    mask |= mask >> 1u;
    mask |= mask >> 2u;
    mask |= mask >> 4u;
    mask |= mask >> 8u;
    mask |= mask >> 16u;
    do {
        i = (i ^ key) & mask;
        i = (i * 0x9e3779b1u) & mask;
        i ^= i >> 3u;
        i = (i + (key >> 11u)) & mask;
        i = (i * 0x85ebca77u) & mask;
        i ^= i >> 7u;
        i = (i ^ (key >> 19u)) & mask;
        i = (i * 0xc2b2ae3du) & mask;
        i ^= i >> 5u;
    } while (i >= n);
    return i;
}

// A sample grid: count strata arranged gridX wide and count/gridX tall (gridX is the largest
// divisor of count not above sqrt(count), so a square count gives the lecture's n x n grid).
// Packed as uvec4(count, gridX, floatBits(1/gridX), floatBits(1/gridY)); built on the host by
// makeSampleGrid (C++ only, below).
VKRT_FN vec2 gridPoint(uvec4 grid, uint stratum, vec2 offset) {
    uint gx = stratum % grid.y;
    uint gy = stratum / grid.y;
#ifdef __cplusplus
    float invX = glm::uintBitsToFloat(grid.z);
    float invY = glm::uintBitsToFloat(grid.w);
#else
    float invX = uintBitsToFloat(grid.z);
    float invY = uintBitsToFloat(grid.w);
#endif
    return vec2(min((float(gx) + offset.x) * invX, ONE_MINUS_EPSILON),
                min((float(gy) + offset.y) * invY, ONE_MINUS_EPSILON));
}

// The 2D sample number `index` of a pixel's `grid.x` samples in dimension `dim`.
//  random:   independent uniform points.
//  regular:  stratum centres.
//  jittered: one uniform point per stratum (Cook 1984; the lecture's n x n jitter).
// Camera samples take stratum = index; every other dimension shuffles the strata per pixel and
// dimension, so light and gloss strata are paired with pixel strata at random (Cook's shuffle).
VKRT_FN vec2 sample2D(uint samplerKind, uvec4 grid, uint pixel, uint index, uint dim, uint seed) {
    uvec4 r = pcg4d(uvec4(pixel, index, dim, seed));
    vec2 jitter = vec2(unitFloat(r.x), unitFloat(r.y));
    if (samplerKind == SAMPLER_RANDOM) return jitter;
    uint stratum = index;
    if (dim != DIM_CAMERA) stratum = permuteIndex(index, grid.x, pcg4d(uvec4(pixel, 0xffffffffu, dim, seed)).x);
    if (samplerKind == SAMPLER_REGULAR) jitter = vec2(0.5f, 0.5f);
    return gridPoint(grid, stratum, jitter);
}

#ifdef __cplusplus
// Host side: the grid for `count` strata (count >= 1).
inline uvec4 makeSampleGrid(uint count) {
    uint gx = 1;
    for (uint d = 1; d * d <= count; ++d)
        if (count % d == 0) gx = d;
    uint gy = count / gx;
    return uvec4(count, gx, glm::floatBitsToUint(1.0f / float(gx)), glm::floatBitsToUint(1.0f / float(gy)));
}
#undef VKRT_FN
}  // namespace vkrt::gpu
#endif

#endif  // VKRT_SAMPLING_H
