// Ray/primitive intersection in object space: watertight triangles, spheres, axis-aligned boxes.
// The C++ counterparts (bvh_builder/intersect.*) implement the same tests independently.
#ifndef VKRT_INTERSECT_GLSL
#define VKRT_INTERSECT_GLSL

// A ray with the per-ray constants of the watertight triangle test (Woop, Benthin & Wald 2013):
// the axis kz where |d| is largest, the other two axes, and the shear that maps d onto +z.
struct TraceRay {
    vec3 origin;
    vec3 dir;        // not necessarily unit length; t is in units of |dir|
    vec3 invDir;     // 1/dir, zero components replaced by a tiny signed value (never NaN)
    ivec3 axes;      // kx, ky, kz
    vec3 shear;      // Sx, Sy, Sz
};

// 1/d with zero components replaced by +-1e-30: the slab distances become huge but finite or
// infinite with the right sign, never 0 * inf = NaN.
vec3 safeInverse(vec3 d) {
    vec3 s = vec3(d.x < 0.0 ? -1.0 : 1.0, d.y < 0.0 ? -1.0 : 1.0, d.z < 0.0 ? -1.0 : 1.0);
    vec3 m = max(abs(d), vec3(1e-30));
    return s / m;
}

// v's components in the order k names them, by selects: indexing a vector with a per-lane index
// (v[k]) is a per-lane scalar access on lavapipe.
float pickAxis(vec3 v, int k) { return k == 0 ? v.x : (k == 1 ? v.y : v.z); }
vec3 permuteAxes(vec3 v, ivec3 k) { return vec3(pickAxis(v, k.x), pickAxis(v, k.y), pickAxis(v, k.z)); }

TraceRay makeTraceRay(vec3 origin, vec3 dir) {
    TraceRay r;
    r.origin = origin;
    r.dir = dir;
    r.invDir = safeInverse(dir);
    vec3 a = abs(dir);
    int kz = (a.x > a.y) ? ((a.x > a.z) ? 0 : 2) : ((a.y > a.z) ? 1 : 2);
    int kx = kz == 2 ? 0 : kz + 1;  // (kz + 1) % 3 without an integer division per lane
    int ky = kx == 2 ? 0 : kx + 1;
    // Keep the winding: swapping kx and ky when d[kz] < 0 preserves the sign of the edge tests.
    float dz = pickAxis(dir, kz);
    if (dz < 0.0) {
        int tmp = kx;
        kx = ky;
        ky = tmp;
    }
    r.axes = ivec3(kx, ky, kz);
    r.shear = vec3(pickAxis(dir, kx) / dz, pickAxis(dir, ky) / dz, 1.0 / dz);
    return r;
}

// Watertight ray/triangle. On a hit with 0 < t < tBest returns true, t and the barycentric
// weights (b1, b2) of v1 and v2. Edge functions are `precise` so no FMA contraction breaks the
// exact sign symmetry between triangles that share an edge (the watertightness argument).
bool intersectTriangle(TraceRay ray, vec3 v0, vec3 v1, vec3 v2, float tBest, out float tHit, out vec2 bary) {
    tHit = 0.0;
    bary = vec2(0.0);
    vec3 A = permuteAxes(v0 - ray.origin, ray.axes);
    vec3 B = permuteAxes(v1 - ray.origin, ray.axes);
    vec3 C = permuteAxes(v2 - ray.origin, ray.axes);
    precise float Ax = A.x - ray.shear.x * A.z;
    precise float Ay = A.y - ray.shear.y * A.z;
    precise float Bx = B.x - ray.shear.x * B.z;
    precise float By = B.y - ray.shear.y * B.z;
    precise float Cx = C.x - ray.shear.x * C.z;
    precise float Cy = C.y - ray.shear.y * C.z;
    precise float U = Cx * By - Cy * Bx;
    precise float V = Ax * Cy - Ay * Cx;
    precise float W = Bx * Ay - By * Ax;
    if ((U < 0.0 || V < 0.0 || W < 0.0) && (U > 0.0 || V > 0.0 || W > 0.0)) return false;
    precise float det = U + V + W;
    if (det == 0.0) return false;  // degenerate triangle or ray in its plane
    precise float Az = ray.shear.z * A.z;
    precise float Bz = ray.shear.z * B.z;
    precise float Cz = ray.shear.z * C.z;
    precise float T = U * Az + V * Bz + W * Cz;
    // Compare T against the range scaled by det to avoid dividing for rejected hits.
    if (det < 0.0 && (T >= 0.0 || T <= tBest * det)) return false;
    if (det > 0.0 && (T <= 0.0 || T >= tBest * det)) return false;
    float invDet = 1.0 / det;
    tHit = T * invDet;
    bary = vec2(V * invDet, W * invDet);
    return tHit > 0.0 && tHit < tBest;
}

// Ray/sphere with the cancellation-free form (Haines et al., Ray Tracing Gems ch. 7): the
// discriminant from the perpendicular distance, the near root from the stable quadratic formula.
// Returns the nearest root in (0, tBest).
bool intersectSphere(TraceRay ray, vec3 center, float radius, float tBest, out float tHit) {
    tHit = 0.0;
    vec3 f = ray.origin - center;
    float a = dot(ray.dir, ray.dir);
    float b = -dot(f, ray.dir);                 // = a * (distance along the ray to the closest point)
    vec3 perp = f + (b / a) * ray.dir;          // from the centre to the closest point of the line
    float disc = radius * radius - dot(perp, perp);
    if (disc < 0.0) return false;
    float c = (length(f) - radius) * (length(f) + radius);  // |f|^2 - r^2 without cancellation
    float q = b + (b < 0.0 ? -1.0 : 1.0) * sqrt(a * disc);
    float t0 = c / q;
    float t1 = q / a;
    if (q == 0.0) { t0 = 0.0; t1 = 0.0; }
    float tNear = min(t0, t1);
    float tFar = max(t0, t1);
    float t = tNear > 0.0 ? tNear : tFar;
    if (!(t > 0.0 && t < tBest)) return false;
    tHit = t;
    return true;
}

// Slab test for an axis-aligned box: entry distance if the origin is outside, exit distance if it
// is inside (camera or secondary ray inside a box), within (0, tBest).
bool intersectBox(TraceRay ray, vec3 lo, vec3 hi, float tBest, out float tHit) {
    tHit = 0.0;
    vec3 t0 = (lo - ray.origin) * ray.invDir;
    vec3 t1 = (hi - ray.origin) * ray.invDir;
    vec3 tMin = min(t0, t1);
    vec3 tMax = max(t0, t1);
    float tEnter = max(max(tMin.x, tMin.y), tMin.z);
    float tExit = min(min(tMax.x, tMax.y), tMax.z);
    if (tEnter > tExit) return false;
    float t = tEnter > 0.0 ? tEnter : tExit;
    if (!(t > 0.0 && t < tBest)) return false;
    tHit = t;
    return true;
}

#endif
