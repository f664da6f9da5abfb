// Importance sampling of the environment map by luminance, for the CPU reference and the GLSL
// kernels alike (this file is valid C++ and valid GLSL): one definition of the sample and of its
// density, so a direction one device samples has the pdf the other computes for it (docs/RENDERING.md
// §10). The tables are built on the host (host/lighting/environment_sampling.h); this file only
// reads them.
//
// The distribution is piecewise constant over a grid of C x C cells on each cube face (cells in
// the face's (s, t), as cube_map.h defines them): a row of cells is picked from a marginal CDF over
// the 6 C rows (row R = face * C + cell row, rows from the top), then a cell of that row from the
// row's conditional CDF, then a point uniformly in the cell's (s, t). The density per steradian is
// the cell's probability * C^2 (uniform in (s, t)) divided by cubeFaceSolidAngleDensity.
//
// The table is one array of floats, read through VKRT_ENV_CDF(i):
//   [0, 6C]                       the marginal CDF: entry R is the probability of rows < R
//                                 (entry 0 is 0, entry 6C is 1)
//   envRowCdf(C, R) + [0, C]      row R's conditional CDF over its C cells, the same way
// ENV_TABLE_SIZE(C) floats in all. Every cell has a probability > 0 (the host floors the weights),
// so every CDF is strictly increasing.
//
// Reading the table:
//   GLSL: define VKRT_ENV_CDF(i) (a float from the kernel's binding) before including this file.
//   C++: the functions take the table as a first argument (const float* envTable), and
//        VKRT_ENV_CDF(i) reads envTable[i]; host/lighting/environment_sampling.h wraps them.
#ifndef VKRT_ENVIRONMENT_SAMPLING_H
#define VKRT_ENVIRONMENT_SAMPLING_H

#include "cube_map.h"

#ifdef __cplusplus
namespace vkrt::envsampling {
using glm::clamp;
using glm::min;
using glm::normalize;
using gpu::uint;
using gpu::vec2;
using gpu::vec3;
using gpu::vec4;
using namespace vkrt::cubemap;
#define VKRT_ENV_TABLE_PARAM const float *envTable,
#define VKRT_ENV_TABLE_ARG envTable,
#define VKRT_ENV_CDF(i) envTable[i]
#ifndef VKRT_LOOP_CHARGE
#define VKRT_LOOP_CHARGE() ((void)0)  // the CPU has no loop limiter (sampling.h)
#endif
#else
#ifndef VKRT_ENV_CDF
#error "define VKRT_ENV_CDF(i) (the environment's CDF table, a float) before including environment_sampling.h"
#endif
#ifndef VKRT_LOOP_CHARGE
#error "include budget.glsl (or define VKRT_LOOP_CHARGE) before environment_sampling.h"
#endif
#define VKRT_ENV_TABLE_PARAM
#define VKRT_ENV_TABLE_ARG
#endif

// Where row R's conditional CDF starts, and the table's size, for C cells per face side.
VKRT_FN uint envRowCdf(uint cells, uint row) { return 6u * cells + 1u + row * (cells + 1u); }
VKRT_FN uint envTableSize(uint cells) { return envRowCdf(cells, 6u * cells); }

// Largest float below 1: a remapped sample stays inside its cell.
VKRT_CONST float ENV_ONE_MINUS_EPSILON = 0.99999994f;

// The interval of the CDF at table[first .. first + n] that holds u: the largest i in [0, n) with
// CDF(first + i) <= u, for u in [0, 1). A binary search in a bounded loop: log2(6 * 64) < 9
// steps for the largest grid, far under the 65,535 iterations after which a GPU driver may cut a
// loop; 32 steps cover any n a uint can hold.
VKRT_FN uint envFindInterval(VKRT_ENV_TABLE_PARAM uint first, uint n, float u) {
    uint lo = 0u;
    uint hi = n;
    for (uint step = 0u; step < 32u && hi - lo > 1u; ++step) {
        VKRT_LOOP_CHARGE();  // the kernel's loop budget counts every loop's passes (budget.glsl)
        uint mid = (lo + hi) >> 1u;
        if (VKRT_ENV_CDF(first + mid) <= u) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    return lo;
}

// A direction drawn with the environment's luminance-weighted density from a uniform 2D sample
// u in [0, 1)^2: xyz the unit direction, w its pdf per steradian (> 0). u.y picks the row, u.x the
// cell within it, and what each leaves of its interval places the point inside the cell, so a
// stratified u stays stratified over the sphere.
VKRT_FN vec4 sampleEnvironment(VKRT_ENV_TABLE_PARAM uint cells, vec2 u) {
    uint row = envFindInterval(VKRT_ENV_TABLE_ARG 0u, 6u * cells, u.y);
    float row0 = VKRT_ENV_CDF(row);
    float pRow = VKRT_ENV_CDF(row + 1u) - row0;
    uint rowCdf = envRowCdf(cells, row);
    uint col = envFindInterval(VKRT_ENV_TABLE_ARG rowCdf, cells, u.x);
    float col0 = VKRT_ENV_CDF(rowCdf + col);
    float pCol = VKRT_ENV_CDF(rowCdf + col + 1u) - col0;
    vec2 inCell = clamp(vec2((u.x - col0) / pCol, (u.y - row0) / pRow), vec2(0.0f), vec2(ENV_ONE_MINUS_EPSILON));
    uint face = row / cells;
    vec2 st = (vec2(float(col), float(row - face * cells)) + inCell) / float(cells);
    float pdf = pRow * pCol * float(cells * cells) / cubeFaceSolidAngleDensity(st);
    vec3 d = normalize(cubeFaceDirection(face, st));
    return vec4(d.x, d.y, d.z, pdf);
}

// The pdf per steradian with which sampleEnvironment draws direction d (any length but zero).
// Equal to the pdf sampleEnvironment returned with d, up to rounding, except for a direction
// within float rounding of a cell's edge, which this may put in the neighbouring cell.
VKRT_FN float environmentPdf(VKRT_ENV_TABLE_PARAM uint cells, vec3 d) {
    CubeFacePoint p = cubeFacePoint(d);
    float n = float(cells);
    uint col = min(uint(p.st.x * n), cells - 1u);
    uint row = p.face * cells + min(uint(p.st.y * n), cells - 1u);
    float pRow = VKRT_ENV_CDF(row + 1u) - VKRT_ENV_CDF(row);
    uint rowCdf = envRowCdf(cells, row);
    float pCol = VKRT_ENV_CDF(rowCdf + col + 1u) - VKRT_ENV_CDF(rowCdf + col);
    return pRow * pCol * float(cells * cells) / cubeFaceSolidAngleDensity(p.st);
}

#undef VKRT_ENV_TABLE_PARAM
#undef VKRT_ENV_TABLE_ARG
#ifdef __cplusplus
#undef VKRT_ENV_CDF
}  // namespace vkrt::envsampling
#endif

#endif  // VKRT_ENVIRONMENT_SAMPLING_H
