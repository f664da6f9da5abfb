// Secondary-ray origins (docs/RENDERING.md §6): Wachter & Binder 2019, "A Fast and Robust Method
// for Avoiding Self-Intersection" (Ray Tracing Gems ch. 6). The hit point is moved off the surface
// by a fixed number of ULPs of each coordinate, so the offset grows with the coordinates'
// magnitude instead of being one global epsilon: the same scene behaves the same at 1e-4 and 1e5.
#ifndef VKRT_RAY_OFFSET_GLSL
#define VKRT_RAY_OFFSET_GLSL

const float OFFSET_ORIGIN = 1.0 / 32.0;     // below this magnitude ULPs are too small: add a fixed offset
const float OFFSET_FLOAT_SCALE = 1.0 / 65536.0;
const float OFFSET_INT_SCALE = 256.0;

// p moved along n (unit, pointing to the side the new ray leaves on).
vec3 offsetRayOrigin(vec3 p, vec3 n) {
    ivec3 ofi = ivec3(OFFSET_INT_SCALE * n);
    vec3 pi = vec3(intBitsToFloat(floatBitsToInt(p.x) + (p.x < 0.0 ? -ofi.x : ofi.x)),
                   intBitsToFloat(floatBitsToInt(p.y) + (p.y < 0.0 ? -ofi.y : ofi.y)),
                   intBitsToFloat(floatBitsToInt(p.z) + (p.z < 0.0 ? -ofi.z : ofi.z)));
    return vec3(abs(p.x) < OFFSET_ORIGIN ? p.x + OFFSET_FLOAT_SCALE * n.x : pi.x,
                abs(p.y) < OFFSET_ORIGIN ? p.y + OFFSET_FLOAT_SCALE * n.y : pi.y,
                abs(p.z) < OFFSET_ORIGIN ? p.z + OFFSET_FLOAT_SCALE * n.z : pi.z);
}

// Offset towards the side of `dir`.
vec3 offsetTowards(Surface s, vec3 dir) {
    return offsetRayOrigin(s.position, dot(dir, s.geomNormal) >= 0.0 ? s.geomNormal : -s.geomNormal);
}

#endif
