// Mirror, Glaze and BlinnPhongMirrored against a closed form: a tilted mirror plane reflects every
// camera ray straight up into a lit Lambertian ceiling, whose radiance at the reflected point is
// known exactly. Tolerance 1e-4 in linear radiance, as in closed_form_test.cpp (float geometry,
// ~1e-6 relative; a wrong reflection direction or blend formula is off by > 1e-2).
#include <cmath>
#include <cstdio>
#include <cstring>

#include <gtest/gtest.h>

#include "analytic_scene.h"

namespace vkrt::test {
namespace {

const glm::dvec3 kLight{0.0, 3.0, 10.0};
const glm::dvec3 kLightI{1.0, 0.95, 0.9};
const glm::dvec3 kCeilingKd{0.7, 0.5, 0.3};
const glm::dvec3 kBackground{0.25, 0.1, 0.05};

// The mirror is the plane y + z = 0 (normal (0,1,1)/sqrt2, facing the camera at +z), made of two
// triangles; the ceiling is the bottom face y = 5 of a large box; the light sits in front of both.
Scene mirrorScene(const Shader& mirrorShader) {
    Scene scene;
    scene.cameras.push_back(orthographicCamera({0, 0, 10}, {0, 0, -1}, 2.0f));
    scene.background = glm::vec3(kBackground);
    scene.lights.push_back(pointLight(glm::vec3(kLight), glm::vec3(kLightI)));
    const int mirror = addShader(scene, mirrorShader);
    const int ceiling = addShader(scene, makeShader(ShaderType::Lambertian, glm::vec3(kCeilingKd)));
    const glm::vec3 a(-3, -2.2f, 2.2f), b(3, -2.2f, 2.2f), c(3, 2.2f, -2.2f), d(-3, 2.2f, -2.2f);
    scene.shapes.push_back(triangle(a, b, c, mirror));
    scene.shapes.push_back(triangle(a, c, d, mirror));
    scene.shapes.push_back(box({-50, 5, -50}, {50, 6, 50}, ceiling));
    return scene;
}

// The ceiling's radiance where the mirror at p sends the ray (straight up to y = 5).
glm::dvec3 ceilingSeenFrom(const glm::dvec3& p) {
    const glm::dvec3 q(p.x, 5.0, p.z);
    const glm::dvec3 l = glm::normalize(kLight - q);
    return kCeilingKd * kLightI * std::max(0.0, glm::dot(glm::dvec3(0, -1, 0), l));
}

struct MirrorModel {
    ShaderType type;
    glm::dvec3 kd{0.0}, ks{0.0};
    double phongExp = 1.0, m = 0.0;
    int maxDepth = 4;

    Seen operator()(const DRay& ray) const {
        // Orthographic rays along -z hit the plane y + z = 0 at z = -y.
        const glm::dvec3 p(ray.origin.x, ray.origin.y, -ray.origin.y);
        const glm::dvec3 n = glm::normalize(glm::dvec3(0, 1, 1));
        const glm::dvec3 l = glm::normalize(kLight - p);
        const glm::dvec3 h = glm::normalize(l - ray.dir);
        const glm::dvec3 diffuse = kd * kLightI * std::max(0.0, glm::dot(n, l));
        const glm::dvec3 specular = ks * kLightI * std::pow(std::max(0.0, glm::dot(n, h)), phongExp);
        const glm::dvec3 r = maxDepth > 0 ? ceilingSeenFrom(p) : glm::dvec3(0.0);
        switch (type) {
        case ShaderType::Mirror: return {0, r};
        case ShaderType::Glaze: return {0, diffuse + m * r};
        case ShaderType::BlinnPhongMirrored: return {0, (1.0 - m) * (diffuse + specular) + m * r};
        default: return {0, glm::dvec3(-1.0)};
        }
    }
};

RenderOptions smallOptions(int maxDepth) {
    RenderOptions o;
    o.width = 32;
    o.height = 32;
    o.samplesPerPixel = 4;
    o.maxDepth = maxDepth;
    return o;
}

void expectMirrorModel(const Shader& shader, const MirrorModel& model, const char* name) {
    const Scene scene = mirrorScene(shader);
    const RenderOptions o = smallOptions(model.maxDepth);
    const Image image = renderChecked(scene, o);
    const Agreement a = compareWithClosedForm(image, makeDCamera(scene.cameras[0], o.width, o.height), model, o);
    std::printf("[reflection] %-40s %4d pixels, max error %.2e\n", name, a.compared, a.maxError);
    EXPECT_EQ(a.compared, o.width * o.height);
    EXPECT_LE(a.maxError, 1e-4) << a.worst;
}

TEST(Reflection, MirrorShowsTheCeiling) {
    expectMirrorModel(makeShader(ShaderType::Mirror), {ShaderType::Mirror}, "Mirror");
}

TEST(Reflection, MirrorAtMaxDepthZeroIsBlack) {
    // max-depth 0: no bounce at all, so R = 0 (not the background).
    MirrorModel model{ShaderType::Mirror};
    model.maxDepth = 0;
    expectMirrorModel(makeShader(ShaderType::Mirror), model, "Mirror, max-depth 0");
}

TEST(Reflection, GlazeAddsTheReflection) {
    Shader s = makeShader(ShaderType::Glaze, {0.2f, 0.3f, 0.1f});
    s.mirrorCoef = 0.6f;
    expectMirrorModel(s, {ShaderType::Glaze, {0.2, 0.3, 0.1}, {0, 0, 0}, 1.0, 0.6}, "Glaze = local + m R");
}

TEST(Reflection, BlinnPhongMirroredBlends) {
    Shader s = makeShader(ShaderType::BlinnPhongMirrored, {0.2f, 0.3f, 0.1f});
    s.specular = {0.4f, 0.4f, 0.4f};
    s.phongExp = 10.0f;
    s.mirrorCoef = 0.3f;
    expectMirrorModel(s, {ShaderType::BlinnPhongMirrored, {0.2, 0.3, 0.1}, {0.4, 0.4, 0.4}, 10.0, 0.3},
                      "BlinnPhongMirrored = (1-m) local + m R");
}

bool bitIdentical(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(glm::vec3)) == 0;
}

// A scene where reflections matter everywhere: a mirror sphere over a checker of coloured boxes.
Scene sphereOverBoxes(const Shader& sphereShader) {
    Scene scene;
    scene.cameras.push_back(perspectiveCamera({0, 2, 4}, {0, -0.5f, -1}, 1.0f, 0.6f));
    scene.background = {0.2f, 0.2f, 0.2f};
    scene.lights.push_back(pointLight({3, 6, 2}, {1, 1, 1}));
    const int shiny = addShader(scene, sphereShader);
    scene.shapes.push_back(sphere({0, 0.8f, -2}, 0.8f, shiny));
    for (int k = 0; k < 4; ++k) {
        const int s = addShader(scene, makeShader(ShaderType::Lambertian, {0.2f + 0.2f * k, 0.8f - 0.2f * k, 0.5f}));
        scene.shapes.push_back(box({-2.0f + k, -0.5f, -5}, {-1.0f + k, 0, 1}, s));
    }
    return scene;
}

TEST(Reflection, RoughnessZeroIsExactlyTheMirror) {
    RenderOptions o = smallOptions(4);
    o.samplesPerPixel = 9;
    const Image mirror = renderChecked(sphereOverBoxes(makeShader(ShaderType::Mirror)), o);

    // Glaze with kd = 0 and m = 1 is local (exactly 0) + 1 * R: the mirror, bit for bit.
    Shader glaze = makeShader(ShaderType::Glaze, glm::vec3(0.0f));
    glaze.mirrorCoef = 1.0f;
    EXPECT_TRUE(bitIdentical(mirror, renderChecked(sphereOverBoxes(glaze), o)));

    // Roughness 0 takes no gloss samples: asking for 4 of them changes nothing.
    RenderOptions manyGloss = o;
    manyGloss.glossSamples = 4;
    EXPECT_TRUE(bitIdentical(mirror, renderChecked(sphereOverBoxes(makeShader(ShaderType::Mirror)), manyGloss)));

    // ...while a rough mirror does differ (the comparison above can fail).
    Shader rough = makeShader(ShaderType::Mirror);
    rough.roughness = 0.2f;
    EXPECT_FALSE(bitIdentical(mirror, renderChecked(sphereOverBoxes(rough), o)));
}

}  // namespace
}  // namespace vkrt::test
