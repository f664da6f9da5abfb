// Whole-image properties: the same bits for any thread count, cancellation, option errors, and
// no non-finite sample in a scene that uses every feature.
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "analytic_scene.h"
#include "cpu_renderer.h"
#include "scene_accel.h"

namespace vkrt::test {
namespace {

// Every shader type, every shape type, both light types, a texture and an instance.
Scene everything() {
    Scene scene;
    scene.cameras.push_back(perspectiveCamera({0, 2.5f, 5}, {0, -0.45f, -1}, 1.0f, 0.8f));
    scene.background = {0.2f, 0.25f, 0.3f};
    scene.lights.push_back(pointLight({-4, 6, 3}, {0.7f, 0.7f, 0.7f}));
    scene.lights.push_back(areaLight({3, 5, 0}, {-0.3f, -1, 0}, 2.0f, 1.0f, {0.6f, 0.5f, 0.4f}));

    Texture tex;
    tex.width = 4;
    tex.height = 4;
    for (int k = 0; k < 16; ++k) tex.rgba8.push_back(((k + k / 4) % 2) ? 0xff2040e0u : 0xffe0e0e0u);
    scene.textures.push_back(tex);

    Shader floor = makeShader(ShaderType::BlinnPhongMirrored, {0.5f, 0.5f, 0.5f});
    floor.specular = {0.3f, 0.3f, 0.3f};
    floor.phongExp = 8.0f;
    floor.mirrorCoef = 0.3f;
    floor.roughness = 0.2f;
    floor.diffuseTexture = 0;
    Shader glass = makeShader(ShaderType::Dielectric);
    glass.refractiveIndex = 1.5f;
    glass.attenuation = {0.9f, 0.95f, 0.8f};
    Shader glaze = makeShader(ShaderType::Glaze, {0.1f, 0.3f, 0.1f});
    glaze.mirrorCoef = 0.5f;
    Shader plastic = makeShader(ShaderType::BlinnPhong, {0.8f, 0.2f, 0.1f});
    plastic.specular = {1, 1, 1};
    plastic.phongExp = 32.0f;
    const int sFloor = addShader(scene, floor);
    const int sGlass = addShader(scene, glass);
    const int sMirror = addShader(scene, makeShader(ShaderType::Mirror));
    const int sGlaze = addShader(scene, glaze);
    const int sPlastic = addShader(scene, plastic);
    const int sGooch = addShader(scene, makeShader(ShaderType::CoolToWarm, {0.2f, 0.6f, 0.3f}));

    scene.shapes.push_back(box({-6, -1, -8}, {6, 0, 3}, sFloor));
    scene.shapes.push_back(sphere({-1.2f, 0.8f, -1}, 0.8f, sGlass));
    scene.shapes.push_back(sphere({1.0f, 0.6f, -2}, 0.6f, sMirror));
    scene.shapes.push_back(box({-0.4f, 0, -3.5f}, {0.6f, 1.2f, -2.5f}, sGlaze));
    scene.shapes.push_back(triangle({-3, 0, -4}, {-1.5f, 2.5f, -4.5f}, {-2.5f, 0, -2.5f}, sPlastic));

    Mesh mesh;  // a small tetrahedron with per-vertex normals
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    mesh.normals = {glm::normalize(glm::vec3(-1, -1, -1)), glm::normalize(glm::vec3(1, -0.3f, -0.3f)),
                    glm::normalize(glm::vec3(-0.3f, 1, -0.3f)), glm::normalize(glm::vec3(-0.3f, -0.3f, 1))};
    mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    scene.meshes.push_back(mesh);
    Shape tetra;
    tetra.type = ShapeType::Mesh;
    tetra.mesh = 0;
    tetra.shader = sGooch;
    scene.prototypes.push_back(tetra);
    Instance inst;
    inst.prototype = 0;
    inst.objectToWorld = glm::translate(glm::mat4(1.0f), glm::vec3(2.2f, 0.0f, -0.5f)) *
                         glm::rotate(glm::mat4(1.0f), glm::radians(25.0f), glm::vec3(0, 1, 0)) *
                         glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, 1.4f, 0.8f));
    scene.instances.push_back(inst);
    return scene;
}

RenderOptions everythingOptions(int threads) {
    RenderOptions o;
    o.width = 48;
    o.height = 40;  // not a multiple of the 16-pixel tiles
    o.samplesPerPixel = 4;
    o.lightSamples = 2;
    o.glossSamples = 2;
    o.threads = threads;
    return o;
}

TEST(Determinism, SameBitsForAnyThreadCount) {
    const Scene scene = everything();
    RenderStats stats;
    const Image one = renderChecked(scene, everythingOptions(1), &stats);
    std::printf("[determinism] 48x40x4: %.3f s on 1 thread; rays: %llu camera, %llu shadow, %llu reflection, "
                "%llu refraction\n",
                stats.seconds, (unsigned long long)stats.cameraRays, (unsigned long long)stats.shadowRays,
                (unsigned long long)stats.reflectionRays, (unsigned long long)stats.refractionRays);
    EXPECT_EQ(stats.cameraRays, 48u * 40u * 4u);
    EXPECT_GT(stats.shadowRays, 0u);
    EXPECT_GT(stats.reflectionRays, 0u);
    EXPECT_GT(stats.refractionRays, 0u);
    for (int threads : {2, 7}) {
        RenderStats s;
        const Image other = renderChecked(scene, everythingOptions(threads), &s);
        EXPECT_EQ(s.threads, threads);
        EXPECT_EQ(std::memcmp(one.pixels.data(), other.pixels.data(), one.pixels.size() * sizeof(glm::vec3)), 0)
            << threads << " threads";
        EXPECT_EQ(s.shadowRays, stats.shadowRays);
    }
}

TEST(Determinism, SeedChangesTheNoiseOnly) {
    const Scene scene = everything();
    RenderOptions a = everythingOptions(2), b = everythingOptions(2);
    b.seed = 12345;
    const Image ia = renderChecked(scene, a), ib = renderChecked(scene, b);
    double meanDiff = 0.0;
    bool anyDifferent = false;
    for (std::size_t k = 0; k < ia.pixels.size(); ++k) {
        const glm::vec3 d = ia.pixels[k] - ib.pixels[k];
        anyDifferent = anyDifferent || d != glm::vec3(0.0f);
        meanDiff += (d.x + d.y + d.z) / 3.0;
    }
    meanDiff /= double(ia.pixels.size());
    EXPECT_TRUE(anyDifferent);
    EXPECT_LT(std::fabs(meanDiff), 0.01);  // different samples of the same image, not a different image
}

TEST(Determinism, CancelThrows) {
    const Scene scene = everything();
    const SceneAccel accel = prepareCpuScene(scene);
    std::atomic<bool> cancel{true};
    RenderOptions o = everythingOptions(2);
    o.quiet = true;
    o.cancel = &cancel;
    EXPECT_THROW(renderCpu(scene, accel, o), RenderCancelled);
}

TEST(Determinism, BadOptionsAreRejectedWithTheirValue) {
    const Scene scene = everything();
    const SceneAccel accel = prepareCpuScene(scene);
    auto expectError = [&](RenderOptions o, const std::string& fragment) {
        o.quiet = true;
        try {
            renderCpu(scene, accel, o);
            ADD_FAILURE() << "no error for " << fragment;
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
        }
    };
    RenderOptions o = everythingOptions(1);
    o.samplesPerPixel = 0;
    expectError(o, "samples per pixel = 0");
    o = everythingOptions(1);
    o.width = -3;
    expectError(o, "width = -3");
    o = everythingOptions(1);
    o.camera = 2;
    expectError(o, "camera 2");
    o = everythingOptions(1);
    o.maxDepth = -1;
    expectError(o, "max depth = -1");
}

TEST(Determinism, BackgroundOptionOverridesTheScene) {
    Scene scene = everything();
    scene.shapes.clear();
    scene.instances.clear();
    RenderOptions o = everythingOptions(1);
    o.background = glm::vec3(50.0f / 255.0f);
    const Image image = renderChecked(scene, o);
    for (const glm::vec3& p : image.pixels) EXPECT_NEAR(p.x, 50.0f / 255.0f, 1e-6f);
}

}  // namespace
}  // namespace vkrt::test
