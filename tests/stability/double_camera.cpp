#include "double_camera.h"

#include <cmath>

namespace vkrt::stability {

DoubleRay cameraRay(const Camera& camera, int width, int height, double x, double y) {
    const glm::dvec3 gaze = glm::normalize(glm::dvec3(camera.gaze));
    const glm::dvec3 w = -gaze;
    // The camera's own up, else (0,1,0), or (1,0,0) when looking straight up or down.
    const glm::dvec3 up = camera.up ? glm::dvec3(*camera.up)
                          : std::fabs(gaze.y) > 0.9999 ? glm::dvec3(1.0, 0.0, 0.0)
                                                       : glm::dvec3(0.0, 1.0, 0.0);
    const glm::dvec3 u = glm::normalize(glm::cross(up, w));
    const glm::dvec3 v = glm::cross(w, u);
    const double planeWidth = camera.imagePlaneWidth;
    const double planeHeight = planeWidth * height / width;
    const double a = planeWidth * (x / width - 0.5);
    const double b = planeHeight * (0.5 - y / height);
    const glm::dvec3 eye(camera.position);
    if (camera.type == CameraType::Orthographic) return {eye + a * u + b * v, -w};
    return {eye, glm::normalize(-double(camera.focalLength) * w + a * u + b * v)};
}

}  // namespace vkrt::stability
