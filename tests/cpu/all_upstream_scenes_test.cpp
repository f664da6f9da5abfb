// Every upstream scene renders (64x64, 1 rpp) without error and without a non-finite sample: the
// renderer copes with every camera, shape, shader, light, texture and instance the real files use.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "analytic_scene.h"
#include "scene_loader.h"
#include "test_paths.h"

namespace vkrt::test {
namespace {

std::vector<std::string> upstreamScenes() {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(upstreamDir(), ec))
        if (entry.path().extension() == ".xml") names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// One test for all 54 files (not one per file): each ctest entry costs a process start, which
// here would dwarf the renders themselves.
TEST(UpstreamScenes, EveryFileRendersAt64x64) {
    VKRT_SKIP_WITHOUT(vkrt::test::upstreamDir());
    const std::vector<std::string> names = upstreamScenes();
    EXPECT_EQ(names.size(), 54u) << upstreamDir();
    double total = 0.0;
    for (const std::string& name : names) {
        SCOPED_TRACE(name);
        const auto start = std::chrono::steady_clock::now();
        try {
            Diagnostics diagnostics;
            const Scene scene = loadScene(upstreamDir() + "/" + name, LoadOptions{}, diagnostics);
            RenderOptions options;
            options.width = 64;
            options.height = 64;
            options.samplesPerPixel = 1;
            RenderStats stats;
            const Image image = renderChecked(scene, options, &stats);  // asserts no non-finite sample
            EXPECT_EQ(image.width, 64);
            EXPECT_EQ(stats.cameraRays, 64u * 64u);
        } catch (const std::exception& e) {
            ADD_FAILURE() << name << ": " << e.what();
        }
        total += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    std::printf("[upstream 64x64] %zu scenes loaded, built and rendered in %.2f s\n", names.size(), total);
}

}  // namespace
}  // namespace vkrt::test
