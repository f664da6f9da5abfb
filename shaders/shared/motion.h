// A moving instance's pose at a time of the shutter, for the CPU reference and the GLSL kernels
// alike (this file is valid C++ and valid GLSL): one definition, so both devices place a moving
// instance with the same float operations (docs/RENDERING.md §9). Not bit for bit: the GPU may
// fuse multiply-adds and its sin() is less exact, so the poses agree to rounding.
//
// The pose at time u in [0, 1] is M(u) = T(u) * R(u) * S(u) with T and S interpolated linearly and
// R by quaternion slerp between the two poses bvh_builder/instance_motion.h decomposed on the host.
// The inverse and the normal matrix come from the cofactors of L = R * S (rows a, b, c:
// L^-1 = [b x c, c x a, a x b] / det as columns), so nothing iterates and nothing branches on data
// but slerp's near-equal case.
#ifndef VKRT_MOTION_H
#define VKRT_MOTION_H

#ifdef __cplusplus
#include <glm/glm.hpp>
#include "device_host.h"
namespace vkrt::motion {
using glm::clamp;
using glm::cross;
using glm::dot;
using glm::mix;
using glm::normalize;
using glm::sin;
using gpu::Instance;
using gpu::InstanceMotion;
using gpu::vec3;
using gpu::vec4;
#endif

// Slerp between unit quaternions on the same side (dot >= 0); the host gives the angle between
// them and 1 / sin(angle), or 0 where they are too close for slerp's division (normalised lerp
// then differs from slerp by far less than float's rounding of the rotation). The result is
// normalised: Vulkan lets sin() err by 2^-11 absolute, which 1 / sin(angle) (up to 1000) would
// turn into a quaternion off unit length, i.e. a rotation that also stretches.
VKRT_FN vec4 slerpRotation(vec4 q0, vec4 q1, float angle, float invSinAngle, float u) {
    if (invSinAngle == 0.0f) return normalize(mix(q0, q1, u));
    return normalize((sin((1.0f - u) * angle) * q0 + sin(u * angle) * q1) * invSinAngle);
}

// The instance record `still` (root, material, group in info) placed at time u of its motion:
// the three matrices as Instance holds them.
VKRT_FN Instance instanceAtTime(Instance still, InstanceMotion m, float time) {
    float u = clamp(time, 0.0f, 1.0f);
    vec3 t = mix(vec3(m.translation0.x, m.translation0.y, m.translation0.z),
                 vec3(m.translation1.x, m.translation1.y, m.translation1.z), u);
    vec4 q = slerpRotation(m.rotation0, m.rotation1, m.translation0.w, m.translation1.w, u);
    vec3 s0 = mix(vec3(m.stretch0[0].x, m.stretch0[0].y, m.stretch0[0].z), vec3(m.stretch1[0].x, m.stretch1[0].y, m.stretch1[0].z), u);
    vec3 s1 = mix(vec3(m.stretch0[1].x, m.stretch0[1].y, m.stretch0[1].z), vec3(m.stretch1[1].x, m.stretch1[1].y, m.stretch1[1].z), u);
    vec3 s2 = mix(vec3(m.stretch0[2].x, m.stretch0[2].y, m.stretch0[2].z), vec3(m.stretch1[2].x, m.stretch1[2].y, m.stretch1[2].z), u);
    // Rows of R from q = (x, y, z, w).
    float x = q.x, y = q.y, z = q.z, w = q.w;
    vec3 r0 = vec3(1.0f - 2.0f * (y * y + z * z), 2.0f * (x * y - w * z), 2.0f * (x * z + w * y));
    vec3 r1 = vec3(2.0f * (x * y + w * z), 1.0f - 2.0f * (x * x + z * z), 2.0f * (y * z - w * x));
    vec3 r2 = vec3(2.0f * (x * z - w * y), 2.0f * (y * z + w * x), 1.0f - 2.0f * (x * x + y * y));
    // Rows of L = R * S.
    vec3 a = r0.x * s0 + r0.y * s1 + r0.z * s2;
    vec3 b = r1.x * s0 + r1.y * s1 + r1.z * s2;
    vec3 c = r2.x * s0 + r2.y * s1 + r2.z * s2;
    vec3 bc = cross(b, c), ca = cross(c, a), ab = cross(a, b);
    float invDet = 1.0f / dot(a, bc);
    bc = bc * invDet;
    ca = ca * invDet;
    ab = ab * invDet;
    // L^-1 has columns bc, ca, ab: its rows take one component of each.
    vec3 i0 = vec3(bc.x, ca.x, ab.x);
    vec3 i1 = vec3(bc.y, ca.y, ab.y);
    vec3 i2 = vec3(bc.z, ca.z, ab.z);
    Instance posed = still;
    posed.objectToWorld[0] = vec4(a.x, a.y, a.z, t.x);
    posed.objectToWorld[1] = vec4(b.x, b.y, b.z, t.y);
    posed.objectToWorld[2] = vec4(c.x, c.y, c.z, t.z);
    posed.worldToObject[0] = vec4(i0.x, i0.y, i0.z, -dot(i0, t));
    posed.worldToObject[1] = vec4(i1.x, i1.y, i1.z, -dot(i1, t));
    posed.worldToObject[2] = vec4(i2.x, i2.y, i2.z, -dot(i2, t));
    // The normal matrix (L^-1)^T: its rows are L^-1's columns.
    posed.normalToWorld[0] = vec4(bc.x, bc.y, bc.z, 0.0f);
    posed.normalToWorld[1] = vec4(ca.x, ca.y, ca.z, 0.0f);
    posed.normalToWorld[2] = vec4(ab.x, ab.y, ab.z, 0.0f);
    return posed;
}

#ifdef __cplusplus
}  // namespace vkrt::motion
#endif

#endif  // VKRT_MOTION_H
