// Secondary-ray origins (docs/RENDERING.md §6): the hit point moves along the normal by a bound on
// the floating-point error of its computation, 16 float epsilons (2^-20) of the largest magnitude
// the computation involved (Surface.errorMagnitude, pbrt-style error bounds). The offset scales with
// the scene, so the same scene behaves the same at 1e-4 and 1e5, and a point near the origin on a
// large primitive moves by the primitive's error rather than by its own tiny coordinates.
#ifndef VKRT_RAY_OFFSET_GLSL
#define VKRT_RAY_OFFSET_GLSL

const float OFFSET_SCALE = 1.0 / 1048576.0;  // 2^-20 = 16 * 2^-24; host/cpu/ray_offset.h explains the margin

// p moved along n (unit, pointing to the side the new ray leaves on).
vec3 offsetRayOrigin(vec3 p, vec3 n, float magnitude) {
    vec3 a = abs(p);
    return p + (OFFSET_SCALE * max(magnitude, max(max(a.x, a.y), a.z))) * n;
}

// Offset towards the side of `dir`.
vec3 offsetTowards(Surface s, vec3 dir) {
    return offsetRayOrigin(s.position, dot(dir, s.geomNormal) >= 0.0 ? s.geomNormal : -s.geomNormal, s.errorMagnitude);
}

#endif
