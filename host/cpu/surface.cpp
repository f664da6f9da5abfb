#include "surface.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "ray_offset.h"

namespace vkrt::cpu {

namespace {

// The instance's 3x4 affine rows (gpu::Instance) applied to a point or a direction. Using the
// uploaded rows, not Scene::Instance's mat4, keeps the arithmetic the GPU kernel performs.
glm::vec3 applyPoint(const glm::vec4 rows[3], const glm::vec3& p) {
    return {glm::dot(glm::vec3(rows[0]), p) + rows[0].w, glm::dot(glm::vec3(rows[1]), p) + rows[1].w,
            glm::dot(glm::vec3(rows[2]), p) + rows[2].w};
}
glm::vec3 applyVector(const glm::vec4 rows[3], const glm::vec3& d) {
    return {glm::dot(glm::vec3(rows[0]), d), glm::dot(glm::vec3(rows[1]), d), glm::dot(glm::vec3(rows[2]), d)};
}

// Equirectangular sphere mapping: u = 0 .. 1 around +y starting from -z (so u = 0.5 faces +z,
// where the course's cameras usually stand) and growing towards +x; v = 0 at the south pole.
glm::vec2 sphereUv(const glm::vec3& n) {
    constexpr float kInvTwoPi = 0.5f * std::numbers::inv_pi_v<float>;
    const float u = 0.5f + std::atan2(n.x, n.z) * kInvTwoPi;
    const float v = 0.5f + std::asin(glm::clamp(n.y, -1.0f, 1.0f)) * std::numbers::inv_pi_v<float>;
    return {u, v};
}

// normalize(v), also for a v whose squared length leaves float range: the cross product of a
// triangle's edges is ~|edge|^2, so the squared length overflows for edges beyond ~1e9 (the
// normal came out 0 and the triangle black) and underflows for edges below ~1e-10. Scaling by a
// power of two first changes neither the direction nor, for ordinary v, a single bit.
glm::vec3 unitVector(glm::vec3 v) {
    const float len2 = glm::dot(v, v);
    if (!(len2 >= std::numeric_limits<float>::min() && len2 <= std::numeric_limits<float>::max())) {
        const float largest = maxAbs(v);
        if (!(largest > 0.0f) || !std::isfinite(largest)) return glm::normalize(v);
        int exponent = 0;
        std::frexp(largest, &exponent);
        v *= std::ldexp(1.0f, -exponent);  // largest component now in [0.5, 1)
    }
    return glm::normalize(v);
}

float unitRange(float x, float lo, float hi) { return hi > lo ? (x - lo) / (hi - lo) : 0.0f; }

// RENDERING.md §6: the bound on |M p| over the primitive's object-space coordinate magnitude m,
// max over rows of |t| + sum |A|*m, and the world point itself.
float errorMagnitude(const glm::vec4 rows[3], float objectMagnitude, const glm::vec3& worldPoint) {
    float m = maxAbs(worldPoint);
    for (int r = 0; r < 3; ++r) {
        const glm::vec4 a = glm::abs(rows[r]);
        m = std::max(m, a.w + (a.x + a.y + a.z) * objectMagnitude);
    }
    return m;
}

}  // namespace

BoxFace boxFaceHit(const glm::vec3& o, const glm::vec3& d, const glm::vec3& lo, const glm::vec3& hi) {
    // 1/d with zero components replaced by a tiny signed value: slab distances stay finite, never 0*inf = NaN.
    glm::vec3 invD;
    for (int a = 0; a < 3; ++a) invD[a] = (d[a] < 0.0f ? -1.0f : 1.0f) / std::max(std::fabs(d[a]), 1e-30f);
    const glm::vec3 t0 = (lo - o) * invD;
    const glm::vec3 t1 = (hi - o) * invD;
    const glm::vec3 tMin = glm::min(t0, t1);
    const glm::vec3 tMax = glm::max(t0, t1);
    BoxFace face;
    if (std::max(std::max(tMin.x, tMin.y), tMin.z) > 0.0f) {
        // Entering from outside: the slab entered last decides the face.
        face.axis = (tMin.x >= tMin.y && tMin.x >= tMin.z) ? 0 : (tMin.y >= tMin.z ? 1 : 2);
        face.maxSide = d[face.axis] < 0.0f;
    } else {
        // Leaving from inside: the slab left first.
        face.axis = (tMax.x <= tMax.y && tMax.x <= tMax.z) ? 0 : (tMax.y <= tMax.z ? 1 : 2);
        face.maxSide = !(d[face.axis] < 0.0f);
    }
    return face;
}

SurfacePoint describeHit(const SceneAccel& accel, const Scene& scene, const bvh::Ray& ray, const bvh::Hit& hit) {
    // A moving instance where it was at the ray's time (the traversal found the hit there).
    gpu::Instance posed;
    const gpu::Instance& inst = bvh::instanceAtTime(accel.bvh, hit.instance, ray.time, posed);
    const PrimOrigin& origin = accel.origin(hit.instance, hit.prim);
    const Shape& shape = *origin.shape;

    SurfacePoint sp;
    sp.emitter = accel.emitterOf(hit.instance);
    sp.shader = sp.emitter >= 0 ? -1 : accel.shaderOf(hit.instance, hit.prim);

    glm::vec3 pObject{0.0f}, nObject{0.0f}, shadingObject{0.0f};
    float objectMagnitude = 0.0f;  // largest |coordinate| of the primitive's data
    bool hasShadingNormal = false;
    if (shape.type == ShapeType::Sphere || shape.type == ShapeType::Box) {
        const glm::vec3 o = applyPoint(inst.worldToObject, ray.origin);
        const glm::vec3 d = applyVector(inst.worldToObject, ray.dir);
        const glm::vec3 p = o + hit.t * d;
        if (shape.type == ShapeType::Sphere) {
            // Re-projected onto the sphere: removes the error of o + t*d along the ray.
            objectMagnitude = maxAbs(shape.center) + shape.radius;
            nObject = glm::normalize(p - shape.center);
            pObject = shape.center + shape.radius * nObject;
            sp.uv = sphereUv(nObject);
        } else {
            objectMagnitude = std::max(maxAbs(shape.minPt), maxAbs(shape.maxPt));
            const BoxFace face = boxFaceHit(o, d, shape.minPt, shape.maxPt);
            const int axis = face.axis;
            pObject = p;
            pObject[axis] = face.maxSide ? shape.maxPt[axis] : shape.minPt[axis];  // snapped onto the face
            nObject[axis] = face.maxSide ? 1.0f : -1.0f;
            // Planar per-face mapping over the box's extent: the face of axis a maps (a+1, a+2) to (u, v).
            const int ua = (axis + 1) % 3;
            const int va = (axis + 2) % 3;
            sp.uv = {unitRange(pObject[ua], shape.minPt[ua], shape.maxPt[ua]),
                     unitRange(pObject[va], shape.minPt[va], shape.maxPt[va])};
        }
    } else {
        glm::vec3 v0 = shape.v0, v1 = shape.v1, v2 = shape.v2;
        const Mesh* mesh = nullptr;
        glm::uvec3 tri{0};
        if (shape.type == ShapeType::Mesh) {
            mesh = &scene.meshes[shape.mesh];
            tri = mesh->triangles[origin.triangle];
            v0 = mesh->positions[tri.x];
            v1 = mesh->positions[tri.y];
            v2 = mesh->positions[tri.z];
        }
        objectMagnitude = std::max(maxAbs(v0), std::max(maxAbs(v1), maxAbs(v2)));
        const float b1 = hit.u, b2 = hit.v, b0 = 1.0f - hit.u - hit.v;
        pObject = b0 * v0 + b1 * v1 + b2 * v2;
        nObject = glm::cross(v1 - v0, v2 - v0);
        sp.uv = {b1, b2};  // loose triangles: v0 -> (0,0), v1 -> (1,0), v2 -> (0,1)
        if (mesh) {
            if (!mesh->normals.empty()) {
                shadingObject = b0 * mesh->normals[tri.x] + b1 * mesh->normals[tri.y] + b2 * mesh->normals[tri.z];
                hasShadingNormal = true;
            }
            if (!mesh->uvs.empty()) sp.uv = b0 * mesh->uvs[tri.x] + b1 * mesh->uvs[tri.y] + b2 * mesh->uvs[tri.z];
        }
    }

    sp.position = applyPoint(inst.objectToWorld, pObject);
    sp.errorMagnitude = errorMagnitude(inst.objectToWorld, objectMagnitude, sp.position);
    sp.geometricNormal = unitVector(applyVector(inst.normalToWorld, nObject));
    sp.shadingNormal = sp.geometricNormal;
    if (hasShadingNormal) {
        const glm::vec3 n = applyVector(inst.normalToWorld, shadingObject);
        const float len2 = glm::dot(n, n);
        // Opposite vertex normals can cancel; the flat normal is the only meaningful answer then.
        if (len2 > 0.0f && std::isfinite(len2)) {
            sp.shadingNormal = glm::normalize(n);
            if (glm::dot(sp.shadingNormal, sp.geometricNormal) < 0.0f) sp.shadingNormal = -sp.shadingNormal;
        }
    }
    return sp;
}

}  // namespace vkrt::cpu
