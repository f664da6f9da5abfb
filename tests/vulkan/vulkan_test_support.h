// What the Vulkan tests share: validated devices whose every validation message fails the test
// (the tiny scene and small-render options are tests/gpu/tiny_scene.h).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "context.h"
#include "gpu_ray_tracer.h"
#include "gpu_renderer.h"
#include "test_kernels.h"
#include "tiny_scene.h"
#include "validation_log.h"

namespace vkrt::test {

// Every test here runs with validation on. Objects made through this fixture are destroyed in
// TearDown, and then every validation message, including those sent during destruction, fails
// the test.
class VulkanTest : public ::testing::Test {
protected:
    Context& context(const ContextOptions& options = {});
    GpuRenderer& renderer(GpuRendererOptions options = {}, const GpuTestHooks& hooks = {});
    // A ray tracer over `scene` with validation on, its log watched; one per test (a second call
    // replaces the first).
    GpuRayTracer& rayTracer(const bvh::SceneBvh& scene, const GpuTestHooks& hooks = {});
    // Checks this log too in TearDown (objects the test owns itself must be gone by then).
    void watch(std::shared_ptr<const ValidationLog> log) { logs_.push_back(std::move(log)); }
    void TearDown() override;

private:
    std::unique_ptr<Context> context_;
    std::unique_ptr<GpuRenderer> renderer_;
    std::unique_ptr<GpuRayTracer> rayTracer_;
    std::vector<std::shared_ptr<const ValidationLog>> logs_;
};

// Two GPU images of one scene from differently compiled kernel variants (samples per dispatch,
// specialisation): bit for bit on lavapipe, where it is measured; on other drivers, whose compilers
// may round each variant differently, the project's CPU/GPU agreement rule (>= 99.5% of pixels
// within 2/255, mean difference <= 0.5/255), so a failure there is a real difference.
void expectSameGpuImage(const GpuRenderer& gpu, const Image& a, const Image& b, const std::string& what);

}  // namespace vkrt::test
