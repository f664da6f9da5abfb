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
    bool thinLens = false;     // Camera::thinLens(): rays leave a disc and meet on the focus plane
    float focusDistance = 0.0f;
    float lensRadius = 0.0f;   // aperture / 2
};

CameraFrame makeCameraFrame(const Camera& camera, int width, int height);

// The ray through pixel (i, j) (j = 0 the top row) at sub-pixel position `sample` in [0,1)^2; with
// a thin lens, from the lens point `lensSample` in [0,1)^2 (concentric-mapped onto the disc) towards
// where the pinhole ray meets the focus plane. The direction is unit length, so hit distances are
// world distances. The GLSL kernel (shaders/camera.glsl) performs the same float operations.
bvh::Ray cameraRay(const CameraFrame& frame, int i, int j, glm::vec2 sample, glm::vec2 lensSample = glm::vec2(0.5f));

}  // namespace vkrt::cpu
