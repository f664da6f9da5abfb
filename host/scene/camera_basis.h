// The camera's basis (docs/RENDERING.md §1), written once: the CPU reference (host/cpu/camera.cpp)
// and the GPU's frame constants (host/gpu/frame_params.cpp) both take it from here, and the loaders
// and --up refuse an up vector by the same test.
#pragma once

#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "scene.h"

namespace vkrt {

struct CameraBasis {
    glm::vec3 u, v, w;  // right, up, backward (w = -normalize(gaze)); orthonormal
};

// |cos| of the angle between the gaze and the up vector above which up is taken as parallel: the
// course's (0,1,0) gives way to the fallback, and a given up is refused. cross(up, w) is then
// still longer than 0.014, so u keeps float precision (RENDERING.md §1).
inline constexpr float kParallelToGaze = 0.9999f;

// The course's up, (0,1,0), or (1,0,0) when the gaze is parallel to it: a camera looking straight
// down or up shows world +x at the top of the image, as the 2022 course renderer whose renders of
// the straight-down scenes exist (RENDERING.md §1 has the evidence).
glm::vec3 courseUp(const glm::vec3& gaze);

// The basis of `gaze` with `up` (the camera's own, vkrt's addition), or courseUp when none is given.
// `up` must have passed upProblem.
CameraBasis cameraBasis(const glm::vec3& gaze, const std::optional<glm::vec3>& up = std::nullopt);
inline CameraBasis cameraBasis(const Camera& camera) { return cameraBasis(camera.gaze, camera.up); }

// Why `up` cannot orient any camera (zero or not finite), or "" (the --up flag, before a gaze is known).
std::string upProblem(const glm::vec3& up);
// Why `up` cannot orient a camera gazing along `gaze` (the above, or parallel to the gaze), or "".
std::string upProblem(const glm::vec3& up, const glm::vec3& gaze);

}  // namespace vkrt
