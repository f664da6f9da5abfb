// Primary rays: the camera basis and the pixel -> ray mapping of docs/RENDERING.md §1.
#pragma once

#include <glm/glm.hpp>

#include "bvh.h"
#include "scene.h"

namespace vkrt::cpu {

struct CameraFrame {
    CameraType type = CameraType::Perspective;
    glm::vec3 eye{0.0f};
    glm::vec3 u{1.0f, 0.0f, 0.0f}, v{0.0f, 1.0f, 0.0f}, w{0.0f, 0.0f, 1.0f};  // right, up, backward
    float focalLength = 1.0f;
    float planeWidth = 0.5f;
    float planeHeight = 0.5f;  // planeWidth * ny / nx
    int nx = 1, ny = 1;
};

CameraFrame makeCameraFrame(const Camera& camera, int width, int height);

// The ray through pixel (i, j) (j = 0 the top row) at sub-pixel position `sample` in [0,1)^2.
// The direction is unit length, so hit distances are world distances.
bvh::Ray cameraRay(const CameraFrame& frame, int i, int j, glm::vec2 sample);

}  // namespace vkrt::cpu
