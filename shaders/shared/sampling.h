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
// C++: the CPU reference and the GPU renderer's host side both call these, so they live in a
// namespace of their own, with the GLSL names they use.
namespace vkrt::sampling {
using glm::abs;
using glm::cos;
using glm::min;
using glm::sin;
using glm::uintBitsToFloat;
using gpu::uint;
using gpu::uvec4;
using gpu::vec2;
using gpu::SAMPLER_RANDOM;
using gpu::SAMPLER_REGULAR;
using gpu::SAMPLER_SOBOL;
using gpu::SAMPLER_SOBOL2;
#endif

// How a loop reports that a driver's loop limiter ended it early: the GLSL kernels define it
// (shaders/budget.glsl, included first); the CPU has no limiter.
#ifndef VKRT_LOOP_CUT_OFF
#ifdef __cplusplus
#define VKRT_LOOP_CHARGE() ((void)0)
#define VKRT_LOOP_CUT_OFF() ((void)0)
#else
#error "include budget.glsl (or define VKRT_LOOP_CUT_OFF) before sampling.h"
#endif
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
VKRT_CONST uint DIM_LENS = 1u;  // the thin lens (depth 0's free slot: gloss and lights start at 1 << 16)
VKRT_CONST uint DIM_TIME = 2u;  // the camera sample's time in the shutter (motion blur; its x only)
VKRT_FN uint dimGloss(uint depth) { return ((depth + 1u) << 16u) | 0u; }
VKRT_FN uint dimLight(uint depth, uint areaLightOrdinal) { return ((depth + 1u) << 16u) | (1u + areaLightOrdinal); }
// Glossy translucency at a dielectric hit of this depth (the slot after every light ordinal).
VKRT_FN uint dimTranslucency(uint depth) { return ((depth + 1u) << 16u) | 0xffffu; }
// The Diffuse bounce's direction at a hit of this depth, and the environment map's light samples
// there (shape emitters take light ordinals after the area lights: dimLight).
VKRT_FN uint dimBounce(uint depth) { return ((depth + 1u) << 16u) | 0xfffeu; }
VKRT_FN uint dimEnvironment(uint depth) { return ((depth + 1u) << 16u) | 0xfffdu; }
// Russian roulette of the Diffuse bounce leaving a hit of this depth, or the branch a dielectric
// hit of this depth continues in a path-traced scene (its x only: a hit is one or the other), and
// the choice of the shape emitter each light sample there goes to (its x only; docs/RENDERING.md §2).
VKRT_FN uint dimRoulette(uint depth) { return ((depth + 1u) << 16u) | 0xfffcu; }
VKRT_FN uint dimEmitterChoice(uint depth) { return ((depth + 1u) << 16u) | 0xfffbu; }
// Light ordinals 0 .. MAX_LIGHT_ORDINALS - 1 (area lights, then shape emitters) have their own
// dimensions; more would alias the fixed ones above (emitter_table.cpp refuses such a scene).
VKRT_CONST uint MAX_LIGHT_ORDINALS = 0xfffau;

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
    if (i >= n) VKRT_LOOP_CUT_OFF();  // only a driver's loop limiter can end the walk outside [0, n)
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

// ---------------------------------------------------------------------------------------------
// Owen-scrambled Sobol (Burley 2020, "Practical Hash-based Owen Scrambling"), 2D: the first two
// Sobol dimensions, each Owen-scrambled (nested uniform scrambling) by a hash keyed per
// (pixel, dimension, seed), and the sample index itself Owen-scrambled per (pixel, dimension),
// which shuffles the order of the points: every dimension draws its points from its own aligned
// block of the sequence in its own order, so dimensions are decorrelated while each dimension's
// first 2^m points of a pixel still form a (0, m, 2)-net (one point in every elementary interval).
// docs/SAMPLING.md describes it and how its hash was checked.
//
// Integer operations only (no loop), then the exact float conversion of unitFloat.

// The 32 bits of x in reverse order. GLSL has it built in (one instruction on GPUs: AMD's
// v_bfrev_b32, NVIDIA's BREV); in C++ swap halves, then quarters, ... , then neighbouring bits
// (compilers turn the first two steps into one bswap).
#ifdef __cplusplus
VKRT_FN uint reverseBits32(uint x) {
    x = (x >> 16u) | (x << 16u);
    x = ((x >> 8u) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8u);
    x = ((x >> 4u) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4u);
    x = ((x >> 2u) & 0x33333333u) | ((x & 0x33333333u) << 2u);
    x = ((x >> 1u) & 0x55555555u) | ((x & 0x55555555u) << 1u);
    return x;
}
#else
VKRT_FN uint reverseBits32(uint x) { return bitfieldReverse(x); }
#endif

// Sobol dimension 1 of the point number `index`, with its digits in reversed order (bit r is the
// digit of weight 2^-(r+1)). Its generator matrix is Pascal's triangle mod 2: digit r is the xor
// of the index bits c with binomial(c, r) odd, i.e. (Lucas) the bits c whose positions contain
// r's bits. That "xor over supersets" is five butterfly steps over the bit positions.
// (Dimension 0 is the van der Corput sequence: in reversed order it is the index itself.)
VKRT_FN uint sobolDim1Reversed(uint index) {
    uint x = index;
    x ^= (x >> 1u) & 0x55555555u;
    x ^= (x >> 2u) & 0x33333333u;
    x ^= (x >> 4u) & 0x0f0f0f0fu;
    x ^= (x >> 8u) & 0x00ff00ffu;
    x ^= (x >> 16u) & 0x0000ffffu;
    return x;
}

// Nested uniform (Owen) scrambling of a value in [0,1) given as 32 digits in reversed order
// (bit 0 = the first binary digit). Owen scrambling flips each digit by a random bit chosen per
// prefix of the digits before it; here each step changes bit k by a function of the bits below
// it and of the key only (adding, multiplying by an odd number, xoring with a multiple by an even
// number all carry information upwards only), so it is such a flip. The steps and constants are
// ours (fractional bits of sqrt(2), sqrt(3), sqrt(5), sqrt(7), made even), chosen by measuring the
// flips' independence (docs/SAMPLING.md); the key enters additively and multiplicatively.
VKRT_FN uint owenScrambleReversed(uint x, uint key) {
    x ^= x * 0x6a09e666u;
    x += key;
    x *= (key >> 15u) | 1u;
    x ^= x * 0xbb67ae84u;
    x += key >> 7u;
    x ^= x * 0x3c6ef372u;
    x *= ((key >> 3u) * 2u) | 1u;
    x ^= x * 0xa54ff53au;
    return x;
}

// The Owen-scrambled, shuffled Sobol point number `index` of a pixel in dimension `dim`.
VKRT_FN vec2 sobolSample2D(uint pixel, uint index, uint dim, uint seed) {
    // Three keys per (pixel, dimension, seed): the shuffle and one scramble per coordinate.
    uvec4 keys = pcg4d(uvec4(pixel, 0xfffffffeu, dim, seed));
    // Owen-scrambling the index (most significant bit first) keeps its high bits constant for
    // indices below 2^m and permutes the low m bits, so the first 2^m shuffled indices are one
    // aligned block of 2^m Sobol points (a (0, m, 2)-net) in a per-pixel, per-dimension order.
    uint shuffled = reverseBits32(owenScrambleReversed(reverseBits32(index), keys.x));
    uint x = owenScrambleReversed(shuffled, keys.y);
    uint y = owenScrambleReversed(sobolDim1Reversed(shuffled), keys.z);
    return vec2(unitFloat(reverseBits32(x)), unitFloat(reverseBits32(y)));
}

// sobol2: pixel sample s is sample s / 2 of one of two Sobol renders whose scrambles are keyed by
// two different seeds (s % 2 picks which). The even and the odd samples are then two independent
// randomised-QMC estimates of the pixel, each a (0, m, 2)-net at a power of two, and half their
// difference is an unbiased estimate of the error of their mean (docs/SAMPLING.md §7); the first
// N samples of a pixel are the same in every render of N or more. Callers turn the pixel sample
// into the index and seed every dimension of that sample is drawn with; other samplers keep both.
VKRT_CONST uint SOBOL2_REPLICA_KEY = 0x9e3779b9u;
VKRT_FN uint sampleSeed(uint samplerKind, uint seed, uint pixelSample) {
    return samplerKind == SAMPLER_SOBOL2 ? seed ^ ((pixelSample & 1u) * SOBOL2_REPLICA_KEY) : seed;
}
VKRT_FN uint sampleIndex(uint samplerKind, uint pixelSample) {
    return samplerKind == SAMPLER_SOBOL2 ? pixelSample >> 1u : pixelSample;
}

// The 2D sample number `index` of a pixel's `grid.x` samples in dimension `dim`.
//  random:   independent uniform points.
//  regular:  stratum centres.
//  jittered: one uniform point per stratum (Cook 1984; the lecture's n x n jitter).
// Camera samples take stratum = index; every other dimension shuffles the strata per pixel and
// dimension, so light and gloss strata are paired with pixel strata at random (Cook's shuffle).
//  sobol:    Owen-scrambled Sobol points, shuffled per pixel and dimension (sobolSample2D; the
//            grid is not used: any count works, powers of two stratify best). sobol2 the same, with
//            index and seed from sampleIndex and sampleSeed.
VKRT_FN vec2 sample2D(uint samplerKind, uvec4 grid, uint pixel, uint index, uint dim, uint seed) {
    if (samplerKind == SAMPLER_SOBOL || samplerKind == SAMPLER_SOBOL2) return sobolSample2D(pixel, index, dim, seed);
    uvec4 r = pcg4d(uvec4(pixel, index, dim, seed));
    vec2 jitter = vec2(unitFloat(r.x), unitFloat(r.y));
    if (samplerKind == SAMPLER_RANDOM) return jitter;
    uint stratum = index;
    if (dim != DIM_CAMERA) stratum = permuteIndex(index, grid.x, pcg4d(uvec4(pixel, 0xffffffffu, dim, seed)).x);
    if (samplerKind == SAMPLER_REGULAR) jitter = vec2(0.5f, 0.5f);
    return gridPoint(grid, stratum, jitter);
}

// The 1D sample number `index` of a pixel's `grid.x` samples in dimension `dim` (a shutter time):
// stratified in 1D over all grid.x strata (not over a grid's columns), the strata shuffled per
// pixel and dimension as sample2D's. Sobol's first coordinate is already 1D-stratified (van der
// Corput). 1 / count is the product of the grid's two host reciprocals: correctly rounded
// multiplies, the same float on every device.
VKRT_FN float sample1D(uint samplerKind, uvec4 grid, uint pixel, uint index, uint dim, uint seed) {
    if (samplerKind == SAMPLER_SOBOL || samplerKind == SAMPLER_SOBOL2) return sobolSample2D(pixel, index, dim, seed).x;
    uvec4 r = pcg4d(uvec4(pixel, index, dim, seed));
    float jitter = unitFloat(r.x);
    if (samplerKind == SAMPLER_RANDOM) return jitter;
    uint stratum = permuteIndex(index, grid.x, pcg4d(uvec4(pixel, 0xffffffffu, dim, seed)).x);
    if (samplerKind == SAMPLER_REGULAR) jitter = 0.5f;
    float inverseCount = uintBitsToFloat(grid.z) * uintBitsToFloat(grid.w);
    return min((float(stratum) + jitter) * inverseCount, ONE_MINUS_EPSILON);
}

// Shirley & Chiu's concentric map of [0,1)^2 onto the unit disc ("A Low Distortion Map Between
// Disk and Square", 1997): square rings go to circles, so the strata of a stratified lens sample
// stay compact and of equal area on the lens.
VKRT_FN vec2 concentricDisk(vec2 s) {
    float ox = 2.0f * s.x - 1.0f;
    float oy = 2.0f * s.y - 1.0f;
    if (ox == 0.0f && oy == 0.0f) return vec2(0.0f, 0.0f);
    float r;
    float theta;
    if (abs(ox) > abs(oy)) {
        r = ox;
        theta = 0.785398163f * (oy / ox);
    } else {
        r = oy;
        theta = 1.570796327f - 0.785398163f * (ox / oy);
    }
    return vec2(r * cos(theta), r * sin(theta));
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
}  // namespace vkrt::sampling
#endif

#endif  // VKRT_SAMPLING_H
