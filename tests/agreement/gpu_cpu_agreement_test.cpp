// The GPU kernel (lavapipe here) against the CPU reference at equal seeds, on every scene users
// have: all of ../shared/scenes/upstream and our scenes/ at 64x64, and scenes covering area lights,
// gloss, dielectrics, instances, meshes and textures at 256x256 with 16 rpp.
//
// The rule and the rendering are agreement_support.h's.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "agreement_support.h"
#include "gpu_renderer.h"
#include "node_packing.h"
#include "scene_loader.h"
#include "test_paths.h"

namespace vkrt::test {
namespace {

// One test over all files rather than one per file: each ctest entry would start a process and a
// validated Vulkan device, which costs more than the renders.
TEST(GpuCpuAgreement, EveryUpstreamAndBundledSceneAt64x64) {
    VKRT_SKIP_WITHOUT(upstreamDir());
    std::vector<std::string> paths = scenesIn(upstreamDir());
    ASSERT_EQ(paths.size(), 54u) << upstreamDir();
    const std::vector<std::string> ours = scenesIn(sourceDir() + "/scenes");
    ASSERT_GE(ours.size(), 3u);
    paths.insert(paths.end(), ours.begin(), ours.end());
    for (const std::string& path : paths) {
        SCOPED_TRACE(path);
        try {
            renderBothAndCompare(path, small(64, 4));
        } catch (const std::exception& e) {
            ADD_FAILURE() << path << ": " << e.what();
        }
    }
}

// The agreement above exercises the inlined world group (node_packing.h, InlinedWorld) on every
// upstream scene that has both loose shapes and instances: scene_accel.cpp builds each such scene
// in the shape the inlining needs, and a change there would silently fall back to the instance step.
TEST(GpuCpuAgreement, UpstreamScenesWithLooseShapesAndInstancesWalkTheirWorldInline) {
    VKRT_SKIP_WITHOUT(upstreamDir());
    int mixed = 0;
    for (const std::string& path : scenesIn(upstreamDir())) {
        Diagnostics diagnostics;
        const Scene scene = loadScene(path, LoadOptions{}, diagnostics);
        bool loose = false;
        for (const Shape& shape : scene.shapes) loose |= shape.type != ShapeType::Mesh;
        if (!loose || scene.instances.empty()) continue;
        ++mixed;
        EXPECT_TRUE(inlinedWorld(GpuRenderer::prepare(scene).accel.bvh).inlined) << path;
    }
    EXPECT_EQ(mixed, 13);
}

// `vkrt --general-kernel`: every feature compiled in, whatever the scene uses. Its untaken paths
// (instances in a scene without them, the instance step beside the inlined world group, spheres
// in a triangle scene) must not change the image. Smaller than the specialised test above: one
// pipeline serves every scene, and the specialised kernels already cover each path that is used.
TEST(GpuCpuAgreement, TheGeneralKernelOnEveryUpstreamAndBundledScene) {
    VKRT_SKIP_WITHOUT(upstreamDir());
    std::vector<std::string> paths = scenesIn(upstreamDir());
    ASSERT_EQ(paths.size(), 54u) << upstreamDir();
    const std::vector<std::string> ours = scenesIn(sourceDir() + "/scenes");
    paths.insert(paths.end(), ours.begin(), ours.end());
    for (const std::string& path : paths) {
        SCOPED_TRACE(path);
        try {
            renderBothAndCompare(path, small(48, 4), KernelVariant::General);
        } catch (const std::exception& e) {
            ADD_FAILURE() << path << ": " << e.what();
        }
    }
}

// Several gloss and light samples per pixel sample: the only settings where one hit emits more
// than one reflected ray (the path stack, integrator.glsl) and an area light takes several
// shadow rays per sample. A lost or repeated gloss ray changes every glossy reflection.
TEST(GpuCpuAgreement, GlossAndLightSampleFanOut) {
    VKRT_SKIP_WITHOUT(upstreamDir());
    RenderOptions options = small(128, 4);
    options.glossSamples = 4;
    options.lightSamples = 4;
    renderBothAndCompare(upstreamDir() + "/glossinessTest.xml", options);
    renderBothAndCompare(upstreamDir() + "/threeEggs_SoftShadows.xml", options);
}

// 256x256 at 16 rpp (the instructor's sampling), one scene per feature the kernel specialises on.
class GpuCpuAgreementLarge : public ::testing::TestWithParam<const char*> {};

TEST_P(GpuCpuAgreementLarge, At256x256With16Rpp) {
    VKRT_SKIP_WITHOUT(upstreamDir());
    const std::string name = GetParam();
    const std::string path = name.rfind("scenes/", 0) == 0 ? sourceDir() + "/" + name : upstreamDir() + "/" + name;
    renderBothAndCompare(path, small(256, 16));
}

INSTANTIATE_TEST_SUITE_P(Features, GpuCpuAgreementLarge,
                         ::testing::Values("threeEggs_SoftShadows.xml",      // area lights, instances
                                           "glossinessTest.xml",             // gloss (roughness)
                                           "dielectric_Test00.xml",          // dielectric, refraction
                                           "earth.xml",                      // image texture
                                           "happyBuddha_100K.xml",           // 100K-triangle mesh
                                           "CornellRoom_wMirroredSpheres.xml",  // mirrors, boxes
                                           "scenes/glass_and_instances.xml"),  // ours: all of them together
                         [](const ::testing::TestParamInfo<const char*>& info) {
                             std::string n = std::filesystem::path(info.param).stem().string();
                             std::replace_if(n.begin(), n.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
                             return n;
                         });

}  // namespace
}  // namespace vkrt::test
