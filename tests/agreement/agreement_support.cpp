#include "agreement_support.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>

#include <gtest/gtest.h>

#include "cpu_renderer.h"
#include "scene_loader.h"
#include "test_paths.h"

namespace vkrt::test {

std::vector<std::string> scenesIn(const std::string& dir, const std::string& extension) {
    std::vector<std::string> paths;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
        if (entry.path().extension() == extension) paths.push_back(entry.path().string());
    std::sort(paths.begin(), paths.end());
    return paths;
}

GpuRenderer& gpu() {
    static std::unique_ptr<GpuRenderer> renderer = [] {
        GpuRendererOptions options;
        options.validation = true;
        return std::make_unique<GpuRenderer>(options);
    }();
    return *renderer;
}

std::size_t differingPixels(const Image& a, const Image& b) {
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    if (a.pixels.size() != b.pixels.size()) return std::max(a.pixels.size(), b.pixels.size());
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) n += a.pixels[i] != b.pixels[i];
    return n;
}

RenderOptions small(int size, int rpp) {
    RenderOptions options;
    options.width = size;
    options.height = size;
    options.samplesPerPixel = rpp;
    return options;
}

DeviceImages renderBoth(const Scene& scene, RenderOptions options, KernelVariant variant) {
    // Each device renders from the scene it prepares itself, as `vkrt` does: the trees differ.
    const SceneAccel cpuAccel = prepareCpuScene(scene);
    const GpuSceneData gpuData = GpuRenderer::prepare(scene);
    options.quiet = true;
    DeviceImages out;
    RenderStats cpuStats;
    out.cpu = renderCpu(scene, cpuAccel, options, &cpuStats);
    const std::size_t messagesBefore = gpu().validationLog()->count();
    out.gpu = gpu().render(gpuData, options, &out.gpuStats, {.variant = variant, .tiling = {}});
    EXPECT_EQ(gpu().validationLog()->count(), messagesBefore) << gpu().validationLog()->joined();
    EXPECT_EQ(cpuStats.nonFiniteSamples, 0u);
    EXPECT_EQ(out.gpuStats.nonFiniteSamples, 0u);
    return out;
}

Agreement renderBothAndCompare(const Scene& scene, const std::string& label, RenderOptions options,
                               KernelVariant variant) {
    return measureAgreement(scene, label, options, variant, true);
}

Agreement measureAgreement(const Scene& scene, const std::string& label, RenderOptions options, KernelVariant variant,
                           bool required) {
    const DeviceImages images = renderBoth(scene, options, variant);
    Agreement a;
    a.diff = compareImages(images.cpu, images.gpu);
    a.ok = meetsAgreementRule(a.diff);
    const std::string name = label + (variant == KernelVariant::General ? "_general" : "");
    std::printf("[agreement] %-40s %dx%d %3d rpp: max %3.0f/255, mean %.4f/255, >2/255 %.3f%%, gpu %.2f s (%s)\n",
                name.c_str(), options.width, options.height, options.samplesPerPixel, a.diff.maxAbs * 255.0,
                a.diff.meanAbs * 255.0, 100.0 * a.diff.fractionOver2, images.gpuStats.renderSeconds,
                images.gpuStats.features.c_str());
    if (!a.ok && required) {
        const std::string heat = artifactDir() + "/agreement_" + name + "_heat.png";
        writeImage(a.diff.heatMap, heat);
        writeImage(images.cpu, artifactDir() + "/agreement_" + name + "_cpu.png");
        writeImage(images.gpu, artifactDir() + "/agreement_" + name + "_gpu.png");
        ADD_FAILURE() << name << ": " << 100.0 * a.diff.fractionOver2 << "% of pixels over 2/255 (limit 0.5%), mean "
                      << a.diff.meanAbs * 255.0 << "/255 (limit 0.5/255); heat map " << heat;
    }
    return a;
}

Agreement renderBothAndCompare(const std::string& path, RenderOptions options, KernelVariant variant) {
    Diagnostics diagnostics;
    const Scene scene = loadScene(path, LoadOptions{false, /*localOrigin=*/true}, diagnostics);
    return renderBothAndCompare(scene, std::filesystem::path(path).stem().string(), options, variant);
}

}  // namespace vkrt::test
