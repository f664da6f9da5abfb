// Shape emitters in the kernel (docs/RENDERING.md §4): a point of one seen from a shading point,
// and the density with which its light samples reach a point a ray hit. The sampling itself is
// shared with the CPU reference (shared/emitter_sampling.h); this file fetches the records.
#ifndef VKRT_EMITTERS_GLSL
#define VKRT_EMITTERS_GLSL

// The triangle an EMITTER_TRIANGLES sample u picks: the first whose cumulative share exceeds u,
// by binary search (host/lighting/emitter_table.cpp pickEmitterTriangle is the same search).
uint pickEmitterTriangle(EmitterRecord e, float u) {
    uint lo = emitterFirstTriangle(e);
    uint hi = lo + emitterTriangleCount(e);
    uint last = hi - 1u;
    while (lo < hi) {
        if (!chargeLoop()) break;
        uint mid = (lo + hi) >> 1u;
        if (u < emitterTriangleShare(mid)) hi = mid;
        else lo = mid + 1u;
    }
    if (lo < hi) markLoopCutOff();
    return min(lo, last);
}

// The emitter a light sample u goes to: the first whose cumulative choice share exceeds u
// (host/lighting/emitter_table.cpp pickEmitter is the same search).
uint pickEmitter(uint count, float u) {
    uint lo = 0u;
    uint hi = count;
    while (lo < hi) {
        if (!chargeLoop()) break;
        uint mid = (lo + hi) >> 1u;
        if (u < emitterChoiceShare(mid)) hi = mid;
        else lo = mid + 1u;
    }
    if (lo < hi) markLoopCutOff();
    return min(lo, count - 1u);
}

// The total solid angle at x of the EMITTER_TRIANGLES emitter's triangles that x's light samples
// go to: all, or for a convex emitter seen from outside those in front of x (`onlyFacing`,
// emitter_sampling.h triangleFacesPoint).
float emitterSolidAngle(EmitterRecord e, vec3 x, out bool onlyFacing) {
    uint first = emitterFirstTriangle(e);
    uint n = emitterTriangleCount(e);
    bool convex = emitterConvex(e);
    float total = 0.0;
    float facing = 0.0;
    uint i = 0u;
    for (; i < n; ++i) {
        if (!chargeLoop()) break;
        EmitterTriangle t = loadEmitterTriangle(first + i);
        float w = triangleSolidAngle(t, x);
        total += w;
        if (convex && triangleFacesPoint(t, x)) facing += w;
    }
    if (i < n) markLoopCutOff();
    onlyFacing = facing > 0.0;
    return onlyFacing ? facing : total;
}

// Whether x samples the emitter's triangles by solid angle, and then their total `omega`.
bool samplesBySolidAngle(EmitterRecord e, vec3 x, out float omega, out bool onlyFacing) {
    omega = 0.0;
    onlyFacing = false;
    if (emitterTriangleCount(e) > SOLID_ANGLE_MAX_TRIANGLES || !solidAngleNear(e, x)) return false;
    omega = emitterSolidAngle(e, x, onlyFacing);
    return omega >= SOLID_ANGLE_MIN;
}

// A direction in the solid angle `omega` of the emitter's triangles: the triangle whose running
// solid angle first exceeds u.x omega (host/lighting/emitter_table.cpp is the same walk).
EmitterSample sampleEmitterBySolidAngle(EmitterRecord e, vec3 x, vec2 u, float omega, bool onlyFacing) {
    uint first = emitterFirstTriangle(e);
    uint n = emitterTriangleCount(e);
    if (n == 1u) return sampleSphericalTriangle(loadEmitterTriangle(first), x, u, omega, 1.0 / omega);
    float target = u.x * omega;
    float running = 0.0;
    uint chosen = n;  // the last triangle with any solid angle, should rounding leave target beyond the sum
    float chosenStart = 0.0;
    float chosenOmega = 0.0;
    bool picked = false;
    uint i = 0u;
    for (; i < n; ++i) {
        if (!chargeLoop()) break;
        EmitterTriangle t = loadEmitterTriangle(first + i);
        float w = onlyFacing && !triangleFacesPoint(t, x) ? 0.0 : triangleSolidAngle(t, x);
        if (w > 0.0) {
            chosen = i;
            chosenStart = running;
            chosenOmega = w;
            if (target < running + w) {
                picked = true;
                break;
            }
        }
        running += w;
    }
    if (!picked && i < n) markLoopCutOff();
    EmitterSample none;
    none.point = x;
    none.normal = vec3(0.0, 0.0, 1.0);
    none.pdf = 0.0;
    if (chosen == n || g_budgetExceeded) return none;
    float ux = clamp((target - chosenStart) / chosenOmega, 0.0, 0.99999994);
    return sampleSphericalTriangle(loadEmitterTriangle(first + chosen), x, vec2(ux, u.y), chosenOmega, 1.0 / omega);
}

EmitterSample sampleEmitter(EmitterRecord e, vec3 x, vec2 u) {
    uint kind = emitterKind(e);
    if (kind == EMITTER_SPHERE) return sampleSphereEmitter(x, e.sphere.xyz, e.sphere.w, u);
    if (kind == EMITTER_ELLIPSOID) return sampleEllipsoidEmitter(e, x, u);
    EmitterSample none;
    none.point = x;
    none.normal = vec3(0.0, 0.0, 1.0);
    none.pdf = 0.0;
    if (emitterTriangleCount(e) == 0u) return none;
    float omega;
    bool onlyFacing;
    if (samplesBySolidAngle(e, x, omega, onlyFacing)) return sampleEmitterBySolidAngle(e, x, u, omega, onlyFacing);
    uint i = pickEmitterTriangle(e, u.x);
    float previous = i > emitterFirstTriangle(e) ? emitterTriangleShare(i - 1u) : 0.0;
    return sampleEmitterTriangle(loadEmitterTriangle(i), previous, emitterAreaPdf(e), x, u);
}

// The solid-angle density at x of the emitter's light samples reaching its point q (normal nq),
// given that they go to this emitter (times emitterChoicePdf: of any light sample).
float emitterPdf(EmitterRecord e, vec3 x, vec3 q, vec3 nq) {
    uint kind = emitterKind(e);
    if (kind == EMITTER_SPHERE) return sphereEmitterPdf(x, e.sphere.xyz, e.sphere.w, q, nq);
    if (kind == EMITTER_ELLIPSOID) return ellipsoidEmitterPdf(e, x, q, nq);
    if (emitterTriangleCount(e) == 0u) return 0.0;
    float omega;
    bool onlyFacing;
    // A face that does not face x gets no light samples (only a grazing ray reaches one).
    if (samplesBySolidAngle(e, x, omega, onlyFacing)) return onlyFacing && !(dot(nq, x - q) > 0.0) ? 0.0 : 1.0 / omega;
    return solidAnglePdf(emitterAreaPdf(e), x, q, nq);
}

#endif
