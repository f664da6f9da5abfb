// Rigid motion of instances (motion blur): the two poses of a moving instance decomposed once on
// the host into the record the kernels and the CPU traversal interpolate (gpu::InstanceMotion,
// shaders/shared/motion.h), and the world box that holds the instance over the whole motion.
#pragma once

#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "aabb.h"
#include "../shaders/shared/device_host.h"

namespace vkrt::bvh {

// Why start -> end cannot be interpolated, or nullopt: an entry not finite, not affine, a singular
// 3x3 part, or the two poses of opposite handedness (the stretch would pass through a singular
// matrix on the way). Loaders call it to report the problem at the element.
std::optional<std::string> motionProblem(const glm::mat4& start, const glm::mat4& end);

// The polar decomposition M = T * R * S of both poses (R a rotation, S symmetric; a mirroring
// pose keeps R proper and puts the sign in S), the rotations on the same quaternion hemisphere.
// Throws std::invalid_argument with motionProblem's text.
gpu::InstanceMotion decomposeMotion(const glm::mat4& start, const glm::mat4& end);

// A box holding objectBox placed by every pose of the motion in [0, 1]: the poses at 65 times
// (motion.h's float arithmetic), grown by the farthest any corner can move between two of them
// (half the step times a bound on its speed), plus worldBounds' rounding margin.
Aabb motionBounds(const Aabb& objectBox, const gpu::InstanceMotion& motion);

}  // namespace vkrt::bvh
