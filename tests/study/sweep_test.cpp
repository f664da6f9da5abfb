// `vkrt sweep` end to end on a small scene (both devices, validation on): the CSV's columns and
// rows, the plots as real PNGs, the report, the reference cache (hit on the second run, with the
// same errors), and the region masks on scenes whose regions are known.
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "reference_cache.h"
#include "region_masks.h"
#include "cpu_renderer.h"
#include "scene_accel.h"
#include "study_scenes.h"
#include "sweep.h"
#include "test_paths.h"

namespace vkrt::test {
namespace {

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> fields;
    std::stringstream s(line);
    for (std::string f; std::getline(s, f, ',');) fields.push_back(f);
    return fields;
}

std::vector<std::vector<std::string>> readCsv(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::vector<std::vector<std::string>> rows;
    for (std::string line; std::getline(in, line);) rows.push_back(split(line));
    return rows;
}

std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

study::SweepOptions smallSweep(const std::filesystem::path& dir) {
    study::SweepOptions o;
    o.scenePath = sourceDir() + "/scenes/glossy.xml";
    o.outDir = dir / "out";
    o.cacheDir = dir / "cache";
    o.render.width = 24;
    o.render.height = 18;
    o.render.quiet = true;
    o.rpps = {1, 4, 16};
    o.seeds = 2;
    o.referenceRpp = 256;
    o.gpu.validation = true;
    return o;
}

TEST(Sweep, WritesCsvPlotsAndReportAndReusesTheCachedReference) {
    const std::filesystem::path dir = artifactDir() + "/sweep";
    std::filesystem::remove_all(dir);
    const Scene scene = exampleScene("glossy");
    study::SweepOptions options = smallSweep(dir);
    std::ostringstream log;

    const auto start = std::chrono::steady_clock::now();
    const study::SweepResult first = study::runSweep(options, scene, log);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 60.0) << "the small sweep should take seconds";
    EXPECT_FALSE(first.reference.fromCache);
    EXPECT_EQ(first.validationMessages, "");
    ASSERT_EQ(first.devices.size(), 2u);

    const auto rows = readCsv(dir / "out" / "sweep.csv");
    ASSERT_FALSE(rows.empty());
    const std::vector<std::string> header = {"device", "sampler", "rpp", "seed", "time_s", "rmse", "relmse",
                                             "rmse_edge", "rmse_penumbra", "rmse_gloss", "rmse_defocus", "rmse_motion"};
    EXPECT_EQ(rows[0], header);
    ASSERT_EQ(rows.size(), 1u + 2u * 4u * 3u * 2u);  // devices x samplers x rpps x seeds
    std::set<std::string> settings;
    for (std::size_t r = 1; r < rows.size(); ++r) {
        ASSERT_EQ(rows[r].size(), header.size()) << "row " << r;
        settings.insert(rows[r][0] + "," + rows[r][1] + "," + rows[r][2] + "," + rows[r][3]);
        EXPECT_TRUE(rows[r][0] == "gpu" || rows[r][0] == "cpu");
        EXPECT_GT(std::stod(rows[r][4]), 0.0) << "time, row " << r;
        for (std::size_t c = 5; c < header.size(); ++c) {
            const double v = std::stod(rows[r][c]);
            // glossy.xml has no lens and nothing moves: those regions are empty, their RMSE nan.
            if (header[c] == "rmse_defocus" || header[c] == "rmse_motion")
                EXPECT_TRUE(std::isnan(v)) << header[c] << " = " << rows[r][c] << ", row " << r;
            else
                EXPECT_TRUE(std::isfinite(v) && v > 0.0) << header[c] << " = " << rows[r][c] << ", row " << r;
        }
    }
    EXPECT_EQ(settings.size(), rows.size() - 1) << "every (device, sampler, rpp, seed) once";

    for (const auto& png : {first.plots.errorVsTime, first.plots.errorVsRpp}) {
        ASSERT_TRUE(std::filesystem::exists(png)) << png;
        const Image image = readImage(png.string());
        EXPECT_EQ(image.width, 1500) << png;
        EXPECT_EQ(image.height, 900) << png;
        double sum = 0.0;
        for (const glm::vec3& p : image.pixels) sum += p.r + p.g + p.b;
        EXPECT_LT(sum, 3.0 * image.pixels.size() * 0.999) << png << " is blank";
    }

    const std::string report = readText(first.report);
    EXPECT_NE(report.find("## Convergence slopes"), std::string::npos);
    EXPECT_NE(report.find("## Cheapest setting reaching RMSE <= 0.01"), std::string::npos);
    for (const char* device : {"gpu", "cpu"})
        for (const char* sampler : {"random", "regular", "jittered", "sobol"})
            EXPECT_NE(report.find(std::string("| ") + device + " | " + sampler + " | "), std::string::npos)
                << device << " " << sampler;

    // The second run takes the reference from the cache; the CPU renders are deterministic, so with
    // the same reference their errors are the same to the last printed digit.
    options.devices = {study::Device::Cpu};
    options.referenceDevice = study::Device::Gpu;
    options.outDir = dir / "out2";
    const study::SweepResult second = study::runSweep(options, scene, log);
    EXPECT_TRUE(second.reference.fromCache);
    EXPECT_EQ(second.reference.key, first.reference.key);
    std::size_t matched = 0;
    for (const study::SweepRow& a : first.rows)
        for (const study::SweepRow& b : second.rows)
            if (a.device == study::Device::Cpu && b.device == a.device && a.sampler == b.sampler && a.rpp == b.rpp &&
                a.seed == b.seed) {
                EXPECT_EQ(a.error.rmse, b.error.rmse);
                ++matched;
            }
    EXPECT_EQ(matched, second.rows.size());
}

TEST(Sweep, CacheKeyChangesWithTheSceneAndTheImageOptionsOnly) {
    study::ReferenceSpec spec;
    const std::string text = "<scene/>";
    const std::string key = study::referenceKey(text, spec);
    study::ReferenceSpec threads = spec;
    threads.options.threads = 7;  // does not change the image
    EXPECT_EQ(study::referenceKey(text, threads), key);
    EXPECT_NE(study::referenceKey(text + " ", spec), key);
    auto changed = [&](auto edit) {
        study::ReferenceSpec s = spec;
        edit(s);
        return study::referenceKey(text, s);
    };
    EXPECT_NE(changed([](study::ReferenceSpec& s) { s.options.width = 251; }), key);
    EXPECT_NE(changed([](study::ReferenceSpec& s) { s.options.maxDepth = 2; }), key);
    EXPECT_NE(changed([](study::ReferenceSpec& s) { s.options.lightSamples = 4; }), key);
    EXPECT_NE(changed([](study::ReferenceSpec& s) { s.options.glossSamples = 4; }), key);
    EXPECT_NE(changed([](study::ReferenceSpec& s) { s.options.background = glm::vec3(0.5f); }), key);
    EXPECT_NE(changed([](study::ReferenceSpec& s) { s.options.camera = 1; }), key);
    EXPECT_NE(changed([](study::ReferenceSpec& s) { s.rpp = 2048; }), key);
    EXPECT_NE(changed([](study::ReferenceSpec& s) { s.device = study::Device::Cpu; }), key);
    // The lens may come from the command line (-d, --aperture), the shutter only from it.
    EXPECT_NE(changed([](study::ReferenceSpec& s) { s.lens = glm::vec2(8.0f, 0.3f); }), key);
    EXPECT_NE(changed([](study::ReferenceSpec& s) { s.options.shutter = glm::vec2(0.0f, 0.5f); }), key);
    EXPECT_EQ(changed([](study::ReferenceSpec& s) { s.options.shutter = glm::vec2(0.0f, 1.0f); }), key);  // the default
}

TEST(Sweep, BadOptionsAreRejectedWithTheirValue) {
    study::SweepOptions o = smallSweep(artifactDir() + "/sweep_bad");
    o.rpps = {4, 0};
    EXPECT_THROW(study::validateSweepOptions(o), std::invalid_argument);
    o.rpps = {4, 4};
    EXPECT_THROW(study::validateSweepOptions(o), std::invalid_argument);
    o.rpps = {4};
    o.seeds = 0;
    EXPECT_THROW(study::validateSweepOptions(o), std::invalid_argument);
    o.seeds = 1;
    o.render.seed = study::kReferenceSeedA;  // would correlate the sweep with the reference
    EXPECT_THROW(study::validateSweepOptions(o), std::invalid_argument);
}

RenderOptions onePixel() {
    RenderOptions o;
    o.width = 1;
    o.height = 1;
    return o;
}

TEST(RegionMasks, FindEdgesPenumbraeAndGloss) {
    const PixelScene edge = edgePixelScene();
    const study::RegionMasks e = study::findRegions(edge.scene, prepareCpuScene(edge.scene), onePixel());
    EXPECT_EQ(e.edge[0], 1);
    EXPECT_EQ(e.penumbra[0], 0);
    EXPECT_EQ(e.gloss[0], 0);

    const PixelScene penumbra = penumbraPixelScene();
    const study::RegionMasks p = study::findRegions(penumbra.scene, prepareCpuScene(penumbra.scene), onePixel());
    EXPECT_EQ(p.edge[0], 0);
    EXPECT_EQ(p.penumbra[0], 1);

    // soft_shadows has no glossy shader; glossy has three rough panels and a sharp one.
    RenderOptions o;
    o.width = 40;
    o.height = 30;
    const Scene soft = exampleScene("soft_shadows");
    const study::RegionMasks s = study::findRegions(soft, prepareCpuScene(soft), o);
    EXPECT_EQ(study::countPixels(s.gloss), 0u);
    EXPECT_GT(study::countPixels(s.penumbra), 0u);
    EXPECT_GT(study::countPixels(s.edge), 0u);
    EXPECT_EQ(s.edge[0], 0) << "the top-left pixel sees only background";
    const Scene glossy = exampleScene("glossy");
    const study::RegionMasks g = study::findRegions(glossy, prepareCpuScene(glossy), o);
    EXPECT_GT(study::countPixels(g.gloss), 0u);
    EXPECT_LT(study::countPixels(g.gloss), g.gloss.size() / 2);
    // Rough glass (glossy translucency) is in the gloss region too; the same glass smooth is not.
    Scene glass = exampleScene("translucency");
    const study::RegionMasks t = study::findRegions(glass, prepareCpuScene(glass), o);
    EXPECT_GT(study::countPixels(t.gloss), 0u);
    EXPECT_LT(study::countPixels(t.gloss), t.gloss.size() / 2);
    for (Shader& shader : glass.shaders) shader.roughness = 0.0f;
    EXPECT_EQ(study::countPixels(study::findRegions(glass, prepareCpuScene(glass), o).gloss), 0u);

    EXPECT_EQ(study::countPixels(g.defocus), 0u);
    EXPECT_EQ(study::countPixels(g.motion), 0u);

    // Defocus: the depth-of-field scene's spheres off the focus plane, not the one on it (nor the
    // same camera as a pinhole); motion: the moving instances, none with a shutter of zero length.
    Scene lens = exampleScene("depth_of_field");
    const study::RegionMasks d = study::findRegions(lens, prepareCpuScene(lens), o);
    EXPECT_GT(study::countPixels(d.defocus), 0u);
    EXPECT_LT(study::countPixels(d.defocus), d.defocus.size());
    EXPECT_EQ(study::countPixels(d.motion), 0u);
    lens.cameras[0].aperture = 0.0f;
    EXPECT_EQ(study::countPixels(study::findRegions(lens, prepareCpuScene(lens), o).defocus), 0u);
    const Scene moving = exampleScene("motion_blur");
    const study::RegionMasks m = study::findRegions(moving, prepareCpuScene(moving), o);
    EXPECT_GT(study::countPixels(m.motion), 0u);
    EXPECT_LT(study::countPixels(m.motion), m.motion.size() / 2);
    EXPECT_EQ(study::countPixels(m.defocus), 0u);
    RenderOptions still = o;
    still.shutter = glm::vec2(0.0f, 0.0f);
    EXPECT_EQ(study::countPixels(study::findRegions(moving, prepareCpuScene(moving), still).motion), 0u);

    // The masks survive their image form (the cache's), every region at once.
    for (const study::RegionMasks* masks : {&g, &d, &m}) {
        const study::RegionMasks back = study::masksFromImage(study::masksToImage(*masks));
        EXPECT_EQ(back.edge, masks->edge);
        EXPECT_EQ(back.penumbra, masks->penumbra);
        EXPECT_EQ(back.gloss, masks->gloss);
        EXPECT_EQ(back.defocus, masks->defocus);
        EXPECT_EQ(back.motion, masks->motion);
    }
}

}  // namespace
}  // namespace vkrt::test
