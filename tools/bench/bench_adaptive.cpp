// `vkrt-bench adaptive SCENE... [-w W] [--target E] [--reference-rpp R] [--max-rpp M] [-k DEPTH] [--repeat N]`:
// adaptive sampling's calibration and efficiency (docs/SAMPLING.md §7), on the CPU reference.
// Per scene, with its default camera and options:
//  - a reference: a uniform sobol2 render of R rpp (seed 1000), its own squared error estimated
//    from its halves and taken out of every true error below;
//  - the adaptive render at --target-error E (seed 0): its estimated relative RMSE, the true one
//    against the reference, their ratio, and the standard deviation of the per-pixel z-scores
//    (adaptive - reference) / sqrt(se_adaptive^2 + se_reference^2) over the noisy pixels (those
//    whose standard error is at least a quarter of the image's RMS standard error);
//  - uniform jittered (the course's sampler) and uniform sobol2 renders at 4, 16, 64, ... rpp until
//    their true error is below the adaptive one's, and the time each needs for that error,
//    interpolated in log-log between the two renders around it: the adaptive speed-up is that
//    time over the adaptive render's (rounds, estimates and plans included).
// Times are render times on this machine (no load, no tree build), the same clock for all three,
// each the median of --repeat runs (default 3). --map-radius R: the error map's smoothing window
// for the z-scores (default kErrorMapRadius, as vkrt's --error-map).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "adaptive_render.h"
#include "bench_args.h"
#include "bench_command.h"
#include "bench_timing.h"
#include "cpu_renderer.h"
#include "scene_loader.h"

namespace vkrt::bench {

namespace {

struct Args {
    std::vector<std::string> scenes;
    int size = 64;
    double target = 0.02;
    std::uint32_t referenceRpp = 4096;
    std::uint32_t maxRpp = 4096;
    std::uint32_t minRpp = adaptive::AdaptiveOptions{}.minRpp;
    int maxDepth = 4;
    int mapRadius = adaptive::kErrorMapRadius;  // the error map's smoothing window (error_estimate.h)
    int repeat = 3;     // each timed render this often, the median time kept
};

Args parseArgs(const std::vector<std::string>& args) {
    Args a;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const bool value = i + 1 < args.size();
        if (args[i] == "-w" && value) a.size = positiveInt(args[++i], "-w");
        else if (args[i] == "--target" && value) a.target = nonNegativeNumber(args[++i], "--target");
        else if (args[i] == "--reference-rpp" && value) a.referenceRpp = static_cast<std::uint32_t>(positiveInt(args[++i], "--reference-rpp"));
        else if (args[i] == "--min-rpp" && value) a.minRpp = static_cast<std::uint32_t>(positiveInt(args[++i], "--min-rpp"));
        else if (args[i] == "--max-rpp" && value) a.maxRpp = static_cast<std::uint32_t>(positiveInt(args[++i], "--max-rpp"));
        else if (args[i] == "-k" && value) a.maxDepth = positiveInt(args[++i], "-k");
        else if (args[i] == "--map-radius" && value) a.mapRadius = positiveInt(args[++i], "--map-radius");
        else if (args[i] == "--repeat" && value) a.repeat = positiveInt(args[++i], "--repeat");
        else if (args[i].rfind("-", 0) == 0) throw std::runtime_error("unknown option " + args[i]);
        else a.scenes.push_back(args[i]);
    }
    if (a.scenes.empty())
        throw std::runtime_error("usage: vkrt-bench adaptive SCENE... [-w W] [--target E] [--reference-rpp R] [--min-rpp M] [--max-rpp M] [-k DEPTH] [--map-radius R] [--repeat N]");
    return a;
}

struct Reference {
    std::vector<glm::dvec3> mean;
    std::vector<glm::vec3> standardError;
    double mse = 0.0;            // its own squared error per value, estimated from its halves
    double meanLuminance = 0.0;
};

// The true MSE per value of `image` against the reference, the reference's own MSE taken out.
double trueMse(const Reference& ref, const std::vector<glm::dvec3>& image) {
    double squares = 0.0;
    for (std::size_t p = 0; p < image.size(); ++p) {
        const glm::dvec3 d = image[p] - ref.mean[p];
        squares += glm::dot(d, d);
    }
    return std::max(squares / (3.0 * image.size()) - ref.mse, 0.0);
}

struct UniformPoint {
    double seconds, error;
};

// The time a sampler's uniform renders need for `error`: log-log interpolation between the two
// renders around it (or the line through the last two when none is below it).
double timeFor(const std::vector<UniformPoint>& points, double error) {
    if (points.size() < 2) return NAN;
    std::size_t i = 1;
    while (i + 1 < points.size() && points[i].error > error) ++i;
    const UniformPoint &a = points[i - 1], &b = points[i];
    const double slope = std::log(b.seconds / a.seconds) / std::log(b.error / a.error);
    return a.seconds * std::pow(error / a.error, slope);
}

}  // namespace

int runAdaptiveBench(const std::vector<std::string>& arguments) {
    const Args a = parseArgs(arguments);
    std::printf("adaptive sampling, %dx%d, --target-error %g, --min-rpp %u, --max-rpp %u, reference %u rpp sobol2; CPU, "
                "times in s (median of %d)\n",
                a.size, a.size, a.target, a.minRpp, a.maxRpp, a.referenceRpp, a.repeat);
    std::printf("%-40s %6s %10s %9s %9s %6s %6s %8s %8s %8s %5s\n", "scene", "rounds", "rpp", "estimate", "true", "ratio",
                "z-std", "time", "x jitt", "x sobol2", "met");
    for (const std::string& path : a.scenes) {
        Diagnostics diagnostics;  // the course files' warnings are not this tool's concern
        LoadOptions load{false, /*localOrigin=*/true};
        load.shaderEmitters = true;
        const Scene scene = loadScene(path, load, diagnostics);
        const SceneAccel accel = prepareCpuScene(scene);
        RenderOptions o;
        o.width = o.height = a.size;
        o.camera = scene.defaultCamera;
        o.maxDepth = a.maxDepth;
        o.quiet = true;
        const std::size_t pixels = static_cast<std::size_t>(a.size) * a.size;

        Reference ref;
        {
            RenderOptions r = o;
            r.sampler = SamplerKind::Sobol2;
            r.samplesPerPixel = static_cast<int>(a.referenceRpp);
            r.seed = 1000;
            CpuSampleRanges cpu(scene, accel, r);
            adaptive::PixelAccumulation acc(a.size, a.size, {0, a.size});
            cpu.add(std::vector<std::uint32_t>(pixels, a.referenceRpp), acc);
            const adaptive::ImageErrorEstimate e = adaptive::estimateImageError(acc);
            ref.mse = e.rmse * e.rmse;
            ref.meanLuminance = e.meanLuminance;
            ref.standardError = adaptive::standardErrors(acc, adaptive::smoothedSampleVariance(acc, a.mapRadius));
            for (std::size_t p = 0; p < pixels; ++p) ref.mean.push_back(glm::dvec3(acc.mean(p)));
        }

        RenderOptions ad = o;
        ad.sampler = SamplerKind::Sobol2;
        ad.samplesPerPixel = static_cast<int>(a.maxRpp);
        adaptive::AdaptiveOptions options;
        options.targetError = a.target;
        options.maxRpp = a.maxRpp;
        options.minRpp = a.minRpp;
        // Timed --repeat times (the same counts and image each time: --target-error alone is
        // deterministic); the median time is kept.
        std::optional<adaptive::AdaptiveResult> timed;
        std::vector<double> adaptiveTimes;
        for (int r = 0; r < a.repeat; ++r) {
            CpuSampleRanges cpu(scene, accel, ad);
            timed = adaptive::renderAdaptive(a.size, a.size, {0, a.size}, options,
                                             [&](const std::vector<std::uint32_t>& next, adaptive::PixelAccumulation& acc) {
                                                 cpu.add(next, acc);
                                             });
            adaptiveTimes.push_back(timed->last.seconds);
        }
        const adaptive::AdaptiveResult& result = *timed;
        const double adaptiveSeconds = median(adaptiveTimes);
        std::vector<glm::dvec3> image;
        for (std::size_t p = 0; p < pixels; ++p) image.push_back(glm::dvec3(result.acc.mean(p)));
        const double trueError = std::sqrt(trueMse(ref, image)) / ref.meanLuminance;
        const std::vector<glm::vec3> se =
            adaptive::standardErrors(result.acc, adaptive::smoothedSampleVariance(result.acc, a.mapRadius));
        double seSquares = 0.0;
        for (const glm::vec3& s : se) seSquares += glm::dot(glm::dvec3(s), glm::dvec3(s));
        const double seRms = std::sqrt(seSquares / (3.0 * pixels));
        double zSquares = 0.0;
        std::size_t zCount = 0;
        for (std::size_t p = 0; p < pixels; ++p)
            for (int c = 0; c < 3; ++c) {
                if (!(se[p][c] >= 0.25 * seRms) || seRms <= 0.0) continue;
                const double z = (image[p][c] - ref.mean[p][c]) /
                                 std::sqrt(double(se[p][c]) * se[p][c] + double(ref.standardError[p][c]) * ref.standardError[p][c]);
                zSquares += z * z;
                ++zCount;
            }
        const double zStd = zCount > 0 ? std::sqrt(zSquares / zCount) : NAN;

        double speedUp[2] = {NAN, NAN};
        int column = 0;
        for (SamplerKind sampler : {SamplerKind::Jittered, SamplerKind::Sobol2}) {
            std::vector<UniformPoint> points;
            for (int rpp = 4; rpp <= (1 << 16); rpp *= 4) {
                RenderOptions u = o;
                u.sampler = sampler;
                u.samplesPerPixel = rpp;
                std::vector<double> times;
                Image uniform;
                for (int r = 0; r < a.repeat; ++r) {
                    RenderStats stats;
                    uniform = renderCpu(scene, accel, u, &stats);
                    times.push_back(stats.seconds);
                }
                std::vector<glm::dvec3> values(uniform.pixels.begin(), uniform.pixels.end());
                points.push_back({median(times), std::sqrt(trueMse(ref, values)) / ref.meanLuminance});
                if (points.size() >= 2 && points.back().error < trueError) break;
            }
            speedUp[column++] = timeFor(points, trueError) / adaptiveSeconds;
        }
        char rpp[32];
        std::snprintf(rpp, sizeof rpp, "%u-%u", result.last.minCount, result.last.maxCount);
        std::printf("%-40s %6d %10s %9.5f %9.5f %6.3f %6.3f %8.3f %8.2f %8.2f %5s\n",
                    std::filesystem::path(path).filename().string().substr(0, 40).c_str(), result.last.number, rpp,
                    result.estimate.relative(), trueError, result.estimate.relative() / trueError, zStd, adaptiveSeconds,
                    speedUp[0], speedUp[1], trueError <= 1.25 * a.target ? "yes" : "NO");
        std::fflush(stdout);
    }
    return 0;
}

}  // namespace vkrt::bench
