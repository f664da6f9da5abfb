#include "both_paths.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "gpu_environment.h"
#include "image_compare.h"
#include "test_paths.h"

namespace vkrt::stability {

BothImages renderBoth(const Scene& scene, const RenderOptions& options, Image* cpuSampleVariance) {
    BothImages out;
    out.cpu = renderCpu(scene, prepareCpuScene(scene), options, &out.cpuStats, cpuSampleVariance);
    GpuRenderer& gpu = sharedGpu();
    const std::size_t messagesBefore = gpu.validationLog()->count();
    // Each device from the scene it prepares itself, as `vkrt` renders it.
    out.gpu = gpu.render(GpuRenderer::prepare(scene), options, &out.gpuStats);
    EXPECT_EQ(out.cpuStats.nonFiniteSamples, 0u) << "CPU samples replaced by black (NaN/Inf radiance)";
    EXPECT_EQ(out.gpuStats.nonFiniteSamples, 0u) << "GPU samples replaced by black (NaN/Inf radiance)";
    EXPECT_EQ(countNonFinite(out.cpu), 0u) << "non-finite pixels in the CPU image";
    EXPECT_EQ(countNonFinite(out.gpu), 0u) << "non-finite pixels in the GPU image";
    EXPECT_EQ(gpu.validationLog()->count(), messagesBefore) << "validation messages:\n" << gpu.validationLog()->joined();
    return out;
}

RenderOptions smallOptions(int width, int height, int samplesPerPixel) {
    RenderOptions o;
    o.width = width;
    o.height = height;
    o.samplesPerPixel = samplesPerPixel;
    o.quiet = true;
    return o;
}

std::string Distance::describe() const {
    std::ostringstream s;
    s << "worst " << maxSteps << "/255, " << 100.0 * fractionWithin2 << "% within 2/255, mean " << meanSteps << "/255";
    return s.str();
}

Distance distance(const Image& a, const Image& b) {
    const ImageDifference diff = compareImages(a, b);
    Distance d;
    d.maxSteps = static_cast<int>(std::lround(diff.maxAbs * 255.0));
    d.fractionWithin2 = 1.0 - diff.fractionOver2;
    d.meanSteps = diff.meanAbs * 255.0;
    return d;
}

void Deviation::add(double error, bool ok, const std::string& where) {
    ++checked;
    worst = std::max(worst, error);
    if (ok) return;
    if (wrong++ == 0) first = where;
}

Distance Deviation::asDistance() const {
    Distance d;
    d.maxSteps = static_cast<int>(std::lround(worst * 255.0));
    d.fractionWithin2 = checked > 0 ? 1.0 - static_cast<double>(wrong) / checked : 1.0;
    return d;
}

bool agrees(const Distance& d) { return d.fractionWithin2 >= 0.995 && d.meanSteps <= 0.5; }

namespace {

std::string cell(const Distance& d) {
    char text[64];
    std::snprintf(text, sizeof text, "%d (%.2f%%)", d.maxSteps, 100.0 * d.fractionWithin2);
    return text;
}

void writeRow(const std::string& row) {
    std::ofstream(vkrt::test::artifactDir() + "/stability_table.tsv", std::ios::app) << row << "\n";
    ::testing::Test::RecordProperty("measured", row);
    std::printf("[ measured ] %s\n", row.c_str());
}

}  // namespace

void recordRow(const std::string& caseName, const Distance& cpuVsReference, const Distance& gpuVsReference,
               const Distance& gpuVsCpu) {
    writeRow(caseName + "\t" + cell(cpuVsReference) + "\t" + cell(gpuVsReference) + "\t" + cell(gpuVsCpu));
}

void recordNote(const std::string& caseName, const std::string& cpuMeasurement) {
    writeRow(caseName + "\t" + cpuMeasurement + "\t-\t-");
}

void recordRow(const std::string& caseName, const Distance& gpuVsCpu) {
    writeRow(caseName + "\t-\t-\t" + cell(gpuVsCpu));
}

void expectGeneralKernelRendersItBitForBit(const Scene& scene, const RenderOptions& options, const std::string& feature) {
    GpuRenderSettings general;
    general.variant = KernelVariant::General;
    GpuRenderStats specialisedStats, generalStats;
    const GpuSceneData data = GpuRenderer::prepare(scene);
    const Image specialised = sharedGpu().render(data, options, &specialisedStats);
    const Image withFeature = sharedGpu().render(data, options, &generalStats, general);
    EXPECT_EQ(specialisedStats.features.find(feature), std::string::npos) << specialisedStats.features;
    EXPECT_NE(generalStats.features.find(feature), std::string::npos) << generalStats.features;
    ASSERT_EQ(specialised.pixels.size(), withFeature.pixels.size());
    expectSameGpuImage(specialised, withFeature, "the general kernel (with " + feature + ") against the specialised one");
}

void expectSameGpuImage(const Image& a, const Image& b, const std::string& what) {
    ASSERT_EQ(a.pixels.size(), b.pixels.size()) << what;
    if (sharedGpu().deviceInfo().lavapipe) {
        for (std::size_t i = 0; i < a.pixels.size(); ++i) ASSERT_EQ(a.pixels[i], b.pixels[i]) << what << ": pixel " << i;
        return;
    }
    const Distance d = distance(a, b);
    EXPECT_TRUE(agrees(d)) << what << " on " << sharedGpu().deviceName() << ": " << d.describe();
}

}  // namespace vkrt::stability
