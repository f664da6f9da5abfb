#include "sweep.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>

#include "shared_renders.h"
#include "sweep_csv.h"
#include "sweep_report.h"
#include "vulkan_errors.h"

namespace vkrt::study {

namespace {

std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path.string() + ": cannot read the scene file");
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

bool uses(const std::vector<Device>& devices, Device d) { return std::find(devices.begin(), devices.end(), d) != devices.end(); }

// Opens the GPU when the sweep or its reference needs it; drops it (with a note) when there is no
// Vulkan device but the CPU can do the work alone.
std::unique_ptr<StudyRenderer> openRenderer(const SweepOptions& options, std::vector<Device>& devices,
                                            std::optional<Device>& referenceDevice, std::ostream& log) {
    const bool wantGpu = uses(devices, Device::Gpu) || referenceDevice == Device::Gpu;
    if (!wantGpu) return std::make_unique<StudyRenderer>(std::nullopt);
    try {
        return std::make_unique<StudyRenderer>(options.gpu);
    } catch (const VulkanUnavailable& e) {
        if (!uses(devices, Device::Cpu)) throw;
        log << "note: no usable Vulkan device (" << e.what() << "); sweeping the CPU reference only\n";
        devices.erase(std::remove(devices.begin(), devices.end(), Device::Gpu), devices.end());
        referenceDevice = Device::Cpu;
        return std::make_unique<StudyRenderer>(std::nullopt);
    }
}

// Every rank must sweep what rank 0 sweeps: a rank without the GPU rank 0 has would render other settings.
void checkSameDevices(WorkSharing& ranks, const std::vector<Device>& devices, Device referenceDevice) {
    if (ranks.size() == 1) return;
    std::vector<std::byte> mine;
    for (Device d : devices) mine.push_back(static_cast<std::byte>(d));
    mine.push_back(static_cast<std::byte>(referenceDevice));
    std::vector<std::byte> leader = mine;
    ranks.broadcast(leader);
    if (leader != mine)
        throw std::runtime_error("sweep: this rank's devices differ from rank 0's (a GPU missing on this machine?); "
                                 "every rank must sweep the same devices");
}

// The estimators weigh the light that a Diffuse surface can both hit and sample: shape emitters and
// the environment map (unless --no-environment). Without those (or without Diffuse) they compute
// the same image.
bool estimatorsDiffer(const Scene& scene, const RenderOptions& options) {
    const bool diffuse = std::any_of(scene.shaders.begin(), scene.shaders.end(), [](const Shader& s) { return s.diffuseBounce; });
    return diffuse && (!scene.emitters.empty() || (options.environment && scene.environment.faceSize > 0));
}

std::string joined(const std::vector<int>& values) {
    std::string s;
    for (int v : values) {
        if (!s.empty()) s += ',';
        s += std::to_string(v);  // appended separately: GCC 12 warns falsely (-Wrestrict) on "," + string
    }
    return s;
}

}  // namespace

void validateSweepOptions(const SweepOptions& o) {
    auto fail = [](const std::string& what) { throw std::invalid_argument("sweep: " + what); };
    if (o.outDir.empty()) fail("--out DIR is required");
    if (o.rpps.empty()) fail("--rpp needs at least one value");
    for (int r : o.rpps)
        if (r < 1) fail("--rpp values must be at least 1, not " + std::to_string(r));
    std::vector<int> sorted = o.rpps;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) fail("--rpp lists a value twice: " + joined(o.rpps));
    if (o.seeds < 1) fail("--seeds must be at least 1, not " + std::to_string(o.seeds));
    if (o.samplers.empty()) fail("--samplers needs at least one sampler");
    if (o.estimators.empty()) fail("--estimators needs at least one estimator");
    for (std::size_t i = 0; i < o.estimators.size(); ++i)
        if (std::find(o.estimators.begin(), o.estimators.begin() + i, o.estimators[i]) != o.estimators.begin() + i)
            fail("--estimators lists " + estimatorName(o.estimators[i]) + " twice");
    if (o.devices.empty()) fail("no device to sweep");
    {
        // The bounds whether or not --targets uses them, as the render command checks its own.
        adaptive::AdaptiveOptions a = o.adaptive;
        a.targetError = 0.01;
        a.seconds.reset();
        try {
            adaptive::checkAdaptiveOptions(a);
        } catch (const std::invalid_argument& e) {
            fail(e.what());
        }
    }
    for (std::size_t i = 0; i < o.targets.size(); ++i)
        if (std::find(o.targets.begin(), o.targets.begin() + static_cast<std::ptrdiff_t>(i), o.targets[i]) !=
            o.targets.begin() + static_cast<std::ptrdiff_t>(i))
            fail("--targets lists " + std::to_string(o.targets[i]) + " twice");
    for (double t : o.targets) {
        adaptive::AdaptiveOptions a = o.adaptive;
        a.targetError = t;
        a.seconds.reset();
        try {
            adaptive::checkAdaptiveOptions(a);
        } catch (const std::invalid_argument& e) {
            fail(std::string("--targets: ") + e.what());
        }
    }
    if (!o.targets.empty() && o.adaptiveSampler != SamplerKind::Sobol2 && o.adaptiveSampler != SamplerKind::Random)
        fail("--targets renders with sobol2 or random, not " + samplerName(o.adaptiveSampler));
    if (o.referenceRpp < 2 || o.referenceRpp % 2 != 0)
        fail("--reference-rpp must be even (two halves) and at least 2, not " + std::to_string(o.referenceRpp));
    if (!(o.targetRmse > 0.0)) fail("--target-rmse must be positive, not " + std::to_string(o.targetRmse));
    for (int s = 0; s < o.seeds; ++s) {
        const std::uint32_t seed = o.render.seed + static_cast<std::uint32_t>(s);
        if (seed == kReferenceSeedA || seed == kReferenceSeedB)
            fail("seed " + std::to_string(seed) + " is one of the reference's seeds; choose another --seed");
    }
}

SweepResult runSweep(const SweepOptions& options, const Scene& scene, std::ostream& log, WorkSharing* sharing) {
    validateSweepOptions(options);
    NoSharing alone;
    WorkSharing& ranks = sharing ? *sharing : alone;
    SweepResult result;
    result.devices = options.devices;
    std::optional<Device> referenceDevice = options.referenceDevice;
    if (!referenceDevice) referenceDevice = uses(options.devices, Device::Gpu) ? Device::Gpu : Device::Cpu;
    std::unique_ptr<StudyRenderer> renderer = openRenderer(options, result.devices, referenceDevice, log);
    checkSameDevices(ranks, result.devices, *referenceDevice);

    const PreparedScene prepared = renderer->prepare(scene);  // once: every render below reuses it
    ReferenceSpec spec;
    spec.options = options.render;
    spec.options.quiet = true;
    // Every estimator has the same expectation, so one reference serves them all and its key leaves
    // the estimator out (reference_cache.h); it is rendered with the one of least variance.
    spec.options.estimator = kReferenceEstimator;
    spec.rpp = options.referenceRpp;
    spec.sampler = options.referenceSampler;
    spec.device = *referenceDevice;
    const Camera& camera = scene.cameras.at(options.render.camera);
    spec.lens = glm::vec2(camera.focusDistance, camera.aperture);

    // The (seed, rpp, sampler, estimator, device) settings in interleaved order: the machine's speed
    // drifts, and interleaving spreads the drift over every setting instead of biasing whichever ran
    // last. MPI ranks share them by their index in this list (shared_renders.h).
    struct Setting {
        int seedIndex, rpp;
        SamplerKind sampler;
        Estimator estimator;
        Device device;
        double target = 0.0;  // adaptive sampling's target error; 0: uniform at rpp
    };
    std::vector<Setting> settings;
    for (int s = 0; s < options.seeds; ++s) {
        for (int rpp : options.rpps)
            for (SamplerKind sampler : options.samplers)
                for (Estimator estimator : options.estimators)
                    for (Device device : result.devices) settings.push_back({s, rpp, sampler, estimator, device});
        for (double target : options.targets)
            for (Estimator estimator : options.estimators)
                for (Device device : result.devices)
                    settings.push_back({s, static_cast<int>(options.adaptive.maxRpp), options.adaptiveSampler, estimator, device, target});
    }
    const auto settingOptions = [&](const Setting& setting) {
        RenderOptions o = options.render;
        o.quiet = true;
        o.samplesPerPixel = setting.rpp;
        o.sampler = setting.sampler;
        o.estimator = setting.estimator;
        o.seed = options.render.seed + static_cast<std::uint32_t>(setting.seedIndex);
        return o;
    };
    const auto renderSetting = [&](std::size_t i) {
        const Setting& setting = settings[i];
        if (setting.target <= 0.0) return renderer->render(setting.device, prepared, settingOptions(setting));
        adaptive::AdaptiveOptions a = options.adaptive;
        a.targetError = setting.target;
        a.seconds.reset();
        return renderer->renderAdaptive(setting.device, prepared, settingOptions(setting), a);
    };

    if (ranks.rank() != 0) {  // a helper: bands of the reference, then its share of the settings
        RenderOptions half = spec.options;
        half.sampler = spec.sampler;
        serveHalves(ranks, *renderer, prepared, spec.device, half);
        renderShared(ranks, settings.size(), renderSetting, {});
        result.leader = false;
        return result;
    }

    if (options.estimators.size() > 1 && !estimatorsDiffer(scene, options.render))
        log << "note: every estimator renders the same image of " << options.scenePath.string()
            << ": it has no Diffuse surface, or nothing but the bounce finds its light (no shape emitter or environment "
               "map; docs/RENDERING.md §5); their times still differ\n";
    const std::string sceneText = readText(options.scenePath);
    std::error_code ec;
    std::filesystem::create_directories(options.outDir, ec);
    if (ec) throw std::runtime_error("sweep: cannot create the output directory " + options.outDir.string() + ": " + ec.message());

    const std::filesystem::path cacheDir = options.cacheDir.empty() ? defaultCacheDir() : options.cacheDir;
    {
        // The helpers render bands of the halves while rank 0 makes the reference; they are told
        // when it is done even when it failed here (the error then ends the job).
        const HalfRenderer shared = ranks.size() > 1 ? sharedHalfRenderer(ranks, *renderer, prepared, spec.device) : HalfRenderer{};
        result.reference = loadOrRenderReference(*renderer, prepared, sceneText, spec, cacheDir, log, shared);
        if (ranks.size() > 1) endHalves(ranks);
    }
    const Reference& ref = result.reference;

    renderShared(ranks, settings.size(), renderSetting, [&](std::size_t i, const TimedRender& r) {
        const Setting& setting = settings[i];
        const RenderOptions o = settingOptions(setting);
        const int rpp = setting.target > 0.0 ? static_cast<int>(std::lround(r.meanRpp)) : setting.rpp;
        SweepRow row{setting.device, setting.sampler, setting.estimator, setting.target, rpp, o.seed, r.seconds,
                     measureError(r.image, ref.image, ref.masks)};
        result.rows.push_back(row);
        if (!options.render.quiet) {
            char line[240];
            char target[48] = "";
            if (setting.target > 0.0) std::snprintf(target, sizeof target, " (adaptive, target %g)", setting.target);
            std::snprintf(line, sizeof line, "%s %-8s %-11s %5d rpp%s seed %u: %8.3f s  rmse %.3e\n",
                          deviceName(setting.device).c_str(), samplerName(setting.sampler).c_str(),
                          estimatorName(setting.estimator).c_str(), rpp, target, o.seed, r.seconds, row.error.rmse);
            log << line << std::flush;
        }
    });

    result.csv = options.outDir / "sweep.csv";
    writeSweepCsv(result.rows, result.csv);
    result.points = summarize(result.rows);

    SweepReportInput report;
    report.scenePath = options.scenePath.string();
    const RenderOptions& r = options.render;
    std::ostringstream settingsLine;
    settingsLine << r.width << "x" << r.height << ", max depth " << r.maxDepth << ", " << r.lightSamples
             << " light sample(s) and " << r.glossSamples << " gloss sample(s) per pixel sample; rpp "
             << joined(options.rpps) << "; " << options.seeds << " seed(s) from " << r.seed << ";";
    if (!options.targets.empty()) {
        settingsLine << " adaptive (" << samplerName(options.adaptiveSampler) << ", " << options.adaptive.minRpp << "-"
                     << options.adaptive.maxRpp << " rpp, its rpp the mean) at target errors";
        for (double t : options.targets) settingsLine << " " << t;
        settingsLine << ";";
    }
    settingsLine << " estimators:";
    for (Estimator e : options.estimators) settingsLine << " " << estimatorName(e);
    settingsLine << "; devices:";
    for (Device d : result.devices)
        settingsLine << " " << (d == Device::Gpu ? "gpu (" + renderer->gpuDeviceName() + ")" : std::string("cpu"));
    settingsLine << ". Time = wall time of one render call (scene loaded and BVH built beforehand; GPU kernel "
                "compiled beforehand).";
    report.settings = settingsLine.str();
    std::ostringstream refLine;
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.1f", ref.seconds);
    refLine << options.referenceRpp << " rpp, " << samplerName(spec.sampler) << " sampler, "
            << estimatorName(spec.options.estimator) << " estimator (for every estimator: they have the same expectation), on the "
            << deviceName(spec.device)
            << (ref.fromCache ? ", from the cache " : ", rendered in " + std::string(seconds) + " s and cached as ") << "`"
            << ref.imagePath.string() << "`.";
    report.referenceLine = refLine.str();
    const PixelMask* masks[kRegionCount] = {nullptr,           &ref.masks.edge,     &ref.masks.penumbra,
                                            &ref.masks.gloss,  &ref.masks.defocus,  &ref.masks.motion,
                                            &ref.masks.indirect, &ref.masks.emitter};
    for (Region g : kRegions) {
        const int i = static_cast<int>(g);
        report.referenceMse[i] = meanOverRegion(ref.noise, masks[i]);
        report.regionPixels[i] = masks[i] ? countPixels(*masks[i]) : ref.image.pixels.size();
    }
    report.points = result.points;
    report.targetRmse = options.targetRmse;
    report.files = {"sweep.csv", "error_vs_time.png", "error_vs_rpp.png",
                    "regions.png (left: red edge, green penumbra, blue gloss; middle: red defocus, green motion; "
                    "right: red indirect, green emitter, so emitter pixels are yellow)",
                    "reference.png", "plots/ (gnuplot data and script)"};
    result.report = options.outDir / "report.md";
    writeSweepReport(report, result.report);
    writeImage(regionsPicture(ref.masks), (options.outDir / "regions.png").string());
    writeImage(ref.image, (options.outDir / "reference.png").string());

    std::array<double, kRegionCount> referenceRmse{};
    for (std::size_t i = 0; i < kRegionCount; ++i) referenceRmse[i] = std::sqrt(report.referenceMse[i]);
    if (auto validation = renderer->validationLog(); validation && validation->count() > 0)
        result.validationMessages = validation->joined();
    result.plots = plotSweep(result.points, referenceRmse, report.regionPixels,
                             options.scenePath.filename().string() + " " + std::to_string(r.width) + "x" + std::to_string(r.height),
                             options.outDir);
    return result;
}

}  // namespace vkrt::study
