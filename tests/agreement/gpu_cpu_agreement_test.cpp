// The GPU kernel (lavapipe here) against the CPU reference at equal seeds, on every scene users
// have: all of ../shared/scenes/upstream and our scenes/ at 64x64, and scenes covering area lights,
// gloss, dielectrics, instances, meshes and textures at 256x256 with 16 rpp.
//
// Tolerance (issue 5): >= 99.5% of pixels within 2/255 in every channel and a mean absolute
// difference <= 0.5/255. Both paths compute the same samples from the same random numbers
// (shaders/shared/sampling.h), so the images would be identical but for rounding: the device
// contracts multiply-adds into FMAs and orders a few sums differently, which can tip a ray that
// grazes a silhouette, a shadow terminator or a BVH box to the other side. That flips isolated
// pixels by a large amount, never a region, and shifts smooth regions by < 1/255 after 8-bit
// truncation. A wrong feature (a missing light, a wrong shader, a broken traversal) changes whole
// regions and fails both bounds. On failure the heat map is kept in test_artifacts/.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cpu_renderer.h"
#include "gpu_renderer.h"
#include "image.h"
#include "image_compare.h"
#include "node_packing.h"
#include "scene_loader.h"
#include "test_paths.h"

namespace vkrt {
namespace {

std::vector<std::string> scenesIn(const std::string& dir) {
    std::vector<std::string> paths;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
        if (entry.path().extension() == ".xml") paths.push_back(entry.path().string());
    std::sort(paths.begin(), paths.end());
    return paths;
}

// One device for the whole binary, validation on: creating it costs more than a 64x64 render.
GpuRenderer& gpu() {
    static std::unique_ptr<GpuRenderer> renderer = [] {
        GpuRendererOptions options;
        options.validation = true;
        return std::make_unique<GpuRenderer>(options);
    }();
    return *renderer;
}

struct Agreement {
    ImageDifference diff;
    bool ok = false;
};

// Renders `path` on both devices with `options` and compares; keeps the heat map on failure.
Agreement renderBothAndCompare(const std::string& path, RenderOptions options,
                               KernelVariant variant = KernelVariant::Specialised) {
    Diagnostics diagnostics;
    const Scene scene = loadScene(path, LoadOptions{}, diagnostics);
    // Each device renders from the scene it prepares itself, as `vkrt` does: the trees differ.
    const SceneAccel cpuAccel = prepareCpuScene(scene);
    const GpuSceneData gpuData = GpuRenderer::prepare(scene);
    options.quiet = true;
    RenderStats cpuStats;
    GpuRenderStats gpuStats;
    const Image cpu = renderCpu(scene, cpuAccel, options, &cpuStats);
    const std::size_t messagesBefore = gpu().validationLog()->count();
    const Image gpuImage = gpu().render(gpuData, options, &gpuStats, {.variant = variant, .tiling = {}});
    EXPECT_EQ(gpu().validationLog()->count(), messagesBefore) << gpu().validationLog()->joined();
    EXPECT_EQ(cpuStats.nonFiniteSamples, 0u);
    EXPECT_EQ(gpuStats.nonFiniteSamples, 0u);
    Agreement a;
    a.diff = compareImages(cpu, gpuImage);
    a.ok = a.diff.fractionOver2 <= 0.005 && a.diff.meanAbs <= 0.5 / 255.0;
    const std::string name = std::filesystem::path(path).stem().string() + (variant == KernelVariant::General ? "_general" : "");
    std::printf("[agreement] %-40s %dx%d %3d rpp: max %3.0f/255, mean %.4f/255, >2/255 %.3f%%, gpu %.2f s (%s)\n",
                name.c_str(), options.width, options.height, options.samplesPerPixel, a.diff.maxAbs * 255.0,
                a.diff.meanAbs * 255.0, 100.0 * a.diff.fractionOver2, gpuStats.renderSeconds, gpuStats.features.c_str());
    if (!a.ok) {
        const std::string heat = test::artifactDir() + "/agreement_" + name + "_heat.png";
        writeImage(a.diff.heatMap, heat);
        writeImage(cpu, test::artifactDir() + "/agreement_" + name + "_cpu.png");
        writeImage(gpuImage, test::artifactDir() + "/agreement_" + name + "_gpu.png");
        ADD_FAILURE() << name << ": " << 100.0 * a.diff.fractionOver2 << "% of pixels over 2/255 (limit 0.5%), mean "
                      << a.diff.meanAbs * 255.0 << "/255 (limit 0.5/255); heat map " << heat;
    }
    return a;
}

RenderOptions small(int size, int rpp) {
    RenderOptions options;
    options.width = size;
    options.height = size;
    options.samplesPerPixel = rpp;
    return options;
}

// One test over all files rather than one per file: each ctest entry would start a process and a
// validated Vulkan device, which costs more than the renders.
TEST(GpuCpuAgreement, EveryUpstreamAndBundledSceneAt64x64) {
    VKRT_SKIP_WITHOUT(vkrt::test::upstreamDir());
    std::vector<std::string> paths = scenesIn(test::upstreamDir());
    ASSERT_EQ(paths.size(), 54u) << test::upstreamDir();
    const std::vector<std::string> ours = scenesIn(test::sourceDir() + "/scenes");
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
    VKRT_SKIP_WITHOUT(vkrt::test::upstreamDir());
    int mixed = 0;
    for (const std::string& path : scenesIn(test::upstreamDir())) {
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
    VKRT_SKIP_WITHOUT(vkrt::test::upstreamDir());
    std::vector<std::string> paths = scenesIn(test::upstreamDir());
    ASSERT_EQ(paths.size(), 54u) << test::upstreamDir();
    const std::vector<std::string> ours = scenesIn(test::sourceDir() + "/scenes");
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
    VKRT_SKIP_WITHOUT(vkrt::test::upstreamDir());
    RenderOptions options = small(128, 4);
    options.glossSamples = 4;
    options.lightSamples = 4;
    renderBothAndCompare(test::upstreamDir() + "/glossinessTest.xml", options);
    renderBothAndCompare(test::upstreamDir() + "/threeEggs_SoftShadows.xml", options);
}

// 256x256 at 16 rpp (the instructor's sampling), one scene per feature the kernel specialises on.
class GpuCpuAgreementLarge : public ::testing::TestWithParam<const char*> {};

TEST_P(GpuCpuAgreementLarge, At256x256With16Rpp) {
    VKRT_SKIP_WITHOUT(vkrt::test::upstreamDir());
    const std::string name = GetParam();
    const std::string path = name.rfind("scenes/", 0) == 0 ? test::sourceDir() + "/" + name : test::upstreamDir() + "/" + name;
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
}  // namespace vkrt
