// Helpers for the CPU reference tests (scenes are built with tests/common/scene_builder.h): a render that checks the basics
// every image must satisfy, and a double-precision camera so expected pixels are computed
// independently of the renderer.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "cpu_renderer.h"
#include "scene.h"
#include "scene_builder.h"

namespace vkrt::test {

// Renders (building the BVH) and checks what holds for every image: no sample was non-finite
// (RENDERING.md §8) and every pixel is finite.
Image renderChecked(const Scene& scene, const RenderOptions& options, RenderStats* stats = nullptr);

// ---- the camera in double precision (RENDERING.md §1), written independently of host/cpu ----
struct DRay {
    glm::dvec3 origin;
    glm::dvec3 dir;  // unit
};
struct DCamera {
    CameraType type;
    glm::dvec3 eye, u, v, w;
    double focal, planeWidth, planeHeight;
    int nx, ny;
};
DCamera makeDCamera(const Camera& camera, int width, int height);
// The ray through image position (x, y) in pixel units (x = i + sx, y = j + sy).
DRay dcameraRay(const DCamera& camera, double x, double y);

// ---- comparing pixels with a closed form ----
// What an analytic scene says about one ray: which surface it sees (-1 = none, any id otherwise,
// e.g. shape*8 + face) and the radiance.
struct Seen {
    int surface = -1;
    glm::dvec3 radiance{0.0};
};
using AnalyticScene = std::function<Seen(const DRay&)>;

// True when the analytic scene sees one surface over the whole pixel footprint (a 9x9 grid of
// rays, corners included): silhouettes and creases are excluded, since which side a ray near them
// falls on depends on rounding.
bool footprintIsClean(const DCamera& camera, const AnalyticScene& scene, int i, int j);

// The expected pixel: the mean of the analytic radiance over the pixel's own camera samples
// (sampling.h's camera dimension, the contract both renderers share).
glm::dvec3 expectedPixel(const DCamera& camera, const AnalyticScene& scene, const RenderOptions& options, int i, int j);

struct Agreement {
    int compared = 0;      // clean pixels
    double maxError = 0.0; // largest channel difference, linear radiance
    std::string worst;     // "pixel (i,j): got ..., expected ..."
};
Agreement compareWithClosedForm(const Image& image, const DCamera& camera, const AnalyticScene& scene,
                                const RenderOptions& options);

// ---- small double-precision geometry ----
// Nearest t > 0 of the ray and a sphere, if any.
std::optional<double> raySphere(const DRay& ray, glm::dvec3 centre, double radius);

}  // namespace vkrt::test
