#include "analytic_scene.h"

#include <cmath>
#include <sstream>

#include <gtest/gtest.h>

#include "sampling.h"
#include "cpu_renderer.h"
#include "scene_accel.h"

namespace vkrt::test {

Image renderChecked(const Scene& scene, const RenderOptions& options, RenderStats* stats) {
    const SceneAccel accel = prepareCpuScene(scene);
    RenderStats local;
    RenderOptions quiet = options;
    quiet.quiet = true;
    Image image = renderCpu(scene, accel, quiet, &local);
    EXPECT_EQ(local.nonFiniteSamples, 0u) << "a sample produced NaN or Inf (RENDERING.md §8)";
    EXPECT_EQ(countNonFinite(image), 0u);
    if (stats) *stats = local;
    return image;
}

DCamera makeDCamera(const Camera& camera, int width, int height) {
    DCamera c;
    c.type = camera.type;
    c.eye = glm::dvec3(camera.position);
    const glm::dvec3 g = glm::normalize(glm::dvec3(camera.gaze));
    c.w = -g;
    // The camera's own up, else (0,1,0), or (1,0,0) when looking straight up or down.
    const glm::dvec3 up = camera.up ? glm::dvec3(*camera.up) : std::abs(g.y) > 0.9999 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    c.u = glm::normalize(glm::cross(up, c.w));
    c.v = glm::cross(c.w, c.u);
    c.focal = camera.focalLength;
    c.planeWidth = camera.imagePlaneWidth;
    c.planeHeight = camera.imagePlaneWidth * double(height) / double(width);
    c.nx = width;
    c.ny = height;
    return c;
}

DRay dcameraRay(const DCamera& c, double x, double y) {
    const double a = c.planeWidth * (x / c.nx - 0.5);
    const double b = c.planeHeight * (0.5 - y / c.ny);
    if (c.type == CameraType::Orthographic) return {c.eye + a * c.u + b * c.v, -c.w};
    return {c.eye, glm::normalize(-c.focal * c.w + a * c.u + b * c.v)};
}

bool footprintIsClean(const DCamera& camera, const AnalyticScene& scene, int i, int j) {
    constexpr int kGrid = 9;
    const int first = scene(dcameraRay(camera, i, j)).surface;
    for (int y = 0; y < kGrid; ++y)
        for (int x = 0; x < kGrid; ++x)
            if (scene(dcameraRay(camera, i + x / double(kGrid - 1), j + y / double(kGrid - 1))).surface != first)
                return false;
    return true;
}

glm::dvec3 expectedPixel(const DCamera& camera, const AnalyticScene& scene, const RenderOptions& options, int i, int j) {
    const auto rpp = static_cast<std::uint32_t>(options.samplesPerPixel);
    const glm::uvec4 grid = sampling::makeSampleGrid(rpp);
    const std::uint32_t pixel = static_cast<std::uint32_t>(j * camera.nx + i);
    glm::dvec3 sum(0.0);
    for (std::uint32_t s = 0; s < rpp; ++s) {
        const glm::vec2 o = sampling::sample2D(static_cast<std::uint32_t>(options.sampler), grid, pixel, s, sampling::DIM_CAMERA,
                                          options.seed);
        sum += scene(dcameraRay(camera, i + double(o.x), j + double(o.y))).radiance;
    }
    return sum / double(rpp);
}

Agreement compareWithClosedForm(const Image& image, const DCamera& camera, const AnalyticScene& scene,
                                const RenderOptions& options) {
    Agreement a;
    for (int j = 0; j < image.height; ++j)
        for (int i = 0; i < image.width; ++i) {
            if (!footprintIsClean(camera, scene, i, j)) continue;
            ++a.compared;
            const glm::dvec3 want = expectedPixel(camera, scene, options, i, j);
            const glm::dvec3 got(image.at(i, j));
            const glm::dvec3 diff = glm::abs(got - want);
            const double err = std::max(diff.x, std::max(diff.y, diff.z));
            if (err > a.maxError) {
                a.maxError = err;
                std::ostringstream s;
                s << "pixel (" << i << "," << j << "): got (" << got.x << "," << got.y << "," << got.z
                  << "), expected (" << want.x << "," << want.y << "," << want.z << ")";
                a.worst = s.str();
            }
        }
    return a;
}

std::optional<double> raySphere(const DRay& ray, glm::dvec3 centre, double radius) {
    const glm::dvec3 f = ray.origin - centre;
    const double b = glm::dot(f, ray.dir);
    const double c = glm::dot(f, f) - radius * radius;
    const double disc = b * b - c;  // dir is unit
    if (disc < 0.0) return std::nullopt;
    const double root = std::sqrt(disc);
    const double t0 = -b - root, t1 = -b + root;
    if (t0 > 0.0) return t0;
    if (t1 > 0.0) return t1;
    return std::nullopt;
}

}  // namespace vkrt::test
