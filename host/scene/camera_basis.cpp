#include "camera_basis.h"

#include <cmath>

namespace vkrt {

namespace {

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// In double: an up of 1e-30 or 1e30 (any length is allowed, as for viewDir) squares out of float's range.
glm::vec3 unit(const glm::vec3& v) { return glm::vec3(glm::normalize(glm::dvec3(v))); }

}  // namespace

glm::vec3 courseUp(const glm::vec3& gaze) {
    return std::fabs(glm::normalize(gaze).y) > kParallelToGaze ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
}

// The course's basis (Shirley's u = up x w, v = w x u) in float, the operations both renderers used
// before an up could be given, so a camera without one renders bit for bit as it did.
CameraBasis cameraBasis(const glm::vec3& gaze, const std::optional<glm::vec3>& up) {
    const glm::vec3 g = glm::normalize(gaze);
    CameraBasis b;
    b.w = -g;
    b.u = glm::normalize(glm::cross(up ? unit(*up) : courseUp(gaze), b.w));
    b.v = glm::cross(b.w, b.u);
    return b;
}

std::string upProblem(const glm::vec3& up) {
    if (!finite(up)) return "up vector must be finite";
    if (up == glm::vec3(0.0f)) return "up vector has zero length";
    return "";
}

std::string upProblem(const glm::vec3& up, const glm::vec3& gaze) {
    if (std::string p = upProblem(up); !p.empty()) return p;
    if (std::fabs(glm::dot(glm::dvec3(unit(up)), glm::normalize(glm::dvec3(gaze)))) > kParallelToGaze)
        return "up vector is parallel to the view direction, so it cannot say which way the image is up";
    return "";
}

}  // namespace vkrt
