// What shading needs to know about a hit: world position, normals, texture coordinates and the
// material, reconstructed once from the primitive (docs/RENDERING.md §3, §6, §7).
#ifndef VKRT_SURFACE_GLSL
#define VKRT_SURFACE_GLSL

const float PI = 3.14159265358979;

struct Surface {
    vec3 position;     // world space, on the surface (not offset)
    vec3 geomNormal;   // world space, unit, the primitive's outward side (sphere/box outward, triangle winding)
    vec3 shadeNormal;  // world space, unit, same side as geomNormal
    vec2 uv;
    uint material;
    float errorMagnitude;  // largest world-space magnitude in the point's computation (ray_offset.glsl)
};

vec3 rowTransformPoint(vec4 r0, vec4 r1, vec4 r2, vec3 p) {
    return vec3(dot(r0.xyz, p) + r0.w, dot(r1.xyz, p) + r1.w, dot(r2.xyz, p) + r2.w);
}

vec3 rowTransformVector(vec4 r0, vec4 r1, vec4 r2, vec3 v) {
    return vec3(dot(r0.xyz, v), dot(r1.xyz, v), dot(r2.xyz, v));
}

float maxAbs(vec3 v) {
    vec3 a = abs(v);
    return max(max(a.x, a.y), a.z);
}

// RENDERING.md §6: the bound on |M p| over object-space coordinates of magnitude m (max over rows
// of |t| + sum |A| * m).
float transformedMagnitude(vec4 r0, vec4 r1, vec4 r2, float m) {
    vec4 a0 = abs(r0), a1 = abs(r1), a2 = abs(r2);
    return max(max(a0.w + (a0.x + a0.y + a0.z) * m, a1.w + (a1.x + a1.y + a1.z) * m), a2.w + (a2.x + a2.y + a2.z) * m);
}

// The rare case of normalizeOr: v's squared length left float range (a triangle's edge cross
// product is ~|edge|^2, so edges beyond ~1e9 overflow it, below ~1e-10 underflow it). Scaling by a
// power of two keeps the direction exactly; the CPU does the same (surface.cpp unitVector).
vec3 rescaledUnitOr(vec3 v, vec3 fallback) {
    float largest = maxAbs(v);
    if (!(largest > 0.0) || isinf(largest)) return fallback;
    int exponent;
    frexp(largest, exponent);
    v = ldexp(v, ivec3(-exponent));  // largest component now in [0.5, 1)
    return v * inversesqrt(dot(v, v));
}

// A unit vector, or `fallback` when v is zero or not finite (degenerate geometry must not make NaN).
// The common path costs what a plain normalize does: the rescale sits behind the test it needs anyway.
vec3 normalizeOr(vec3 v, vec3 fallback) {
    float len2 = dot(v, v);
    if (!(len2 > 0.0) || isinf(len2)) return rescaledUnitOr(v, fallback);
    return v * inversesqrt(len2);
}

Surface surfaceAt(vec3 origin, vec3 dir, Hit hit) {
    Surface s;
    s.uv = vec2(0.0);
    vec3 o = origin;
    vec3 d = dir;
    // A moving instance where it was at the sample's time (the traversal found the hit there).
    uint motion = HAS_INSTANCES ? instanceMotion(hit.instance) : MOTION_NONE;
    Instance posed;
    if (motion != MOTION_NONE) posed = posedInstance(hit.instance, motion);
    if (HAS_INSTANCES) {
        vec4 r0 = instanceRow(hit.instance, 0u), r1 = instanceRow(hit.instance, 1u), r2 = instanceRow(hit.instance, 2u);
        if (motion != MOTION_NONE) {
            r0 = posed.worldToObject[0];
            r1 = posed.worldToObject[1];
            r2 = posed.worldToObject[2];
        }
        o = rowTransformPoint(r0, r1, r2, origin);
        d = rowTransformVector(r0, r1, r2, dir);
    }

    int base = int(hit.prim * PRIM_TEXELS);
    uvec4 a = imageLoad(primitives, base);
    uint kind = primitiveKind(a);
    PrimInfo info = loadPrimInfo(hit.prim);
    vec3 p;
    vec3 ng;
    vec3 ns;
    float objectMagnitude;  // largest |coordinate| of the primitive's data
    if (kind == PRIM_KIND_TRIANGLE) {
        vec3 v0 = texelFloats(a);
        vec3 v1 = texelFloats(imageLoad(primitives, base + 1));
        vec3 v2 = texelFloats(imageLoad(primitives, base + 2));
        objectMagnitude = max(maxAbs(v0), max(maxAbs(v1), maxAbs(v2)));
        float b0 = 1.0 - hit.bary.x - hit.bary.y;
        // Barycentric reconstruction: accurate to a few ULPs of the vertices, unlike o + t*d.
        p = b0 * v0 + hit.bary.x * v1 + hit.bary.y * v2;
        ng = cross(v1 - v0, v2 - v0);
        ns = ng;
        s.uv = hit.bary;
        uvec3 corners = primitiveCornerAttribs(info);
        if (corners.x != ATTRIB_NONE) {
            VertexAttrib a0 = loadVertexAttrib(corners.x);
            VertexAttrib a1 = loadVertexAttrib(corners.y);
            VertexAttrib a2 = loadVertexAttrib(corners.z);
            vec3 n = b0 * vertexNormal(a0) + hit.bary.x * vertexNormal(a1) + hit.bary.y * vertexNormal(a2);
            ns = dot(n, n) > 0.0 ? n : ng;
            if (HAS_TEXTURES) s.uv = b0 * vertexUv(a0) + hit.bary.x * vertexUv(a1) + hit.bary.y * vertexUv(a2);
        }
    } else if (kind == PRIM_KIND_SPHERE) {
        vec3 center = texelFloats(a);
        float radius = uintBitsToFloat(imageLoad(primitives, base + 1).x);
        objectMagnitude = maxAbs(center) + radius;
        vec3 q = o + hit.t * d;
        vec3 n = normalizeOr(q - center, vec3(0.0, 1.0, 0.0));
        p = center + radius * n;  // re-projected onto the sphere
        ng = n;
        ns = n;
        if (HAS_TEXTURES) s.uv = vec2(0.5 + atan(n.x, n.z) / (2.0 * PI), 0.5 + asin(clamp(n.y, -1.0, 1.0)) / PI);
    } else {
        vec3 lo = texelFloats(a);
        vec3 hi = texelFloats(imageLoad(primitives, base + 1));
        objectMagnitude = max(maxAbs(lo), maxAbs(hi));
        // Which face: redo the slab test and take the axis that decided the entry (or exit).
        vec3 invD = safeInverse(d);
        vec3 t0 = (lo - o) * invD;
        vec3 t1 = (hi - o) * invD;
        vec3 tMin = min(t0, t1);
        vec3 tMax = max(t0, t1);
        float tEnter = max(max(tMin.x, tMin.y), tMin.z);
        int axis;
        float side;  // +1: the hi face, -1: the lo face
        if (tEnter > 0.0) {
            axis = (tMin.x >= tMin.y && tMin.x >= tMin.z) ? 0 : (tMin.y >= tMin.z ? 1 : 2);
            side = d[axis] < 0.0 ? 1.0 : -1.0;
        } else {
            axis = (tMax.x <= tMax.y && tMax.x <= tMax.z) ? 0 : (tMax.y <= tMax.z ? 1 : 2);
            side = d[axis] < 0.0 ? -1.0 : 1.0;
        }
        p = o + hit.t * d;
        p[axis] = side > 0.0 ? hi[axis] : lo[axis];  // snapped onto the face plane
        ng = vec3(0.0);
        ng[axis] = side;
        ns = ng;
        if (HAS_TEXTURES) {
            int b = (axis + 1) % 3;
            int c = (axis + 2) % 3;
            float eb = hi[b] - lo[b];
            float ec = hi[c] - lo[c];
            s.uv = vec2(eb > 0.0 ? (p[b] - lo[b]) / eb : 0.0, ec > 0.0 ? (p[c] - lo[c]) / ec : 0.0);
        }
    }

    vec3 fallback = normalizeOr(-dir, vec3(0.0, 1.0, 0.0));
    if (HAS_INSTANCES) {
        vec4 w0 = instanceRow(hit.instance, 3u), w1 = instanceRow(hit.instance, 4u), w2 = instanceRow(hit.instance, 5u);
        vec4 n0 = instanceRow(hit.instance, 6u), n1 = instanceRow(hit.instance, 7u), n2 = instanceRow(hit.instance, 8u);
        if (motion != MOTION_NONE) {
            w0 = posed.objectToWorld[0];
            w1 = posed.objectToWorld[1];
            w2 = posed.objectToWorld[2];
            n0 = posed.normalToWorld[0];
            n1 = posed.normalToWorld[1];
            n2 = posed.normalToWorld[2];
        }
        uint override = instanceMaterialOverride(instanceInfo(hit.instance));
        p = rowTransformPoint(w0, w1, w2, p);
        objectMagnitude = transformedMagnitude(w0, w1, w2, objectMagnitude);
        ng = rowTransformVector(n0, n1, n2, ng);
        ns = rowTransformVector(n0, n1, n2, ns);
        s.material = override != MATERIAL_NONE ? override : primitiveMaterial(info);
    } else {
        s.material = primitiveMaterial(info);
    }
    s.position = p;
    s.errorMagnitude = max(objectMagnitude, maxAbs(p));
    s.geomNormal = normalizeOr(ng, fallback);
    s.shadeNormal = normalizeOr(ns, s.geomNormal);
    if (dot(s.shadeNormal, s.geomNormal) < 0.0) s.shadeNormal = -s.shadeNormal;
    return s;
}

#endif
