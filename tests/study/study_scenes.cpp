#include "study_scenes.h"

#include <algorithm>
#include <cmath>

#include "diagnostics.h"
#include "scene_builder.h"
#include "scene_loader.h"
#include "test_paths.h"

namespace vkrt::test {

PixelScene edgePixelScene() {
    // Orthographic camera on +z looking down -z with a 1-unit image plane: the single pixel spans
    // x, y in [-0.5, 0.5] (RENDERING.md §1: u = +x, v = +y). The triangle covers everything below
    // the line y = 0.3 x + 0.1, which crosses the pixel from (-0.5, -0.05) to (0.5, 0.25), so the
    // area above it is the integral of 0.5 - (0.3 x + 0.1) over [-0.5, 0.5] = 0.4.
    PixelScene p;
    Scene& s = p.scene;
    s.cameras.push_back(orthographicCamera({0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, -1.0f}, 1.0f));
    s.background = glm::vec3(1.0f, 0.5f, 0.25f);
    // No lights: a Lambertian surface is exactly black.
    const int black = addShader(s, makeShader(ShaderType::Lambertian, glm::vec3(0.8f)));
    s.shapes.push_back(triangle({-10.0f, -2.9f, 0.0f}, {10.0f, 3.1f, 0.0f}, {0.0f, -50.0f, 0.0f}, black));
    p.expected = 0.4 * glm::dvec3(s.background);
    return p;
}

PixelScene penumbraPixelScene() {
    // Ground y = 0 (Lambertian kd), a 2x2 light at height 4 facing down (x, z in [-1, 1]), an opaque
    // quad at height 2 covering the half-plane x + z/2 > 0.2 (diagonal to the light's axes, so no
    // sampler gets an axis-aligned edge for free). The camera sees the ground at the origin through
    // a tiny footprint (1e-3 wide: the visible part of the light changes by ~1e-4 across it, and
    // linearly, so the pixel mean is the centre's value to second order). From the origin a light
    // point q is hidden when the segment crosses the quad: (q.x + q.z/2) / 2 > 0.2.
    constexpr double kd = 0.8, h = 4.0, occluderHeight = 2.0, e = 0.2;
    PixelScene p;
    Scene& s = p.scene;
    s.cameras.push_back(orthographicCamera({0.0f, 1.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 1e-3f));
    Light light;
    light.type = LightType::Area;
    light.position = glm::vec3(0.0f, static_cast<float>(h), 0.0f);
    light.normal = glm::vec3(0.0f, -1.0f, 0.0f);
    light.width = 2.0f;
    light.length = 2.0f;
    light.intensity = glm::vec3(1.0f);
    s.lights.push_back(light);
    const int ground = addShader(s, makeShader(ShaderType::Lambertian, glm::vec3(static_cast<float>(kd))));
    const int dark = addShader(s, makeShader(ShaderType::Lambertian, glm::vec3(0.1f)));
    Shape floor;
    floor.type = ShapeType::Box;
    floor.minPt = glm::vec3(-10.0f, -1.0f, -10.0f);
    floor.maxPt = glm::vec3(10.0f, 0.0f, 10.0f);
    floor.shader = ground;
    s.shapes.push_back(floor);
    // The half-plane's boundary x = e - z/2 runs from (e + 5, -10) to (e - 5, 10).
    const float ef = static_cast<float>(e), y = static_cast<float>(occluderHeight);
    s.shapes.push_back(triangle({ef + 5.0f, y, -10.0f}, {20.0f, y, -10.0f}, {20.0f, y, 10.0f}, dark));
    s.shapes.push_back(triangle({ef + 5.0f, y, -10.0f}, {20.0f, y, 10.0f}, {ef - 5.0f, y, 10.0f}, dark));

    // kd * I * mean over the light of visible(q) * N.L with N.L = h / |q|. Per column x the visible
    // z are [-1, min(1, 2 (2e - x))] (scaled by occluderHeight / h = 1/2), and the integral of
    // h / sqrt(x^2 + z^2 + h^2) over z is h * asinh(z / sqrt(x^2 + h^2)); the x integral is a
    // midpoint sum over 20000 columns (error ~1e-9, far below the tests' statistical tolerances).
    constexpr int n = 20000;
    const double scale = h / occluderHeight;
    double sum = 0.0;
    for (int a = 0; a < n; ++a) {
        const double x = -1.0 + 2.0 * (a + 0.5) / n;
        const double zTop = std::min(1.0, 2.0 * (scale * e - x));
        if (zTop <= -1.0) continue;
        const double r = std::sqrt(x * x + h * h);
        sum += h * (std::asinh(zTop / r) - std::asinh(-1.0 / r)) * (2.0 / n);
    }
    p.expected = glm::dvec3(kd * sum / 4.0);  // the light's area is 4
    return p;
}

Scene exampleScene(const std::string& name) {
    Diagnostics diagnostics;
    Scene scene = loadScene(sourceDir() + "/scenes/" + name + ".xml", LoadOptions{}, diagnostics);
    return scene;
}

}  // namespace vkrt::test
