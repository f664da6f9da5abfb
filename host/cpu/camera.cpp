#include "camera.h"

#include <cmath>

#include "camera_basis.h"
#include "sampling.h"

namespace vkrt::cpu {

CameraFrame makeCameraFrame(const Camera& camera, int width, int height) {
    CameraFrame f;
    f.type = camera.type;
    f.eye = camera.position;
    const CameraBasis basis = cameraBasis(camera);  // shared with the GPU's frame constants
    f.u = basis.u;
    f.v = basis.v;
    f.w = basis.w;
    f.focalLength = camera.focalLength;
    f.planeWidth = camera.imagePlaneWidth;
    f.planeHeight = camera.imagePlaneWidth * static_cast<float>(height) / static_cast<float>(width);
    f.nx = width;
    f.ny = height;
    f.thinLens = camera.thinLens();
    f.focusDistance = camera.focusDistance;
    f.lensRadius = 0.5f * camera.aperture;
    return f;
}

bvh::Ray cameraRay(const CameraFrame& f, int i, int j, glm::vec2 sample, glm::vec2 lensSample) {
    const float a = f.planeWidth * ((static_cast<float>(i) + sample.x) / static_cast<float>(f.nx) - 0.5f);
    const float b = f.planeHeight * (0.5f - (static_cast<float>(j) + sample.y) / static_cast<float>(f.ny));
    bvh::Ray ray;
    if (f.type == CameraType::Perspective) {
        const glm::vec3 q = -f.focalLength * f.w + a * f.u + b * f.v;
        ray.origin = f.eye;
        ray.dir = glm::normalize(q);
        if (f.thinLens) {
            // q reaches the plane at distance focalLength along the gaze: scaled by D / f it ends on
            // the focus plane, which every lens point's ray then passes through.
            const glm::vec2 disk = sampling::concentricDisk(lensSample) * f.lensRadius;
            const glm::vec3 offset = disk.x * f.u + disk.y * f.v;
            ray.origin = f.eye + offset;
            // Scaled down to the larger of q and the offset before normalising: q * (D / f) at
            // D = 1e20 has a squared length past float's range, and normalize() gave a zero
            // direction (a background image). Either form is a positive multiple of the same vector.
            const float k = f.focusDistance / f.focalLength;
            ray.dir = k >= 1.0f ? glm::normalize(q - offset / k) : glm::normalize(q * k - offset);
        }
    } else {
        ray.origin = f.eye + a * f.u + b * f.v;
        ray.dir = -f.w;
        if (f.thinLens) {
            const glm::vec2 disk = sampling::concentricDisk(lensSample) * f.lensRadius;
            const glm::vec3 offset = disk.x * f.u + disk.y * f.v;
            ray.origin = ray.origin + offset;
            const float d = f.focusDistance;
            ray.dir = d >= 1.0f ? glm::normalize(-f.w - offset / d) : glm::normalize(-d * f.w - offset);
        }
    }
    return ray;
}

}  // namespace vkrt::cpu
