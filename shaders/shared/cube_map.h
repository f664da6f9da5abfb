// Directions <-> points on the faces of a cube map, for the CPU reference and the GLSL kernels
// alike (this file is valid C++ and valid GLSL): one definition of the environment map's geometry
// (docs/RENDERING.md §10). Texel fetches are not here: each side reads its own texel storage
// (host/lighting/environment_map.h on the CPU) through the footprint cubeTexelFootprint gives.
//
// The convention is OpenGL's cube map (the RenderMan one): a direction d picks the face of its
// largest |component| (the major axis, ma), and the face's image coordinates are
//     s = (sc / |ma| + 1) / 2   (0 at the image's left column, 1 at its right)
//     t = (tc / |ma| + 1) / 2   (0 at its top row, 1 at its bottom)
// with, per face:
//     face  sc   tc   ma          face  sc   tc   ma
//      +X   -z   -y   x            +Y   +x   +z   y
//      -X   +z   -y   x            -Y   +x   -z   y
//      +Z   +x   -y   z            -Z   -x   -y   z
// (../shared/scenes/JSON_FORMAT.md §5.3: the course's 2018 reef faces are seamless under exactly
// this table.) Ties between equal |components| go to x, then y (a direction on the +X/+Y edge is
// on +X); a zero component counts as positive (-0 too), so every non-zero direction has exactly
// one face. The zero vector has none (the result is NaN).
#ifndef VKRT_CUBE_MAP_H
#define VKRT_CUBE_MAP_H

#ifdef __cplusplus
#include <glm/glm.hpp>
#include "device_host.h"
namespace vkrt::cubemap {
using glm::abs;
using glm::atan;
using glm::clamp;
using glm::floor;
using glm::min;
using glm::sqrt;
using gpu::uint;
using gpu::uvec3;
using gpu::vec2;
using gpu::vec3;
#endif

// Face indices: the order of the files <prefix>posX.png, negX, posY, negY, posZ, negZ.
VKRT_CONST uint CUBE_POS_X = 0u;
VKRT_CONST uint CUBE_NEG_X = 1u;
VKRT_CONST uint CUBE_POS_Y = 2u;
VKRT_CONST uint CUBE_NEG_Y = 3u;
VKRT_CONST uint CUBE_POS_Z = 4u;
VKRT_CONST uint CUBE_NEG_Z = 5u;
VKRT_CONST uint CUBE_FACES = 6u;

// A point on a face: which face, and where on its image (s right, t down, both in [0, 1]).
struct CubeFacePoint {
    uint face;
    vec2 st;
};

// The face a direction meets and where (d need not be unit length; it must not be zero).
// s and t are clamped to [0, 1]: Vulkan's division may err by 2.5 ulp, which could put
// sc / |ma| a hair outside [-1, 1].
VKRT_FN CubeFacePoint cubeFacePoint(vec3 d) {
    vec3 a = abs(d);
    float sc;
    float tc;
    float ma;
    CubeFacePoint p;
    if (a.x >= a.y && a.x >= a.z) {
        ma = a.x;
        tc = -d.y;
        if (d.x >= 0.0f) {
            p.face = CUBE_POS_X;
            sc = -d.z;
        } else {
            p.face = CUBE_NEG_X;
            sc = d.z;
        }
    } else if (a.y >= a.z) {
        ma = a.y;
        sc = d.x;
        if (d.y >= 0.0f) {
            p.face = CUBE_POS_Y;
            tc = d.z;
        } else {
            p.face = CUBE_NEG_Y;
            tc = -d.z;
        }
    } else {
        ma = a.z;
        tc = -d.y;
        if (d.z >= 0.0f) {
            p.face = CUBE_POS_Z;
            sc = d.x;
        } else {
            p.face = CUBE_NEG_Z;
            sc = -d.x;
        }
    }
    p.st = clamp(vec2(0.5f * (sc / ma + 1.0f), 0.5f * (tc / ma + 1.0f)), vec2(0.0f), vec2(1.0f));
    return p;
}

// The inverse: the point of the cube [-1, 1]^3 at (s, t) of a face, as a direction (not unit
// length; normalise it for a ray). Also defined for s or t outside [0, 1]: the face's plane goes
// on past its edge (host/lighting/environment_map.cpp fills the faces' borders that way).
VKRT_FN vec3 cubeFaceDirection(uint face, vec2 st) {
    float a = 2.0f * st.x - 1.0f;  // sc / |ma|
    float b = 2.0f * st.y - 1.0f;  // tc / |ma|
    if (face == CUBE_POS_X) return vec3(1.0f, -b, -a);
    if (face == CUBE_NEG_X) return vec3(-1.0f, -b, a);
    if (face == CUBE_POS_Y) return vec3(a, 1.0f, b);
    if (face == CUBE_NEG_Y) return vec3(a, -1.0f, -b);
    if (face == CUBE_POS_Z) return vec3(a, -b, 1.0f);
    return vec3(-a, -b, -1.0f);
}

// The solid angle per unit area of (s, t) at a face point: dw / (ds dt) = 4 / (1 + a^2 + b^2)^(3/2)
// with a = 2s - 1, b = 2t - 1 (the point (1, a, b) on the plane at distance 1 sees an area element
// da db at solid angle cos(theta) / r^2 = 1 / r^3, and da db = 4 ds dt). From 4 at the face's
// centre to 4 / 3^(3/2) = 0.77 at its corners; it integrates to 4 pi / 6 over each face.
// A density of directions per unit area of (s, t) divided by this is a density per steradian.
VKRT_FN float cubeFaceSolidAngleDensity(vec2 st) {
    float a = 2.0f * st.x - 1.0f;
    float b = 2.0f * st.y - 1.0f;
    float r2 = 1.0f + a * a + b * b;
    return 4.0f / (r2 * sqrt(r2));
}

// The exact solid angle of the rectangle [lo, hi] of a face's (s, t): the integral of
// cubeFaceSolidAngleDensity over it, from the closed form F(a, b) = atan(a b / sqrt(1 + a^2 + b^2))
// of the solid angle of [0, a] x [0, b] on the plane at distance 1 (differences of four corners).
VKRT_FN float cubeFaceRectSolidAngle(vec2 lo, vec2 hi) {
    float a0 = 2.0f * lo.x - 1.0f;
    float a1 = 2.0f * hi.x - 1.0f;
    float b0 = 2.0f * lo.y - 1.0f;
    float b1 = 2.0f * hi.y - 1.0f;
    return atan(a1 * b1 / sqrt(1.0f + a1 * a1 + b1 * b1)) - atan(a0 * b1 / sqrt(1.0f + a0 * a0 + b1 * b1)) -
           atan(a1 * b0 / sqrt(1.0f + a1 * a1 + b0 * b0)) + atan(a0 * b0 / sqrt(1.0f + a0 * a0 + b0 * b0));
}

// ---------------------------------------------------------------------------------------------
// Bordered faces (host/lighting/environment_map.h builds them): face f of an N x N map is stored
// as (N + 2) x (N + 2) texels, its own texels at x, y in [1, N] and a one-texel border around them
// holding the neighbouring faces' texels across each edge. A bilinear lookup then never leaves
// its face and is continuous across the cube's edges, with no wrapping logic in the kernel.
// Texel (x, y) of bordered face f is number f * (N + 2)^2 + y * (N + 2) + x of the table.

// The four texels a bilinear lookup at p reads on an N x N map: `first` is the top-left one's
// number; the others are first + 1, first + (N + 2), first + (N + 2) + 1. `weight` is how far p
// sits from the top-left texel's centre towards the right (x) and bottom (y) ones, in [0, 1].
// Texel x of a bordered face has its centre at s = (x - 0.5) / N (the border's at -0.5 / N and
// 1 + 0.5 / N), so s in [0, 1] stays between the centres of texels 0 and N + 1.
struct CubeTexelFootprint {
    uint first;
    vec2 weight;
};

VKRT_FN CubeTexelFootprint cubeTexelFootprint(CubeFacePoint p, uint faceSize) {
    float n = float(faceSize);
    vec2 x = p.st * n + vec2(0.5f);
    vec2 cell = min(floor(x), vec2(n));  // s = 1 exactly: texels N and N + 1, weight 1
    uint row = faceSize + 2u;
    CubeTexelFootprint f;
    f.first = p.face * row * row + uint(cell.y) * row + uint(cell.x);
    f.weight = x - cell;
    return f;
}

// Where border texel (x, y) of bordered face `face` copies from: the face across the edge and the
// texel there (0-based x, y in [0, N) of that face's own N x N image). x or y is 0 or N + 1 (not
// both: a corner is the mean of the three texels that meet at the cube's corner, its own face's and
// the two border texels beside it). The source is the texel the point a quarter texel past the edge
// falls in, at the border texel's place along the edge: that is the neighbour's texel on the edge
// at the same place (texel rows meet edge to edge, and the grids agree along a shared edge). The
// border texel's own centre, half a texel past the edge, would project onto the neighbour up to
// half a texel off along the edge near the corners (the plane's 1 / (1 + 1/N) foreshortening),
// where the nearest texel is a tie; a quarter texel keeps it a quarter texel from any tie.
VKRT_FN uvec3 cubeBorderSource(uint face, int x, int y, uint faceSize) {
    float n = float(faceSize);
    float beyond = 0.25f / n;
    float s = x == 0 ? -beyond : x == int(faceSize) + 1 ? 1.0f + beyond : (float(x) - 0.5f) / n;
    float t = y == 0 ? -beyond : y == int(faceSize) + 1 ? 1.0f + beyond : (float(y) - 0.5f) / n;
    CubeFacePoint p = cubeFacePoint(cubeFaceDirection(face, vec2(s, t)));
    uint last = faceSize - 1u;
    return uvec3(p.face, min(uint(p.st.x * n), last), min(uint(p.st.y * n), last));
}

#ifdef __cplusplus
}  // namespace vkrt::cubemap
#endif

#endif  // VKRT_CUBE_MAP_H
