// Area lights: soft shadows converging to the analytic irradiance, and a 0x0 area light being a
// point light bit for bit (RENDERING.md §4).
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "analytic_scene.h"
#include "lights.h"
#include "sampling.h"

namespace vkrt::test {
namespace {

// ---- soft shadow of a square occluder ----
// Ground: the plane y = 0 (top of a box), Lambertian kd. Light: a 2x2 square at height 4 facing
// down. Occluder: a 1x1 square (two triangles) at height 2 under the light's centre. From a ground
// point p the occluder projects onto the light plane as the square [-1 - px, 1 - px] x [...] (scale
// 4/2 about p), so every ground point with |px|, |pz| < 2 is in the penumbra.
constexpr double kLightHeight = 4.0, kOccluderHeight = 2.0, kLightHalf = 1.0, kOccluderHalf = 0.5;
constexpr double kKd = 0.8;

// Integral of h / sqrt(x^2 + z^2 + h^2) over [x0,x1] x [z0,z1]: the Lambertian cosine to a point
// at height h over the rectangle. Antiderivative G with d2G/dxdz = 1/r (checked numerically when
// this test was written: 1.36486212 by the formula vs 1.36486216 by an 800x800 midpoint sum).
double cosineIntegral(double x0, double x1, double z0, double z1, double h) {
    if (x1 <= x0 || z1 <= z0) return 0.0;
    auto g = [h](double x, double z) {
        const double r = std::sqrt(x * x + z * z + h * h);
        return x * std::log(z + r) + z * std::log(x + r) - h * std::atan(x * z / (h * r));
    };
    return h * (g(x1, z1) - g(x0, z1) - g(x1, z0) + g(x0, z0));
}

// The exact mean over the light of kd * I * N.L * visibility, for the ground point (px, 0, pz).
double groundRadiance(double px, double pz) {
    const double scale = kLightHeight / kOccluderHeight;
    // Light and occluder shadow on the light plane, in coordinates relative to p.
    const double lx0 = -kLightHalf - px, lx1 = kLightHalf - px, lz0 = -kLightHalf - pz, lz1 = kLightHalf - pz;
    const double sx0 = scale * (-kOccluderHalf - px), sx1 = scale * (kOccluderHalf - px);
    const double sz0 = scale * (-kOccluderHalf - pz), sz1 = scale * (kOccluderHalf - pz);
    const double whole = cosineIntegral(lx0, lx1, lz0, lz1, kLightHeight);
    const double hidden = cosineIntegral(std::max(lx0, sx0), std::min(lx1, sx1), std::max(lz0, sz0),
                                         std::min(lz1, sz1), kLightHeight);
    const double area = 4.0 * kLightHalf * kLightHalf;
    return kKd * (whole - hidden) / area;
}

Scene softShadowScene() {
    Scene scene;
    // Looking straight down from below the occluder (so it never hides the ground from the camera);
    // the image spans x, z in [-2, 2], image up = -z.
    scene.cameras.push_back(orthographicCamera({0, 1, 0}, {0, -1, 0}, 4.0f));
    scene.lights.push_back(areaLight({0, float(kLightHeight), 0}, {0, -1, 0}, 2.0f * kLightHalf, 2.0f * kLightHalf,
                                     {1, 1, 1}));
    const int ground = addShader(scene, makeShader(ShaderType::Lambertian, glm::vec3(float(kKd))));
    const int dark = addShader(scene, makeShader(ShaderType::Lambertian, glm::vec3(0.1f)));
    scene.shapes.push_back(box({-10, -1, -10}, {10, 0, 10}, ground));
    const float h = float(kOccluderHeight), s = float(kOccluderHalf);
    scene.shapes.push_back(triangle({-s, h, -s}, {s, h, -s}, {s, h, s}, dark));
    scene.shapes.push_back(triangle({-s, h, -s}, {s, h, s}, {-s, h, s}, dark));
    return scene;
}

// RMS over all pixels of (rendered - exact), the exact value averaged over the pixel's own camera
// samples so that only the light sampling error remains.
double softShadowRmsError(int rpp) {
    const Scene scene = softShadowScene();
    RenderOptions o;
    o.width = 32;
    o.height = 32;
    o.samplesPerPixel = rpp;
    const Image image = renderChecked(scene, o);
    const DCamera cam = makeDCamera(scene.cameras[0], o.width, o.height);
    const AnalyticScene exact = [](const DRay& ray) {
        const double t = -ray.origin.y / ray.dir.y;
        const glm::dvec3 p = ray.origin + t * ray.dir;
        return Seen{0, glm::dvec3(groundRadiance(p.x, p.z))};
    };
    double sum2 = 0.0;
    for (int j = 0; j < o.height; ++j)
        for (int i = 0; i < o.width; ++i) {
            const double e = double(image.at(i, j).x) - expectedPixel(cam, exact, o, i, j).x;
            sum2 += e * e;
        }
    return std::sqrt(sum2 / (o.width * o.height));
}

TEST(AreaLight, AnalyticModelIsRight) {
    // The model's own sanity: full visibility far outside the penumbra equals the unoccluded
    // integral, and straight under the centre the occluder hides exactly the whole light.
    EXPECT_NEAR(groundRadiance(0.0, 0.0), 0.0, 1e-12);
    const double open = kKd * cosineIntegral(-1 - 3.0, 1 - 3.0, -1, 1, kLightHeight) / 4.0;
    EXPECT_NEAR(groundRadiance(3.0, 0.0), open, 1e-12);
    // Small light limit: the mean cosine over the light tends to h / |c - p|.
    EXPECT_NEAR(cosineIntegral(-1e-3, 1e-3, -1e-3, 1e-3, 2.0) / 4e-6, 1.0, 1e-6);
}

TEST(AreaLight, SoftShadowConvergesToTheAnalyticOcclusion) {
    const std::vector<int> rpps{1, 4, 16, 64, 256};
    std::vector<double> errors;
    for (int rpp : rpps) errors.push_back(softShadowRmsError(rpp));
    for (std::size_t k = 0; k < rpps.size(); ++k)
        std::printf("[area light] rpp %3d: RMS error vs analytic occlusion %.5f\n", rpps[k], errors[k]);
    for (std::size_t k = 1; k < rpps.size(); ++k) EXPECT_LT(errors[k], errors[k - 1]) << "rpp " << rpps[k];
    // Bound at rpp = n^2 = 256: the n x n light strata are each used once (jittered, shuffled
    // against the pixel strata). Only strata cut by the occluder's shadow edges (at most 2n + 2 of
    // n^2) have any variance, at most f^2/4 each with f <= kd = 0.8, so the RMS error is at most
    // sqrt((2n+2) f^2/4) / n^2 = 0.0091; the camera jitter moves the edge by up to one stratum
    // between samples, which at most doubles the number of cut strata: bound 2 x 0.0091.
    const double n = 16.0;
    const double bound = 2.0 * std::sqrt((2.0 * n + 2.0) * kKd * kKd / 4.0) / (n * n);
    EXPECT_LT(errors.back(), bound);
}

// ---- a 0x0 area light is a point light ----
Scene sphereOnGround(const Light& second) {
    Scene scene;
    scene.cameras.push_back(perspectiveCamera({0, 2, 3}, {0, -0.6f, -1}, 1.0f, 0.7f));
    scene.background = {0.2f, 0.2f, 0.2f};
    scene.lights.push_back(areaLight({-3, 5, 1}, {0.3f, -1, 0}, 1.5f, 0.8f, {0.5f, 0.5f, 0.6f}));
    scene.lights.push_back(second);
    Shader plastic = makeShader(ShaderType::BlinnPhong, {0.7f, 0.2f, 0.2f});
    plastic.specular = {0.5f, 0.5f, 0.5f};
    plastic.phongExp = 24.0f;
    const int red = addShader(scene, plastic);
    const int grey = addShader(scene, makeShader(ShaderType::Lambertian, {0.6f, 0.6f, 0.6f}));
    scene.shapes.push_back(sphere({0, 0.7f, -1}, 0.7f, red));
    scene.shapes.push_back(box({-10, -1, -10}, {10, 0, 10}, grey));
    return scene;
}

TEST(AreaLight, ZeroSizeIsExactlyAPointLight) {
    RenderOptions o;
    o.width = 40;
    o.height = 40;
    o.samplesPerPixel = 16;
    const glm::vec3 c(2.0f, 4.0f, 1.0f), intensity(0.8f, 0.7f, 0.6f);
    const Image point = renderChecked(sphereOnGround(pointLight(c, intensity)), o);
    const Image area = renderChecked(sphereOnGround(areaLight(c, {0, -1, 0}, 0.0f, 0.0f, intensity)), o);
    ASSERT_EQ(point.pixels.size(), area.pixels.size());
    EXPECT_EQ(std::memcmp(point.pixels.data(), area.pixels.data(), point.pixels.size() * sizeof(glm::vec3)), 0);
    // ...and a light of real size gives a different image, so the comparison can fail.
    const Image big = renderChecked(sphereOnGround(areaLight(c, {0, -1, 0}, 2.0f, 2.0f, intensity)), o);
    EXPECT_NE(std::memcmp(point.pixels.data(), big.pixels.data(), point.pixels.size() * sizeof(glm::vec3)), 0);
}

TEST(AreaLight, RectangleConvention) {
    // RENDERING.md §4: for the usual downward normal, width runs along +x and length along +z;
    // the sample (su, sv) maps to c + (su - 1/2) width T + (sv - 1/2) length B.
    Scene scene;
    scene.lights.push_back(areaLight({1, 5, -2}, {0, -1, 0}, 4.0f, 2.0f, {1, 1, 1}));
    const auto lights = cpu::makeLightSources(scene);
    ASSERT_EQ(lights.size(), 1u);
    const glm::vec3 widthEnd = cpu::lightPoint(lights[0], {1.0f, 0.5f});
    const glm::vec3 lengthEnd = cpu::lightPoint(lights[0], {0.5f, 1.0f});
    EXPECT_EQ(widthEnd, glm::vec3(3, 5, -2));
    EXPECT_EQ(lengthEnd, glm::vec3(1, 5, -1));
    // A normal along z uses the x axis to build the tangent: T = normalize(x cross n).
    Scene facing;
    facing.lights.push_back(areaLight({0, 0, 0}, {0, 0, 1}, 2.0f, 2.0f, {1, 1, 1}));
    const glm::vec3 t = cpu::lightPoint(cpu::makeLightSources(facing)[0], {1.0f, 0.5f});
    EXPECT_NEAR(t.y, -1.0f, 1e-6f);  // cross((1,0,0), (0,0,1)) = (0,-1,0)
    EXPECT_NEAR(t.x, 0.0f, 1e-6f);
}

}  // namespace
}  // namespace vkrt::test
