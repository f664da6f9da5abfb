// The camera of RENDERING.md §1 in double precision, written independently of the renderers, for
// tests that compute expected pixels in closed form.
#pragma once

#include <glm/glm.hpp>

#include "scene.h"

namespace vkrt::stability {

struct DoubleRay {
    glm::dvec3 origin;
    glm::dvec3 dir;  // unit
};

// The ray through image position (x, y) in pixel units (the pixel centre is (i + 0.5, j + 0.5)).
DoubleRay cameraRay(const Camera& camera, int width, int height, double x, double y);

}  // namespace vkrt::stability
