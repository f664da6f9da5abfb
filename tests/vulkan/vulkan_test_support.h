// What the Vulkan tests share: validated devices whose every validation message fails the test,
// a tiny scene that needs no BVH builder, and the options of small renders.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "context.h"
#include "gpu_ray_tracer.h"
#include "gpu_renderer.h"
#include "render_options.h"
#include "scene.h"
#include "scene_accel.h"
#include "test_kernels.h"
#include "validation_log.h"

namespace vkrt::test {

// Every test here runs with validation on. Objects made through this fixture are destroyed in
// TearDown, and then every validation message, including those sent during destruction, fails
// the test.
class VulkanTest : public ::testing::Test {
protected:
    Context& context(const ContextOptions& options = {});
    GpuRenderer& renderer(GpuRendererOptions options = {});
    // A ray tracer over `scene` with validation on, its log watched; one per test (a second call
    // replaces the first).
    GpuRayTracer& rayTracer(const bvh::SceneBvh& scene, GpuRendererOptions options = {});
    // Checks this log too in TearDown (objects the test owns itself must be gone by then).
    void watch(std::shared_ptr<const ValidationLog> log) { logs_.push_back(std::move(log)); }
    void TearDown() override;

private:
    std::unique_ptr<Context> context_;
    std::unique_ptr<GpuRenderer> renderer_;
    std::unique_ptr<GpuRayTracer> rayTracer_;
    std::vector<std::shared_ptr<const ValidationLog>> logs_;
};

// A scene with one camera, one sphere, one point light and one Lambertian shader, and its
// acceleration structure built by hand (one bottom-level node, one identity instance, one
// top-level node). Not movable: the accel points into the scene.
struct TinyScene {
    Scene scene;
    SceneAccel accel;
    TinyScene();
    TinyScene(const TinyScene&) = delete;
    TinyScene& operator=(const TinyScene&) = delete;
};

RenderOptions smallRender(int width, int height, int samples);

}  // namespace vkrt::test
