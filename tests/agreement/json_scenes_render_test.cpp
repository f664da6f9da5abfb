// The course's JSON scenes (../shared/scenes/json, SOURCES.md there; issue 19) on both devices:
//  - every file renders at 64x64, 1 rpp, and the GPU agrees with the CPU by agreement_support.h's
//    rule, as the XML scenes do (gpu_cpu_agreement_test.cpp);
//  - each JSON twin of an XML file (the same camera, lights, shaders and shapes; the loader's
//    JsonTwins test in tests/scene/json_scenes_test.cpp checks the scene models field by field)
//    renders bit-identically to its XML, on the CPU and on the GPU.
// The twins that have an instructor reference render are checked against it in
// tests/cpu/reference_render_test.cpp (suite JsonTwins), by the XML side's rule.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "agreement_support.h"
#include "statistical_compare.h"
#include "diagnostics.h"
#include "json_twins.h"
#include "scene_loader.h"
#include "test_paths.h"

namespace vkrt::test {
namespace {

// Whether the scene is path traced: a Diffuse surface bounces (docs/RENDERING.md §5).
bool pathTraced(const Scene& scene) {
    return std::any_of(scene.shaders.begin(), scene.shaders.end(), [](const Shader& s) { return s.diffuseBounce; });
}

// A path-traced sample traces several bounces and their light samples, each through the scene's
// geometry, so a rounding difference (the GPU fuses multiply-adds) tips a ray across an edge more
// often than in a Whitted-style sample; after a tip the two devices trace unrelated paths and the
// pixel differs by a whole sample's value. In dragons00.json (600 instanced 100K-triangle dragons,
// glossy and glass ones, Diffuse ground) that happens to 0.39-0.51% of the pixels at 1 rpp (0%
// with -k 1, 0.07% with -k 2, growing with every bounce; isolated pixels, never a region). For a
// path-traced scene that meets the mean bound but not the 0.5% one, the devices must instead agree
// up to their noise at other seeds: `vkrt compare --stat`'s per-pixel z-test (statistical_compare.h).
void expectStatisticalAgreement(const Scene& scene, const std::string& name) {
    static study::StudyRenderer renderer(GpuRendererOptions{.validation = true});
    const study::PreparedScene prepared = renderer.prepare(scene);
    RenderOptions options = small(64, 16);
    options.camera = scene.defaultCamera;
    const study::StatisticalComparison c = study::compareDevicesStatistically(renderer, prepared, options);
    std::printf("[agreement] %-40s z-test at seeds %u/%u, %d/%d rpp: max |z| %.2f (limit %.2f), %.3f%% pass -> %s\n",
                name.c_str(), c.gpuSeed, c.cpuSeed, c.gpuRpp, c.cpuRpp, c.test.maxAbsZ, c.test.zLimit,
                100.0 * c.test.passedFraction(), c.test.pass ? "PASS" : "FAIL");
    EXPECT_TRUE(c.test.pass) << name << ": the devices disagree beyond their noise";
}

// One test over all files, as for the XML scenes: a ctest entry per file would start a process and
// a validated Vulkan device each, which costs more than the renders.
TEST(GpuCpuAgreement, EveryJsonSceneAt64x64With1Rpp) {
    VKRT_SKIP_WITHOUT(jsonSceneDir());
    const std::vector<std::string> paths = scenesIn(jsonSceneDir(), ".json");
    ASSERT_EQ(paths.size(), 58u) << jsonSceneDir();
    std::size_t rendered = 0;
    for (const std::string& path : paths) {
        SCOPED_TRACE(path);
        const std::filesystem::path file(path);
        try {
            Diagnostics diagnostics;  // each file's warnings are the loader tests' concern (tests/scene)
            const Scene scene = loadScene(path, LoadOptions{}, diagnostics);
            const std::string name = file.stem().string();
            const Agreement a = measureAgreement(scene, name, small(64, 1), KernelVariant::Specialised, !pathTraced(scene));
            if (!a.ok) {
                EXPECT_LE(a.diff.meanAbs, 0.5 / 255.0) << name << ": a region differs, not isolated pixels";
                expectStatisticalAgreement(scene, name);
            }
            ++rendered;
        } catch (const std::exception& e) {
            ADD_FAILURE() << path << ": " << e.what();
        }
    }
    std::printf("[agreement] JSON corpus: %zu of %zu rendered on both devices\n", rendered, paths.size());
    EXPECT_EQ(rendered, paths.size());
}

// --- JSON twins ---

// The instructor references' background (50/255 grey, upstream/reference/README.md).
const glm::vec3 kTwinBackground(50.0f / 255.0f);


// Bit-identical, not merely close: the twins hold equal scene models (floats exactly), so every
// step after the loader (trees, tables, kernels, samples) sees the same input.
TEST(JsonTwins, RenderBitIdenticallyToTheirXmlOnBothDevices) {
    VKRT_SKIP_WITHOUT(jsonSceneDir());
    VKRT_SKIP_WITHOUT(upstreamDir());
    for (const JsonTwin& twin : kJsonTwins) {
        const std::string label = std::string(twin.json) + ".json vs " + twin.xml + ".xml";
        SCOPED_TRACE(label);
        try {
            Diagnostics diagnostics;
            const Scene xs = loadScene(upstreamDir() + "/" + twin.xml + ".xml", LoadOptions{}, diagnostics);
            const Scene js = loadScene(jsonSceneDir() + "/" + twin.json + ".json", LoadOptions{}, diagnostics);
            EXPECT_EQ(xs.background == js.background, twin.sameBackground) << "the list's background flag is stale";
            RenderOptions options = small(64, 4);
            if (!twin.sameBackground) options.background = kTwinBackground;
            // mirrorTest2.xml names an environment map its JSON twin (mirrorScene01) does not: the
            // twins are the same camera, lights, shaders and shapes, so both render without it.
            options.environment = false;
            const DeviceImages x = renderBoth(xs, options);
            const DeviceImages j = renderBoth(js, options);
            const std::size_t cpuDiff = differingPixels(x.cpu, j.cpu);
            const std::size_t gpuDiff = differingPixels(x.gpu, j.gpu);
            std::printf("[twin] %-52s 64x64 4 rpp%s: cpu %zu, gpu %zu of %zu pixels differ\n", label.c_str(),
                        twin.sameBackground ? "" : ", bg 50/255", cpuDiff, gpuDiff, x.cpu.pixels.size());
            EXPECT_EQ(cpuDiff, 0u) << "CPU images differ";
            EXPECT_EQ(gpuDiff, 0u) << "GPU images differ";
            if (cpuDiff || gpuDiff) {
                const std::string stem = artifactDir() + "/twin_" + twin.json;
                writeImage(x.cpu, stem + "_xml_cpu.png");
                writeImage(j.cpu, stem + "_json_cpu.png");
                writeImage(x.gpu, stem + "_xml_gpu.png");
                writeImage(j.gpu, stem + "_json_gpu.png");
            }
        } catch (const std::exception& e) {
            ADD_FAILURE() << label << ": " << e.what();
        }
    }
}

}  // namespace
}  // namespace vkrt::test
