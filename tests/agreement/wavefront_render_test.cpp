// The wavefront renderer (--gpu-kernel wavefront, host/gpu/wavefront_renderer.h) against the
// megakernel: its shading stages run the megakernel's own shadeRay with the shadow rays deferred,
// and its ACCUMULATE stage adds a pixel's samples in sample order, so its image is the megakernel's
// bit for bit where the two compilations round alike (lavapipe: every scene below and all 112
// course files, tools/wavefront_compare.py); elsewhere the agreement rule (agreement_support.h)
// holds. The megakernel itself is checked against the CPU reference by gpu_cpu_agreement_test.
// The image does not depend on the paths in flight per wave; progressive passes and --part rows
// behave as the megakernel's.
#include <cctype>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "agreement_support.h"
#include "cpu_renderer.h"
#include "image_compare.h"
#include "scene_loader.h"
#include "test_paths.h"

namespace vkrt {
namespace {

Scene load(const std::string& path) {
    Diagnostics diagnostics;
    LoadOptions load{false, true};
    load.shaderEmitters = true;
    return loadScene(path, load, diagnostics);
}

// A small, quiet render of `scene` through its own camera.
RenderOptions smallRender(const Scene& scene, int size, int rpp) {
    RenderOptions options = test::small(size, rpp);
    options.quiet = true;
    options.camera = scene.defaultCamera;
    return options;
}

GpuRenderSettings wavefront(std::uint64_t wavePaths = 0) {
    GpuRenderSettings s;
    s.kernel = GpuKernel::Wavefront;
    s.wavePaths = wavePaths;
    return s;
}

// Bit for bit on lavapipe (both kernels are compiled by the same LLVM from the same shading code);
// on another driver the two compilations may contract differently: the agreement rule.
void expectSameImage(const Image& wavefrontImage, const Image& megakernelImage, const std::string& name) {
    if (test::gpu().deviceInfo().lavapipe) {
        EXPECT_EQ(test::differingPixels(wavefrontImage, megakernelImage), 0u) << name;
        return;
    }
    const ImageDifference diff = compareImages(megakernelImage, wavefrontImage);
    EXPECT_LE(diff.fractionOver2, 0.005) << name;
    EXPECT_LE(diff.meanAbs, 0.5 / 255.0) << name;
}

struct Case {
    std::string path;
    Estimator estimator = Estimator::MisPower;
};

// One scene per kernel feature: Whitted lights and shaders, area lights, gloss, dielectrics (the
// path stack: branching rays), translucency, textures, instances, thin lens, motion, the
// path-traced Diffuse with shape emitters under every estimator, mesh emitters, an environment map.
std::vector<Case> cases() {
    const std::string bundled = test::sourceDir() + "/scenes/";
    const std::string xml = test::upstreamDir() + "/";
    const std::string json = test::jsonSceneDir() + "/";
    return {
        {bundled + "soft_shadows.xml"},      {bundled + "glossy.xml"},
        {bundled + "glass_and_instances.xml"}, {bundled + "translucency.xml"},
        {bundled + "depth_of_field.xml"},    {bundled + "motion_blur.xml"},
        {bundled + "quad_lit_room.json"},    {bundled + "quad_lit_room.json", Estimator::Nee},
        {bundled + "quad_lit_room.json", Estimator::Bounce}, {bundled + "quad_lit_room.json", Estimator::MisBalance},
        {json + "threeOBJS_CooltoWarm.json"}, {xml + "pt_test.xml"},      {xml + "mirrorTest2.xml"},
        {xml + "bhart_00_2012.xml"},        {json + "LittleOfEverything.json"},
        {json + "emitterTest_OBJ.json"},     {json + "CornellBox_Dielectric.json"},
    };
}

class WavefrontFeature : public ::testing::TestWithParam<Case> {};

TEST_P(WavefrontFeature, EqualsTheMegakernel) {
    const Case& c = GetParam();
    VKRT_SKIP_WITHOUT(c.path);
    const Scene scene = load(c.path);
    RenderOptions options = smallRender(scene, 40, 4);
    options.height = 30;
    options.estimator = c.estimator;
    const GpuSceneData data = GpuRenderer::prepare(scene);
    GpuRenderStats stats;
    const Image megakernel = test::gpu().render(data, options);
    const Image waves = test::gpu().render(data, options, &stats, wavefront());
    EXPECT_TRUE(stats.wavefront);
    expectSameImage(waves, megakernel, c.path + " (" + estimatorName(c.estimator) + ")");
    EXPECT_EQ(stats.nonFiniteSamples, 0u);
}

std::string caseName(const ::testing::TestParamInfo<Case>& info) {
    std::string name = std::filesystem::path(info.param.path).stem().string() + "_" + estimatorName(info.param.estimator);
    for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    return name;
}

INSTANTIATE_TEST_SUITE_P(WavefrontRender, WavefrontFeature, ::testing::ValuesIn(cases()), caseName);

// Waves of one row, of five rows and one sample, and the device's default: the same image (each
// pixel's samples are summed in sample order whatever the wave).
TEST(WavefrontRender, TheImageDoesNotDependOnThePathsInFlight) {
    for (const char* file : {"/scenes/glass_and_instances.xml", "/scenes/quad_lit_room.json"}) {
        const Scene scene = load(test::sourceDir() + file);
        RenderOptions options = smallRender(scene, 24, 6);
        options.height = 20;
        const GpuSceneData data = GpuRenderer::prepare(scene);
        const Image whole = test::gpu().render(data, options, nullptr, wavefront());
        for (const std::uint64_t paths : {24ull, 24ull * 5, 24ull * 20 * 4}) {
            const Image waves = test::gpu().render(data, options, nullptr, wavefront(paths));
            EXPECT_EQ(test::differingPixels(waves, whole), 0u) << file << ", " << paths << " paths per wave";
        }
    }
}

class Recorder : public CheckpointSink {
public:
    void checkpoint(const Image& soFar, int samplesDone) override {
        images.push_back(soFar);
        samples.push_back(samplesDone);
    }
    std::vector<Image> images;
    std::vector<int> samples;
};

// 9 samples in 3 passes with waves of 2 samples: rounds end at 3 and 6 samples (images then), the
// result is the one-pass image, and each image agrees with the CPU's after as many samples.
TEST(WavefrontRender, ProgressivePassesEndOnTheirSamplesAndAgreeWithTheCpu) {
    const Scene scene = load(test::sourceDir() + "/scenes/glass_and_instances.xml");
    RenderOptions options = smallRender(scene, 32, 9);
    const GpuSceneData data = GpuRenderer::prepare(scene);
    const Image plain = test::gpu().render(data, options, nullptr, wavefront());
    options.checkpoints = 3;
    Recorder onGpu, onCpu;
    options.onCheckpoint = &onGpu;
    const Image progressive = test::gpu().render(data, options, nullptr, wavefront(32 * 32 * 2));
    EXPECT_EQ(test::differingPixels(progressive, plain), 0u);
    ASSERT_EQ(onGpu.samples, (std::vector<int>{3, 6}));
    options.onCheckpoint = &onCpu;
    renderCpu(scene, prepareCpuScene(scene), options);
    ASSERT_EQ(onCpu.samples, onGpu.samples);
    for (std::size_t p = 0; p < onGpu.images.size(); ++p) {
        const ImageDifference diff = compareImages(onCpu.images[p], onGpu.images[p]);
        EXPECT_LE(diff.fractionOver2, 0.005) << "pass " << p;
        EXPECT_LE(diff.meanAbs, 0.5 / 255.0) << "pass " << p;
    }
}

// --part's rows: those rows of the whole image, the others black.
TEST(WavefrontRender, APartRendersItsRowsOfTheWholeImage) {
    const Scene scene = load(test::sourceDir() + "/scenes/quad_lit_room.json");
    RenderOptions options = smallRender(scene, 24, 4);
    const GpuSceneData data = GpuRenderer::prepare(scene);
    const Image whole = test::gpu().render(data, options, nullptr, wavefront());
    options.rows = glm::ivec2(7, 16);
    const Image part = test::gpu().render(data, options, nullptr, wavefront(24 * 4));
    for (int y = 0; y < options.height; ++y)
        for (int x = 0; x < options.width; ++x) {
            const glm::vec3 expected = y >= 7 && y < 16 ? whole.at(x, y) : glm::vec3(0.0f);
            ASSERT_EQ(part.at(x, y), expected) << "pixel (" << x << ", " << y << ")";
        }
}

}  // namespace
}  // namespace vkrt
