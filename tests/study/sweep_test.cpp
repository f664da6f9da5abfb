// `vkrt sweep` end to end on a small scene (both devices, validation on): the CSV's columns and
// rows, the plots as real PNGs, the report, the reference cache (hit on the second run, with the
// same errors), the estimator axis against one reference, and the region masks on scenes whose
// regions are known.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cpu_renderer.h"
#include "diagnostics.h"
#include "reference_cache.h"
#include "region_masks.h"
#include "scene_accel.h"
#include "scene_loader.h"
#include "study_scenes.h"
#include "sweep.h"
#include "sweep_report.h"
#include "test_paths.h"

namespace vkrt::test {
namespace {

// The fields of a CSV line, an empty last one included (getline alone drops it).
std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> fields;
    std::stringstream s(line);
    for (std::string f; std::getline(s, f, ',');) fields.push_back(f);
    if (!line.empty() && line.back() == ',') fields.emplace_back();
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

Scene loadFile(const std::filesystem::path& path) {
    Diagnostics diagnostics;
    return loadScene(path.string(), LoadOptions{}, diagnostics);
}

// emitterTest.json (a small sphere emitter over a ground and a big sphere) with its Lambertian
// receivers made Diffuse: the estimators differ there. Written into `dir`.
std::filesystem::path diffuseEmitterScene(const std::filesystem::path& dir) {
    std::string text = readText(jsonSceneDir() + "/emitterTest.json");
    const std::string from = "\"Lambertian\"", to = "\"Diffuse\"";
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at)) text.replace(at, from.size(), to);
    std::filesystem::create_directories(dir);
    const std::filesystem::path path = dir / "emitterTest_diffuse.json";
    std::ofstream(path) << text;
    return path;
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
    const std::vector<std::string> header = {"device",        "sampler",       "estimator",  "rpp",
                                             "seed",          "time_s",        "rmse",       "relmse",
                                             "rmse_edge",     "rmse_penumbra", "rmse_gloss", "rmse_defocus",
                                             "rmse_motion",   "rmse_indirect", "rmse_emitter", "adaptive_target"};
    EXPECT_EQ(rows[0], header);
    ASSERT_EQ(rows.size(), 1u + 2u * 4u * 3u * 2u);  // devices x samplers x rpps x seeds
    std::set<std::string> settings;
    for (std::size_t r = 1; r < rows.size(); ++r) {
        ASSERT_EQ(rows[r].size(), header.size()) << "row " << r;
        settings.insert(rows[r][0] + "," + rows[r][1] + "," + rows[r][3] + "," + rows[r][4]);
        EXPECT_TRUE(rows[r][0] == "gpu" || rows[r][0] == "cpu");
        EXPECT_EQ(rows[r][2], "mis") << "the default estimator only, row " << r;
        EXPECT_GT(std::stod(rows[r][5]), 0.0) << "time, row " << r;
        EXPECT_EQ(rows[r].back(), "") << "a uniform render has no adaptive target, row " << r;
        for (std::size_t c = 6; c + 1 < header.size(); ++c) {
            const double v = std::stod(rows[r][c]);
            // glossy.xml has no lens, nothing moves and nothing is path traced: those regions are
            // empty, their RMSE nan.
            if (header[c] == "rmse_defocus" || header[c] == "rmse_motion" || header[c] == "rmse_indirect" ||
                header[c] == "rmse_emitter")
                EXPECT_TRUE(std::isnan(v)) << header[c] << " = " << rows[r][c] << ", row " << r;
            else
                EXPECT_TRUE(std::isfinite(v) && v > 0.0) << header[c] << " = " << rows[r][c] << ", row " << r;
        }
    }
    EXPECT_EQ(settings.size(), rows.size() - 1) << "every (device, sampler, rpp, seed) once";

    for (const auto& png : {first.plots.errorVsTime, first.plots.errorVsRpp}) {
        ASSERT_TRUE(std::filesystem::exists(png)) << png;
        const Image image = readImage(png.string());
        EXPECT_EQ(image.width, 2000) << png;
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
            EXPECT_NE(report.find(std::string("| ") + device + " | " + sampler + " | mis | "), std::string::npos)
                << device << " " << sampler;
    EXPECT_EQ(report.find("## Estimators at equal time"), std::string::npos) << "one estimator: nothing to compare";

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

// --targets: adaptive renders form a series of their own on both devices, each point at its mean
// rpp, with less error at the smaller target, in the CSV, the report and the plots.
TEST(Sweep, AdaptiveTargetsFormTheirOwnSeries) {
    const std::filesystem::path dir = artifactDir() + "/sweep_adaptive";
    std::filesystem::remove_all(dir);
    const Scene scene = exampleScene("glossy");
    study::SweepOptions options = smallSweep(dir);
    options.render.width = 40;
    options.render.height = 30;
    options.samplers = {SamplerKind::Jittered};
    options.rpps = {4, 16};
    options.targets = {0.05, 0.02};
    options.adaptive.maxRpp = 256;
    std::ostringstream log;
    const study::SweepResult result = study::runSweep(options, scene, log);
    EXPECT_EQ(result.validationMessages, "");
    std::map<std::pair<study::Device, double>, double> mse;  // per device and target, over seeds
    int adaptiveRows = 0;
    for (const study::SweepRow& r : result.rows) {
        if (r.adaptiveTarget == 0.0) continue;
        ++adaptiveRows;
        EXPECT_EQ(r.sampler, SamplerKind::Sobol2);
        EXPECT_GE(r.rpp, 16) << "the mean is at least --min-rpp";
        EXPECT_LE(r.rpp, 256);
        mse[{r.device, r.adaptiveTarget}] += r.error.rmse * r.error.rmse;
    }
    EXPECT_EQ(adaptiveRows, 2 * 2 * 2);  // devices x targets x seeds
    for (study::Device d : {study::Device::Gpu, study::Device::Cpu})
        EXPECT_LT(mse[std::pair(d, 0.02)], mse[std::pair(d, 0.05)]) << study::deviceName(d);
    const auto rows = readCsv(dir / "out" / "sweep.csv");
    int targets = 0;
    for (std::size_t r = 1; r < rows.size(); ++r) targets += rows[r].back() == "0.05" || rows[r].back() == "0.02";
    EXPECT_EQ(targets, adaptiveRows);
    const std::string report = readText(result.report);
    for (const char* device : {"gpu", "cpu"})
        EXPECT_NE(report.find(std::string("| ") + device + " | sobol2 adaptive | mis | "), std::string::npos) << device;
    EXPECT_TRUE(std::filesystem::exists(dir / "out" / "plots" / "cpu_sobol2_adaptive_mis.dat"));
    EXPECT_TRUE(std::filesystem::exists(result.plots.errorVsTime));
    options.targets = {0.00001};
    EXPECT_THROW(study::validateSweepOptions(options), std::invalid_argument);
}

TEST(Sweep, EveryEstimatorIsMeasuredAgainstTheOneReference) {
    VKRT_SKIP_WITHOUT(jsonSceneDir() + "/emitterTest.json");
    const std::filesystem::path dir = artifactDir() + "/sweep_estimators";
    std::filesystem::remove_all(dir);
    study::SweepOptions options = smallSweep(dir);
    options.scenePath = diffuseEmitterScene(dir);
    const Scene scene = loadFile(options.scenePath);
    options.render.background = glm::vec3(0.0f);  // the emitter alone lights the scene (its sky is grey)
    options.devices = {study::Device::Cpu};
    options.samplers = {SamplerKind::Jittered};
    const std::vector<Estimator> all = {Estimator::Bounce, Estimator::Nee, Estimator::MisBalance, Estimator::MisPower};
    options.estimators = all;
    std::ostringstream log;
    const study::SweepResult swept = study::runSweep(options, scene, log);
    EXPECT_FALSE(swept.reference.fromCache);

    // One row per estimator, rpp and seed, in the CSV too.
    ASSERT_EQ(swept.rows.size(), all.size() * 3u * 2u);
    const auto csv = readCsv(dir / "out" / "sweep.csv");
    ASSERT_EQ(csv.size(), 1u + swept.rows.size());
    EXPECT_EQ(csv[0][2], "estimator");
    for (Estimator e : all) {
        EXPECT_EQ(std::count_if(swept.rows.begin(), swept.rows.end(), [e](const study::SweepRow& r) { return r.estimator == e; }), 6)
            << estimatorName(e);
        EXPECT_EQ(std::count_if(csv.begin(), csv.end(), [e](const auto& row) { return row[2] == estimatorName(e); }), 6)
            << estimatorName(e);
    }
    // The path-traced regions are there, so their errors are numbers.
    for (const study::SweepRow& r : swept.rows) {
        EXPECT_TRUE(std::isfinite(r.error.rmseIndirect) && r.error.rmseIndirect > 0.0) << estimatorName(r.estimator);
        EXPECT_TRUE(std::isfinite(r.error.rmseEmitter) && r.error.rmseEmitter > 0.0) << estimatorName(r.estimator);
    }
    // Where the small emitter lights Diffuse surfaces, its light samples beat the bounce that must
    // hit it, at equal rpp (docs/SAMPLING.md §4 measures equal time). Measured at 16 rpp: RMSE in
    // the emitter region 1.8x lower (the pixels' edges, 24x18 pixels for a whole scene, are half of
    // it for every estimator), relative MSE 15x lower.
    auto at16 = [&](Estimator e) {
        for (const study::SweepPoint& p : swept.points)
            if (p.estimator == e && p.rpp == 16) return p;
        return study::SweepPoint{};
    };
    for (Estimator e : {Estimator::Nee, Estimator::MisBalance, Estimator::MisPower}) {
        const int emitter = static_cast<int>(study::Region::Emitter);
        EXPECT_LT(1.5 * at16(e).rmse[emitter], at16(Estimator::Bounce).rmse[emitter]) << estimatorName(e);
        EXPECT_LT(5.0 * at16(e).relMse, at16(Estimator::Bounce).relMse) << estimatorName(e);
    }

    const std::string report = readText(swept.report);
    EXPECT_NE(report.find("## Estimators at equal time"), std::string::npos);
    for (Estimator e : all)
        EXPECT_NE(report.find("| cpu | jittered | " + estimatorName(e) + " | "), std::string::npos) << estimatorName(e);

    // The reference is rendered with MIS whatever is swept, and its key leaves the estimator out:
    // a sweep of another estimator alone takes it from the cache.
    EXPECT_NE(readText(dir / "cache" / "references" / (swept.reference.key + ".txt")).find("estimator mis "), std::string::npos);
    options.estimators = {Estimator::Bounce};
    options.outDir = dir / "out2";
    const study::SweepResult bounce = study::runSweep(options, scene, log);
    EXPECT_TRUE(bounce.reference.fromCache);
    EXPECT_EQ(bounce.reference.key, swept.reference.key);
    for (const study::SweepRow& a : swept.rows)
        for (const study::SweepRow& b : bounce.rows)
            if (a.estimator == b.estimator && a.rpp == b.rpp && a.seed == b.seed) {
                EXPECT_EQ(a.error.rmse, b.error.rmse);
            }
}

TEST(Sweep, EqualTimeInterpolatesBetweenTheSettingsAroundIt) {
    auto point = [](Estimator e, int rpp, double seconds, double rmse) {
        study::SweepPoint p;
        p.estimator = e;
        p.rpp = rpp;
        p.seconds = seconds;
        p.rmse.fill(rmse);
        return p;
    };
    // bounce: 0.1 s -> 0.4, 0.4 s -> 0.1 (RMSE ~ 1 / (25 t)); nee: 0.2 s -> 0.05, 0.8 s -> 0.025.
    const std::vector<study::SweepPoint> points = {point(Estimator::Bounce, 1, 0.1, 0.4), point(Estimator::Bounce, 4, 0.4, 0.1),
                                                   point(Estimator::Nee, 1, 0.2, 0.05), point(Estimator::Nee, 4, 0.8, 0.025)};
    const double t = study::commonTime(points, study::Device::Cpu, SamplerKind::Jittered);
    EXPECT_DOUBLE_EQ(t, 0.4);  // bounce's longest
    const study::Series bounce{study::Device::Cpu, SamplerKind::Jittered, Estimator::Bounce};
    const study::Series nee{study::Device::Cpu, SamplerKind::Jittered, Estimator::Nee};
    EXPECT_DOUBLE_EQ(study::rmseAtTime(points, bounce, study::Region::All, t), 0.1);
    EXPECT_NEAR(study::rmseAtTime(points, nee, study::Region::All, t), 0.05 * std::pow(0.5, 0.5), 1e-12);  // halfway in log time
    EXPECT_TRUE(std::isnan(study::rmseAtTime(points, nee, study::Region::All, 0.1)));  // before nee's first setting
    // No time both reached: nothing to compare.
    const std::vector<study::SweepPoint> apart = {point(Estimator::Bounce, 1, 0.1, 0.4), point(Estimator::Nee, 1, 0.2, 0.05)};
    EXPECT_TRUE(std::isnan(study::commonTime(apart, study::Device::Cpu, SamplerKind::Jittered)));
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
    EXPECT_NE(changed([](study::ReferenceSpec& s) { s.options.environment = false; }), key);  // --no-environment
    // Every estimator has the same expectation: one reference serves them all.
    for (Estimator e : {Estimator::Bounce, Estimator::Nee, Estimator::MisBalance, Estimator::MisPower})
        EXPECT_EQ(changed([e](study::ReferenceSpec& s) { s.options.estimator = e; }), key) << estimatorName(e);
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
    o.render.seed = 0;
    o.estimators = {};
    EXPECT_THROW(study::validateSweepOptions(o), std::invalid_argument);
    o.estimators = {Estimator::Nee, Estimator::Bounce, Estimator::Nee};
    EXPECT_THROW(study::validateSweepOptions(o), std::invalid_argument);
    o.estimators = {Estimator::Nee, Estimator::Bounce};
    EXPECT_NO_THROW(study::validateSweepOptions(o));
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
    EXPECT_EQ(study::countPixels(g.indirect), 0u);
    EXPECT_EQ(study::countPixels(g.emitter), 0u);

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

TEST(RegionMasks, FindPathTracedPixelsAndTheEmittersLightingThem) {
    VKRT_SKIP_WITHOUT(jsonSceneDir() + "/emitterTest.json");
    RenderOptions o;
    o.width = 40;
    o.height = 30;

    // Lambertian receivers: the shape emitter lights them (its soft shadow is a penumbra) but
    // nothing is path traced, so every estimator computes the same image: no indirect or emitter pixel.
    const Scene lambertian = loadFile(jsonSceneDir() + "/emitterTest.json");
    const study::RegionMasks l = study::findRegions(lambertian, prepareCpuScene(lambertian), o);
    EXPECT_EQ(study::countPixels(l.indirect), 0u);
    EXPECT_EQ(study::countPixels(l.emitter), 0u);
    EXPECT_GT(study::countPixels(l.penumbra), 0u);

    // The same receivers Diffuse: path traced; the emitter lights most of them, but not the ground
    // in the big sphere's shadow nor the sphere's far side. Emitter pixels are indirect ones.
    const Scene diffuse = loadFile(diffuseEmitterScene(artifactDir() + "/region_masks"));
    const study::RegionMasks d = study::findRegions(diffuse, prepareCpuScene(diffuse), o);
    EXPECT_GT(study::countPixels(d.indirect), d.indirect.size() / 2);
    EXPECT_GT(study::countPixels(d.emitter), 0u);
    EXPECT_LT(study::countPixels(d.emitter), study::countPixels(d.indirect));
    for (std::size_t k = 0; k < d.emitter.size(); ++k)
        if (d.emitter[k]) {
            EXPECT_EQ(d.indirect[k], 1) << "pixel " << k;
        }
    EXPECT_EQ(d.penumbra, l.penumbra) << "the penumbra does not depend on the receivers' shader";
    // At -k 0 a Diffuse hit is black: nothing is path traced.
    RenderOptions flat = o;
    flat.maxDepth = 0;
    const study::RegionMasks f = study::findRegions(diffuse, prepareCpuScene(diffuse), flat);
    EXPECT_EQ(study::countPixels(f.indirect), 0u);
    EXPECT_EQ(study::countPixels(f.emitter), 0u);

    // Diffuse under point lights only: path traced, but no emitter to sample.
    if (std::filesystem::exists(jsonSceneDir() + "/diffuseScene.json")) {
        const Scene points = loadFile(jsonSceneDir() + "/diffuseScene.json");
        const study::RegionMasks p = study::findRegions(points, prepareCpuScene(points), o);
        EXPECT_GT(study::countPixels(p.indirect), 0u);
        EXPECT_EQ(study::countPixels(p.emitter), 0u);
    }

    // Through mirrors: glossy.xml with Diffuse spheres. The panels show them one level deeper, so
    // at -k 1 (where a Diffuse hit of depth 1 is black) only the spheres seen directly are indirect.
    Scene glossy = exampleScene("glossy");
    for (Shader& shader : glossy.shaders)
        if (shader.name == "red" || shader.name == "green" || shader.name == "blue") shader.diffuseBounce = true;
    const std::size_t deep = study::countPixels(study::findRegions(glossy, prepareCpuScene(glossy), o).indirect);
    RenderOptions shallowOptions = o;
    shallowOptions.maxDepth = 1;
    const std::size_t shallow = study::countPixels(study::findRegions(glossy, prepareCpuScene(glossy), shallowOptions).indirect);
    EXPECT_GT(shallow, 0u);
    EXPECT_GT(deep, shallow);

    const study::RegionMasks back = study::masksFromImage(study::masksToImage(d));
    EXPECT_EQ(back.indirect, d.indirect);
    EXPECT_EQ(back.emitter, d.emitter);
    EXPECT_EQ(back.penumbra, d.penumbra);
}

}  // namespace
}  // namespace vkrt::test
