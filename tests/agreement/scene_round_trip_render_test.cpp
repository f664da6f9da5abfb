// vkrt convert's round trip as the renderers see it (issue 19): every course file and bundled scene,
// written in the other format (XML -> JSON, JSON -> XML) and loaded back, renders bit-identically
// to the original on the CPU and on the GPU. tests/scene/scene_round_trip_test.cpp checks the
// models field by field; this checks that those fields are all the renderers read.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "agreement_support.h"
#include "diagnostics.h"
#include "json_writer.h"
#include "scene_loader.h"
#include "test_paths.h"
#include "xml_writer.h"

namespace vkrt::test {
namespace {

namespace fs = std::filesystem;

Scene loadQuietly(const std::string& path) {
    Diagnostics diagnostics;  // the files' warnings are the loader tests' concern
    return loadScene(path, LoadOptions{}, diagnostics);
}

// `scene` written as the format `path` does not have, into `dir`, and loaded back.
Scene throughTheOtherFormat(const Scene& scene, const std::string& path, const fs::path& dir) {
    const bool toJson = fs::path(path).extension() == ".xml";
    const fs::path written = dir / (fs::path(path).stem().string() + (toJson ? ".json" : ".xml"));
    std::ofstream(written, std::ios::binary) << (toJson ? jsonSceneText(scene, dir) : xmlSceneText(scene, dir));
    return loadQuietly(written.string());
}

TEST(SceneRoundTrip, EveryFileRendersBitIdenticallyAfterConversionOnBothDevices) {
    VKRT_SKIP_WITHOUT(upstreamDir());
    VKRT_SKIP_WITHOUT(jsonSceneDir());
    std::vector<std::string> paths = scenesIn(upstreamDir(), ".xml");
    for (const std::string& p : scenesIn(jsonSceneDir(), ".json")) paths.push_back(p);
    for (const std::string& p : scenesIn(sourceDir() + "/scenes", ".xml")) paths.push_back(p);
    ASSERT_EQ(paths.size(), 54u + 58u + 6u);
    const fs::path dir = fs::path(artifactDir()) / "round_trip_render";
    fs::remove_all(dir);
    fs::create_directories(dir);
    // 16x16 at 4 rpp: every pixel of a 4x4 image grid is a different ray, soft shadows and gloss
    // are sampled; any field the model comparison missed would move pixels.
    const RenderOptions options = small(16, 4);
    std::size_t identical = 0;
    for (const std::string& path : paths) {
        SCOPED_TRACE(path);
        try {
            const Scene original = loadQuietly(path);
            const Scene converted = throughTheOtherFormat(original, path, dir);
            const DeviceImages a = renderBoth(original, options);
            const DeviceImages b = renderBoth(converted, options);
            const std::size_t cpu = differingPixels(a.cpu, b.cpu), gpu = differingPixels(a.gpu, b.gpu);
            EXPECT_EQ(cpu, 0u) << "CPU pixels differ";
            EXPECT_EQ(gpu, 0u) << "GPU pixels differ";
            identical += cpu == 0 && gpu == 0;
        } catch (const std::exception& e) {
            ADD_FAILURE() << path << ": " << e.what();
        }
    }
    std::printf("[round trip] %zu of %zu files render bit-identically after conversion on both devices\n", identical,
                paths.size());
}

}  // namespace
}  // namespace vkrt::test
