// Progressive renders (--progressive N, RenderOptions::checkpoints) on both devices: the image a
// progressive render returns is the one-pass image bit for bit (every pixel sums its samples in
// sample order either way), the passes end where checkpointEnds says, each pass's image is the
// mean of the samples so far (the GPU's agrees with the CPU's by the agreement rule: the same
// samples), and it converges on the final image. On the GPU a render in several tiles shows the
// finished tiles whole, the current one partly sampled and the rest black.
#include <cmath>
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

struct Recorded {
    Image image;
    int samples = 0;
};

class Recorder : public CheckpointSink {
public:
    void checkpoint(const Image& soFar, int samplesDone) override { passes.push_back({soFar, samplesDone}); }
    std::vector<Recorded> passes;
};

Scene glassScene() {
    Diagnostics diagnostics;
    return loadScene(test::sourceDir() + "/scenes/glass_and_instances.xml", LoadOptions{false, true}, diagnostics);
}

double rmse(const Image& a, const Image& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        const glm::vec3 d = a.pixels[i] - b.pixels[i];
        sum += glm::dot(d, d);
    }
    return std::sqrt(sum / (3.0 * static_cast<double>(a.pixels.size())));
}

TEST(CheckpointEnds, SplitTheUnitsEvenlyWithoutRepeats) {
    EXPECT_EQ(checkpointEnds(16, 4), (std::vector<int>{4, 8, 12, 16}));
    EXPECT_EQ(checkpointEnds(10, 3), (std::vector<int>{3, 6, 10}));
    EXPECT_EQ(checkpointEnds(3, 8), (std::vector<int>{1, 2, 3}));  // more passes than samples: one each
    EXPECT_EQ(checkpointEnds(16, 1), (std::vector<int>{16}));
    EXPECT_EQ(checkpointEnds(16, 0), (std::vector<int>{16}));
}

TEST(ProgressiveRender, PassesConvergeOnTheOnePassImageOnBothDevices) {
    const Scene scene = glassScene();
    RenderOptions options = test::small(48, 12);
    options.height = 36;
    const test::DeviceImages plain = test::renderBoth(scene, options);

    options.checkpoints = 3;
    Recorder onCpu, onGpu;
    options.onCheckpoint = &onCpu;
    const Image cpu = renderCpu(scene, prepareCpuScene(scene), options);
    options.onCheckpoint = &onGpu;
    GpuRenderStats stats;
    const Image gpu = test::gpu().render(GpuRenderer::prepare(scene), options, &stats);
    EXPECT_EQ(test::differingPixels(cpu, plain.cpu), 0u) << "the CPU's progressive image is not the one-pass image";
    EXPECT_EQ(test::differingPixels(gpu, plain.gpu), 0u) << "the GPU's progressive image is not the one-pass image";

    // 12 samples in 3 passes: images after 4 and 8 (the GPU's dispatches of this scene are 1
    // sample each, so its passes end on the same samples).
    ASSERT_EQ(stats.samplesPerDispatch, 1u);
    ASSERT_EQ(onCpu.passes.size(), 2u);
    ASSERT_EQ(onGpu.passes.size(), 2u);
    double previous = INFINITY;
    for (std::size_t p = 0; p < 2; ++p) {
        EXPECT_EQ(onCpu.passes[p].samples, 4 * static_cast<int>(p + 1));
        EXPECT_EQ(onGpu.passes[p].samples, 4 * static_cast<int>(p + 1));
        // The agreement rule (agreement_support.h): the same samples on both devices.
        const ImageDifference diff = compareImages(onCpu.passes[p].image, onGpu.passes[p].image);
        EXPECT_LE(diff.fractionOver2, 0.005) << "pass " << p;
        EXPECT_LE(diff.meanAbs, 0.5 / 255.0) << "pass " << p;
        // Each pass is nearer the final image than the one before, and not yet it: its pixels are
        // means of fewer samples (the scene's soft shadows and gloss are noisy at 4 and 8 rpp).
        const double error = rmse(onCpu.passes[p].image, cpu);
        EXPECT_GT(error, 0.0) << "pass " << p;
        EXPECT_LT(error, previous) << "pass " << p;
        previous = error;
    }
}

// Three full-width bands of 16 rows (fixed tiles), 6 samples in 2 passes: a pass image per band,
// each showing the bands before it whole and the ones after it black; the result is the one-pass
// image.
TEST(ProgressiveRender, GpuTilesShowFinishedTilesWholeAndLaterOnesBlack) {
    const Scene scene = glassScene();
    RenderOptions options = test::small(40, 6);
    options.height = 48;
    GpuRenderSettings tiled;
    tiled.tiling.fixedTileWidth = 40;
    tiled.tiling.fixedTileHeight = 16;
    tiled.tiling.fixedWorkgroups = 5;
    const GpuSceneData data = GpuRenderer::prepare(scene);
    const Image plain = test::gpu().render(data, options, nullptr, tiled);
    options.checkpoints = 2;
    Recorder recorder;
    options.onCheckpoint = &recorder;
    const Image progressive = test::gpu().render(data, options, nullptr, tiled);
    EXPECT_EQ(test::differingPixels(progressive, plain), 0u);
    // Passes end at 3 and 6 samples in each band; the last band's 6 is the result itself.
    ASSERT_EQ(recorder.passes.size(), 5u);
    const auto bandIsBlack = [](const Image& image, int band) {
        for (int y = band * 16; y < band * 16 + 16; ++y)
            for (int x = 0; x < image.width; ++x)
                if (image.at(x, y) != glm::vec3(0.0f)) return false;
        return true;
    };
    const auto bandIs = [](const Image& image, const Image& reference, int band) {
        for (int y = band * 16; y < band * 16 + 16; ++y)
            for (int x = 0; x < image.width; ++x)
                if (image.at(x, y) != reference.at(x, y)) return false;
        return true;
    };
    for (std::size_t p = 0; p < recorder.passes.size(); ++p) {
        const int band = static_cast<int>(p / 2);
        const Image& image = recorder.passes[p].image;
        EXPECT_EQ(recorder.passes[p].samples, p % 2 == 0 ? 3 : 6) << "pass " << p;
        for (int b = 0; b < band; ++b) EXPECT_TRUE(bandIs(image, plain, b)) << "pass " << p << ", band " << b;
        EXPECT_FALSE(bandIsBlack(image, band)) << "pass " << p;
        EXPECT_EQ(bandIs(image, plain, band), p % 2 == 1) << "pass " << p;  // complete only after its last pass
        for (int b = band + 1; b < 3; ++b) EXPECT_TRUE(bandIsBlack(image, b)) << "pass " << p << ", band " << b;
    }
}

}  // namespace
}  // namespace vkrt
