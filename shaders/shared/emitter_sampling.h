// Directions and light points for path tracing, for the CPU reference and the GLSL kernels alike
// (this file is valid C++ and valid GLSL; docs/RENDERING.md §4-§5): the Diffuse bounce's
// cosine-weighted direction, a point on a shape emitter with its solid-angle density, and the
// multiple-importance weights. One definition, so both devices draw the same directions from the
// same sample numbers (equal to rounding, not bit for bit: the GPU may fuse multiply-adds and its
// sqrt, sin and cos are less exact).
//
// Densities are per steradian as seen from the shading point x. A density of 0 means "no
// sample": the caller adds nothing for it.
#ifndef VKRT_EMITTER_SAMPLING_H
#define VKRT_EMITTER_SAMPLING_H

#ifdef __cplusplus
#include <glm/glm.hpp>
#include "device_host.h"
#include "sampling.h"
namespace vkrt::emitters {
using glm::abs;
using glm::atan;
using glm::clamp;
using glm::cos;
using glm::cross;
using glm::dot;
using glm::length;
using glm::max;
using glm::min;
using glm::normalize;
using glm::sin;
using glm::sqrt;
using gpu::EmitterRecord;
using gpu::emitterConvex;
using gpu::EmitterTriangle;
using gpu::uint;
using gpu::vec2;
using gpu::vec3;
using gpu::vec4;
using mat3 = glm::mat3;
using sampling::concentricDisk;
#endif

VKRT_CONST float EMITTER_PI = 3.14159265358979f;
VKRT_CONST float EMITTER_INV_PI = 0.318309886183791f;

// An orthonormal basis whose third column is the unit vector n. Every such construction jumps
// somewhere (no tangent field on the sphere is continuous); where it jumps matters here, because
// both devices must pick the same side for the same surface. Duff et al.'s (2017) jumps at n.z = 0:
// on every wall and floor of an axis-aligned room, whose normals' z is a rounding error of either
// sign, so the CPU and the GPU drew unrelated bounces on whole triangles. This one is the cross
// product with a fixed reference direction G1 (unit: 0.48^2 + 0.6^2 + 0.64^2 = 1), or G2 (unit and
// orthogonal to G1) within 37 degrees of +-G1, so it jumps only on the cone |n.G1| = 0.8, which no
// axis direction is near (|components of G1| <= 0.64) and where |cross| >= 0.6 on both sides.
VKRT_FN mat3 basisAround(vec3 n) {
    vec3 a = abs(dot(n, vec3(0.48f, 0.6f, 0.64f))) < 0.8f ? vec3(0.48f, 0.6f, 0.64f) : vec3(0.780869f, -0.624695f, 0.0f);
    vec3 t = normalize(cross(a, n));
    return mat3(t, cross(n, t), n);
}

// A cosine-weighted direction around the unit normal n (Malley's method: the concentric disc
// point lifted onto the hemisphere, so the sample's strata stay compact). Density cos / pi.
VKRT_FN vec3 cosineDirection(vec3 n, vec2 u) {
    vec2 d = concentricDisk(u);
    float z = sqrt(max(0.0f, 1.0f - d.x * d.x - d.y * d.y));
    return normalize(basisAround(n) * vec3(d.x, d.y, z));
}
VKRT_FN float cosinePdf(vec3 n, vec3 dir) { return max(dot(n, dir), 0.0f) * EMITTER_INV_PI; }

// A uniformly distributed unit vector (Archimedes: z uniform in [-1, 1]).
VKRT_FN vec3 uniformSphereDirection(vec2 u) {
    float z = 1.0f - 2.0f * u.x;
    float r = sqrt(max(0.0f, 1.0f - z * z));
    float phi = 2.0f * EMITTER_PI * u.y;
    return vec3(r * cos(phi), r * sin(phi), z);
}

// A point on an emitter seen from x: `pdf` is per steradian at x (0: none).
struct EmitterSample {
    vec3 point;
    vec3 normal;  // unit, the surface's outward side (emission is two-sided)
    float pdf;
};

// From an area density at point q with unit normal nq to a solid-angle density at x.
VKRT_FN float solidAnglePdf(float areaPdf, vec3 x, vec3 q, vec3 nq) {
    vec3 d = q - x;
    float cosQ = abs(dot(nq, normalize(d)));
    return cosQ > 0.0f ? areaPdf * dot(d, d) / cosQ : 0.0f;
}

// 1 - cos(theta_max) of the cone a sphere of radius r subtends at distance^2 d2 > r^2, written as
// sin^2 / (1 + cos) so that a small, far sphere keeps its digits (1 - cos would cancel).
VKRT_FN float coneOneMinusCos(float d2, float r) {
    float sin2 = min(r * r / d2, 1.0f);
    return sin2 / (1.0f + sqrt(1.0f - sin2));
}

// Whether x samples the sphere by its cone: outside it by a margin, so the cone is well defined
// (from inside, or on it, the whole sphere is sampled by area).
VKRT_FN bool sphereConeApplies(vec3 x, vec3 c, float r) {
    vec3 toC = c - x;
    return dot(toC, toC) > r * r * 1.0001f;
}

// EMITTER_SPHERE (world centre c, radius r): by the solid angle it subtends from x (the cone of
// directions towards it, uniformly), or uniformly by area when x is inside or on it.
VKRT_FN EmitterSample sampleSphereEmitter(vec3 x, vec3 c, float r, vec2 u) {
    EmitterSample s;
    if (!sphereConeApplies(x, c, r)) {
        s.normal = uniformSphereDirection(u);
        s.point = c + r * s.normal;
        s.pdf = solidAnglePdf(1.0f / (4.0f * EMITTER_PI * r * r), x, s.point, s.normal);
        return s;
    }
    vec3 toC = c - x;
    float d2 = dot(toC, toC);
    float d = sqrt(d2);
    float oneMinusCosMax = coneOneMinusCos(d2, r);
    float oneMinusCos = u.x * oneMinusCosMax;
    float cosTheta = 1.0f - oneMinusCos;
    float sin2Theta = oneMinusCos * (2.0f - oneMinusCos);
    float sinTheta = sqrt(max(0.0f, sin2Theta));
    float phi = 2.0f * EMITTER_PI * u.y;
    vec3 dir = normalize(basisAround(toC / d) * vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta));
    // The nearer intersection of x + t dir with the sphere: t = d cos - sqrt(r^2 - d^2 sin^2).
    float t = d * cosTheta - sqrt(max(0.0f, r * r - d2 * sin2Theta));
    s.point = x + t * dir;
    s.normal = normalize(s.point - c);
    s.pdf = 1.0f / (2.0f * EMITTER_PI * oneMinusCosMax);
    return s;
}

// The density sampleSphereEmitter gives the point q (unit normal nq) it reaches from x.
VKRT_FN float sphereEmitterPdf(vec3 x, vec3 c, float r, vec3 q, vec3 nq) {
    if (!sphereConeApplies(x, c, r)) return solidAnglePdf(1.0f / (4.0f * EMITTER_PI * r * r), x, q, nq);
    vec3 toC = c - x;
    return 1.0f / (2.0f * EMITTER_PI * coneOneMinusCos(dot(toC, toC), r));
}

// The 3x4 affine rows of an EmitterRecord applied to a point, and the transpose of the 3x3 part of
// `rows` applied to a vector (with toObject's rows: M^-T v, the normal of the world surface).
VKRT_FN vec3 applyRows(vec4 r0, vec4 r1, vec4 r2, vec3 p) {
    return vec3(dot(vec3(r0), p) + r0.w, dot(vec3(r1), p) + r1.w, dot(vec3(r2), p) + r2.w);
}
VKRT_FN vec3 applyTransposed(vec4 r0, vec4 r1, vec4 r2, vec3 v) {
    return v.x * vec3(r0) + v.y * vec3(r1) + v.z * vec3(r2);
}

// EMITTER_ELLIPSOID (the object sphere (centre, radius) = e.sphere under the affine map M =
// toWorld): by the cone of the object sphere seen from x's object-space image x' = M^-1 x, when x'
// is outside it. Visibility is affine-invariant, so the cone's directions reach exactly the
// ellipsoid's visible side; a linear map A = M^-1 takes a world direction w to A w / |A w| and
// solid angle by |det A| / |A w|^3 (the Jacobian of Heitz et al. 2016's linearly transformed
// distributions), so the world density is the cone's times |det A| (|q - x| / |q' - x'|)^3. It is
// bounded (by the cone's density times cond(M)^3), where area sampling's grows as distance^2 near
// the surface. From inside the ellipsoid or on it: uniformly over the object sphere's area, a
// patch dA with unit object normal n becoming |det M| |M^-T n| dA (Nanson's formula), so the world
// area density is 1 / (4 pi r^2 |det M|) (the record's constant) over |M^-T n|.
VKRT_FN float ellipsoidAreaPdf(EmitterRecord e, vec3 objectNormal) {
    float stretch = length(applyTransposed(e.toObject[0], e.toObject[1], e.toObject[2], objectNormal));
    return stretch > 0.0f ? emitterAreaPdf(e) / stretch : 0.0f;
}
VKRT_FN float ellipsoidInverseDeterminant(EmitterRecord e) {
    return abs(dot(vec3(e.toObject[0]), cross(vec3(e.toObject[1]), vec3(e.toObject[2]))));
}
// The world density of a cone sample of object density `conePdf` from x (object x') to q (object q').
VKRT_FN float ellipsoidConePdf(EmitterRecord e, float conePdf, vec3 x, vec3 xo, vec3 q, vec3 qo) {
    vec3 dw = q - x;
    vec3 dobj = qo - xo;
    float lo2 = dot(dobj, dobj);
    if (!(lo2 > 0.0f)) return 0.0f;
    float ratio = sqrt(dot(dw, dw) / lo2);
    return conePdf * ellipsoidInverseDeterminant(e) * ratio * ratio * ratio;
}
VKRT_FN EmitterSample sampleEllipsoidEmitter(EmitterRecord e, vec3 x, vec2 u) {
    vec3 xo = applyRows(e.toObject[0], e.toObject[1], e.toObject[2], x);
    EmitterSample s;
    if (sphereConeApplies(xo, vec3(e.sphere), e.sphere.w)) {
        EmitterSample so = sampleSphereEmitter(xo, vec3(e.sphere), e.sphere.w, u);
        s.point = applyRows(e.toWorld[0], e.toWorld[1], e.toWorld[2], so.point);
        s.normal = normalize(applyTransposed(e.toObject[0], e.toObject[1], e.toObject[2], so.normal));
        s.pdf = ellipsoidConePdf(e, so.pdf, x, xo, s.point, so.point);
        return s;
    }
    vec3 n = uniformSphereDirection(u);
    s.point = applyRows(e.toWorld[0], e.toWorld[1], e.toWorld[2], vec3(e.sphere) + e.sphere.w * n);
    s.normal = normalize(applyTransposed(e.toObject[0], e.toObject[1], e.toObject[2], n));
    s.pdf = solidAnglePdf(ellipsoidAreaPdf(e, n), x, s.point, s.normal);
    return s;
}
// The density sampleEllipsoidEmitter gives the world point q (unit normal nq) it reaches from x.
VKRT_FN float ellipsoidEmitterPdf(EmitterRecord e, vec3 x, vec3 q, vec3 nq) {
    vec3 xo = applyRows(e.toObject[0], e.toObject[1], e.toObject[2], x);
    vec3 qo = applyRows(e.toObject[0], e.toObject[1], e.toObject[2], q);
    if (sphereConeApplies(xo, vec3(e.sphere), e.sphere.w)) {
        vec3 toC = vec3(e.sphere) - xo;
        float conePdf = 1.0f / (2.0f * EMITTER_PI * coneOneMinusCos(dot(toC, toC), e.sphere.w));
        return ellipsoidConePdf(e, conePdf, x, xo, q, qo);
    }
    vec3 n = normalize(qo - vec3(e.sphere));
    return solidAnglePdf(ellipsoidAreaPdf(e, n), x, q, nq);
}

// EMITTER_TRIANGLES: the triangle whose cumulative share first exceeds u.x was chosen by the
// caller (a binary search over emitterTriangleCdf, the same on both sides); `previousCdf` is the
// share before it. u.x is stretched back to [0, 1) inside that triangle's share, and the point is
// uniform in the triangle (square-root map), so the world area density is the emitter's constant.
VKRT_FN EmitterSample sampleEmitterTriangle(EmitterTriangle t, float previousCdf, float areaPdf, vec3 x, vec2 u) {
    float width = emitterTriangleCdf(t) - previousCdf;
    float ux = width > 0.0f ? min((u.x - previousCdf) / width, 0.99999994f) : 0.0f;
    float su = sqrt(max(ux, 0.0f));
    EmitterSample s;
    s.point = vec3(t.corner) + su * (1.0f - u.y) * vec3(t.edge1) + su * u.y * vec3(t.edge2);
    s.normal = normalize(cross(vec3(t.edge1), vec3(t.edge2)));
    s.pdf = solidAnglePdf(areaPdf, x, s.point, s.normal);
    return s;
}

// EMITTER_TRIANGLES with at most SOLID_ANGLE_MAX_TRIANGLES triangles (a triangle, a quad, a box, a
// small mesh): by solid angle near the emitter (SOLID_ANGLE_NEAR below). Each light sample picks a
// triangle in proportion to the solid angle it subtends at x and a direction uniformly inside it
// (Arvo 1995), so the density is 1 / (the triangles' total solid angle) wherever the sample lands:
// no 1 / distance^2 tail near the emitter, where area sampling's samples are heavy-tailed
// (docs/RENDERING.md §4). Larger meshes keep area sampling (the per-sample loop over their
// triangles would cost more than it saves). Below SOLID_ANGLE_MIN steradians (an emitter ~70 times
// its size away) Arvo's construction loses its digits in float (sin of the sampled arc from
// 1 - q^2) and area sampling is near-uniform in solid angle anyway, so the emitter is sampled by area
// there; the rule depends on x alone, so a bounce's hit is weighed with the density of the same
// rule.
VKRT_CONST uint SOLID_ANGLE_MAX_TRIANGLES = 12u;
VKRT_CONST float SOLID_ANGLE_MIN = 1e-4f;
// Solid-angle sampling pays near the emitter, where area sampling's 1 / distance^2 tail lives;
// farther away the two densities differ little across the emitter and Arvo's construction (an atan
// per triangle for the solid angles, a sin and a cos per sample) costs more than the variance it
// saves. So a triangle set is sampled by solid angle only from points within SOLID_ANGLE_NEAR
// bounding-sphere radii of its centre (EmitterRecord::sphere), by area beyond (Cycles' triangle
// lights make the same kind of choice, per triangle: solid angle where the longest edge exceeds the
// distance to the triangle's plane). At 2 radii the quad-lit room's error per sample is that of
// solid-angle sampling everywhere to three digits, at less time per sample (docs/BENCHMARKS.md). A
// convex emitter keeps solid-angle sampling everywhere: area sampling would spend half its samples
// on the faces turned away from the point.
VKRT_CONST float SOLID_ANGLE_NEAR = 2.0f;
VKRT_FN bool solidAngleNear(EmitterRecord e, vec3 x) {
    if (emitterConvex(e)) return true;
    vec3 d = x - vec3(e.sphere);
    float r = SOLID_ANGLE_NEAR * e.sphere.w;
    return dot(d, d) < r * r;
}

// A convex emitter (a box: EmitterRecord::choice.z = 1, its triangles wound so that e1 x e2 points
// outwards) seen from a point outside it shows only the faces whose plane the point is in front
// of: a direction towards any other face meets the box first. Those are the triangles its light
// samples go to (half the box's solid angle, where sampling every face wasted half the samples on
// the hidden side); from inside the box no face is in front and every face counts.
VKRT_FN bool triangleFacesPoint(EmitterTriangle t, vec3 x) {
    return dot(cross(vec3(t.edge1), vec3(t.edge2)), x - vec3(t.corner)) > 0.0f;
}

// The solid angle of triangle t at x (Van Oosterom & Strackee 1983: tan(omega / 2) =
// |a . (b x c)| / (|a||b||c| + (a.b)|c| + (b.c)|a| + (c.a)|b|) for the corners a, b, c relative to
// x). The triple product is written a . (e1 x e2), which keeps its digits for a far triangle where
// the three directions nearly coincide.
VKRT_FN float triangleSolidAngle(EmitterTriangle t, vec3 x) {
    vec3 a = vec3(t.corner) - x;
    vec3 b = a + vec3(t.edge1);
    vec3 c = a + vec3(t.edge2);
    float la = length(a);
    float lb = length(b);
    float lc = length(c);
    float num = abs(dot(a, cross(vec3(t.edge1), vec3(t.edge2))));
    float den = la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb;
    return num > 0.0f ? 2.0f * atan(num, den) : 0.0f;
}

// A direction uniform inside triangle t's solid angle `omega` (> 0) at x, for u in [0, 1)^2, and
// the point of t it reaches (Arvo 1995, "Stratified sampling of spherical triangles": u.x picks
// the sub-triangle of area u.x omega sharing the corner A, u.y a point on the arc from B to its
// third corner). Differences of nearly equal cosines are rewritten as products of sines:
// cos(s - alpha) - cos(alpha) = -2 sin(s / 2) sin(s / 2 - alpha), 1 - cos(arc) = |p - q|^2 / 2.
// `pdf` is the caller's density (1 / the emitter's total solid angle): uniform over every
// triangle's share.
VKRT_FN EmitterSample sampleSphericalTriangle(EmitterTriangle t, vec3 x, vec2 u, float omega, float pdf) {
    vec3 e1 = vec3(t.edge1);
    vec3 e2 = vec3(t.edge2);
    vec3 toA = vec3(t.corner) - x;
    vec3 A = normalize(toA);
    vec3 B = normalize(toA + e1);
    vec3 C = normalize(toA + e2);
    // The corner angle alpha at A, between the arcs AB and AC: nAB x nAC is along A, of length
    // |nAB||nAC| sin(alpha), and nAB . nAC = |nAB||nAC| cos(alpha).
    vec3 nAB = cross(A, B);
    vec3 nAC = cross(A, C);
    float ya = abs(dot(cross(nAB, nAC), A));
    float xa = dot(nAB, nAC);
    float ha = sqrt(ya * ya + xa * xa);
    EmitterSample r;
    r.normal = normalize(cross(e1, e2));
    r.point = x;
    r.pdf = 0.0f;
    if (!(ha > 0.0f)) return r;  // a degenerate corner: no sub-triangle to pick
    float sinAlpha = ya / ha;
    float cosAlpha = xa / ha;
    vec3 AB = A - B;
    float oneMinusCosC = 0.5f * dot(AB, AB);  // c: the arc from A to B
    // s = u.x omega, the sub-triangle's area: every sine and cosine below from those of s / 2 and
    // alpha by the angle-sum identities (one sin and one cos; no inverse trigonometry for alpha).
    float halfS = 0.5f * u.x * omega;
    float sinHalf = sin(halfS);
    float cosHalf = cos(halfS);
    float sinS0 = 2.0f * sinHalf * cosHalf;           // sin(s)
    float cosS0 = 1.0f - 2.0f * sinHalf * sinHalf;    // cos(s)
    float sinS = sinS0 * cosAlpha - cosS0 * sinAlpha; // sin(s - alpha)
    float cosS = cosS0 * cosAlpha + sinS0 * sinAlpha; // cos(s - alpha)
    float sinHalfMinus = sinHalf * cosAlpha - cosHalf * sinAlpha;  // sin(s / 2 - alpha)
    float cosHalfMinus = cosHalf * cosAlpha + sinHalf * sinAlpha;  // cos(s / 2 - alpha)
    float du = -2.0f * sinHalf * sinHalfMinus;                         // cos(s - alpha) - cos(alpha)
    float dv = 2.0f * sinHalf * cosHalfMinus - sinAlpha * oneMinusCosC; // sin(s - alpha) + sin(alpha) cos(c)
    float den = (dv * sinS + du * cosS) * sinAlpha;
    float q = den != 0.0f ? ((dv * cosS - du * sinS) * cosAlpha - dv) / den : 1.0f;
    q = clamp(q, -1.0f, 1.0f);
    // C': the sub-triangle's third corner, on the arc from A towards C at cos(arc) = q.
    vec3 towardsC = C - dot(C, A) * A;
    float lt = length(towardsC);
    vec3 Cp = lt > 0.0f ? q * A + sqrt(max(0.0f, 1.0f - q * q)) * (towardsC / lt) : A;
    vec3 CB = Cp - B;
    float oneMinusZ = u.y * 0.5f * dot(CB, CB);
    float z = 1.0f - oneMinusZ;
    vec3 towardsCp = Cp - dot(Cp, B) * B;
    float lp = length(towardsCp);
    vec3 dir = lp > 0.0f ? z * B + sqrt(max(0.0f, oneMinusZ * (2.0f - oneMinusZ))) * (towardsCp / lp) : B;
    vec3 n = cross(e1, e2);
    float along = dot(n, dir);
    if (along == 0.0f) return r;  // grazing: the plane is not reached
    r.point = x + (dot(n, toA) / along) * dir;
    r.pdf = pdf;
    return r;
}

// Russian roulette (docs/RENDERING.md §5): a Diffuse bounce whose path weight's largest component
// m is below its depth's threshold goes on with probability m / threshold, carrying its weight
// divided by that probability (so its expected contribution is unchanged), and ends otherwise.
// The factor its weight takes for the roulette sample u (the caller draws u only below the
// threshold): 0 (ended) or 1 / probability, which lifts the weight's largest component to the
// threshold. The thresholds are measured (tools/time_to_error.py, docs/BENCHMARKS.md): from the
// bounce leaving a hit of depth ROULETTE_DEEP_DEPTH on, 1/4 halves the cost of the long tail of
// deep renders (-k 16: 1.3-2.9x faster to a given error); before it, where the samplers stratify
// the bounces that carry most of the image, a roulette sample (1D, not stratified with them) adds
// more noise than it saves time, and only paths below 1/64 play (at 1/4 there, diffuseScene's
// kd 0.5 took 2x the time to an error under sobol at the default depth 4, where no deep bounce
// follows).
VKRT_CONST float ROULETTE_WEIGHT = 0.25f;
VKRT_CONST float ROULETTE_SHALLOW_WEIGHT = 0.015625f;
VKRT_CONST uint ROULETTE_DEEP_DEPTH = 4u;
VKRT_FN float rouletteThreshold(uint depth) { return depth >= ROULETTE_DEEP_DEPTH ? ROULETTE_WEIGHT : ROULETTE_SHALLOW_WEIGHT; }
VKRT_FN float rouletteFactor(float m, float threshold, float u) {
    float p = m / threshold;
    return u < p ? 1.0f / p : 0.0f;
}

// Veach's multiple-importance weight of a strategy with density `a` (times its sample count)
// against one with density `b`: the balance heuristic a / (a + b), or the power heuristic with
// exponent 2. Densities can reach float's range on a tiny, far emitter (1 / (2 pi (1 - cos))),
// so both are scaled by the larger before squaring.
VKRT_FN float misWeight(float a, float b, bool power) {
    if (!(a > 0.0f)) return 0.0f;
    if (!(b > 0.0f)) return 1.0f;
    float m = max(a, b);
    float x = a / m;
    float y = b / m;
    if (power) {
        x *= x;
        y *= y;
    }
    return x / (x + y);
}

#ifdef __cplusplus
}  // namespace vkrt::emitters
#endif

#endif  // VKRT_EMITTER_SAMPLING_H
