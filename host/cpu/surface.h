// From a BVH hit to what shading needs: the world-space point, the normals and the texture
// coordinates, computed from the scene model's shape (docs/RENDERING.md §3 and §7).
#pragma once

#include <glm/glm.hpp>

#include "bvh.h"
#include "scene.h"
#include "scene_accel.h"

namespace vkrt::cpu {

struct SurfacePoint {
    glm::vec3 position{0.0f};         // world space, on the primitive (not yet offset)
    glm::vec3 geometricNormal{0.0f};  // unit, world space, the primitive's true outward side
    glm::vec3 shadingNormal{0.0f};    // unit, world space, on the same side as geometricNormal
    glm::vec2 uv{0.0f};
    int shader = 0;                   // index into Scene::shaders (not for an emitter's surface)
    int emitter = -1;                 // index into Scene::emitters when the hit is on a shape emitter
    float errorMagnitude = 0.0f;      // the largest world-space magnitude the hit point's computation
                                      // involved: it scales the ray offset (ray_offset.h, RENDERING.md §6)
};

// `ray` is the world-space ray that produced `hit` (its direction as traced, not renormalised).
SurfacePoint describeHit(const SceneAccel& accel, const Scene& scene, const bvh::Ray& ray, const bvh::Hit& hit);

struct BoxFace {
    int axis = 0;          // 0, 1, 2 = x, y, z
    bool maxSide = false;  // the face at hi[axis] (outward normal +axis), else at lo[axis]
};

// The face of the box [lo, hi] that the object-space ray o + t d hits (the box's slab test redone:
// the slab entered last from outside, or left first from inside; ties x before y before z).
BoxFace boxFaceHit(const glm::vec3& o, const glm::vec3& d, const glm::vec3& lo, const glm::vec3& hi);

}  // namespace vkrt::cpu
