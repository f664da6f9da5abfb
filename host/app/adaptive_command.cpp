#include "adaptive_command.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>

#include "cpu_renderer.h"
#include "gpu_renderer.h"
#include "exposure.h"
#include "float_range.h"
#include "interrupt.h"
#include "output_file.h"
#include "render_steps.h"
#include "sample_count_map.h"

namespace vkrt {

namespace {

// The image so far: each pixel's mean over the samples it has.
Image meanImage(const adaptive::PixelAccumulation& acc) {
    Image image(acc.width, acc.height);
    for (std::size_t p = 0; p < acc.pixels(); ++p) image.pixels[p] = acc.mean(p);
    return image;
}

std::string errorText(const adaptive::ImageErrorEstimate& e) {
    char text[64];
    std::snprintf(text, sizeof text, "%.4g", e.relative());
    return text;
}

// The rounds on one device: the GPU when `gpu` and `gpuData` are given (with `kernel`: --gpu-kernel),
// else the CPU reference from `accel`. Both commands (a render, watch mode) run them through here.
struct DeviceRounds {
    adaptive::AdaptiveResult result;
    std::string device;                 // for the summary: the device, and on the GPU the kernel
    std::uint64_t nonFiniteSamples = 0;
    bool onGpu = false;
};

DeviceRounds runRounds(GpuRenderer* gpu, const GpuSceneData* gpuData, const Scene& scene, const SceneAccel* accel,
                       const RenderOptions& options, const adaptive::AdaptiveOptions& adaptiveOptions,
                       const adaptive::RoundDone& onRound, GpuKernel kernel) {
    DeviceRounds out;
    out.onGpu = gpu && gpuData;
    std::optional<CpuSampleRanges> cpu;
    if (!out.onGpu) cpu.emplace(scene, *accel, options);
    GpuRenderStats gpuStats;
    out.result = adaptive::renderAdaptive(
        options.width, options.height, rowsOf(options), adaptiveOptions,
        [&](const std::vector<std::uint32_t>& next, adaptive::PixelAccumulation& acc) {
            if (cpu) return cpu->add(next, acc);
            gpu->addSampleRanges(*gpuData, options, next, acc, &gpuStats, kernel);
            out.nonFiniteSamples += gpuStats.nonFiniteSamples;
        },
        onRound);
    if (cpu) {
        out.nonFiniteSamples = cpu->stats().nonFiniteSamples;
        out.device = "cpu (" + std::to_string(cpu->stats().threads) + " threads)";
    } else {
        out.device = gpu->deviceName() + " [kernel: " + gpuStats.features +
                     (gpuStats.wavefront ? "; wavefront stages" : "; samples/dispatch=" + std::to_string(gpuStats.samplesPerDispatch)) + "]";
    }
    return out;
}

// The rendered rows' pixels (the mean rpp's denominator).
double pixelsOf(const RenderOptions& options) {
    const glm::ivec2 rows = rowsOf(options);
    return static_cast<double>(options.width) * (rows.y - rows.x);
}

}  // namespace

int runAdaptiveRender(CommandLine& cl) {
    const auto start = std::chrono::steady_clock::now();
    checkOutputBeforeRendering(cl.outputPath, cl.scenePath);
    // Each file once: a map written over the image (or the other map) would replace it.
    const auto same = [](const std::string& a, const std::string& b) {
        return std::filesystem::absolute(a).lexically_normal() == std::filesystem::absolute(b).lexically_normal();
    };
    for (const std::string& map : {cl.errorMapPath, cl.sampleMapPath}) {
        if (map.empty()) continue;
        checkOutputBeforeRendering(map, cl.scenePath);
        if (same(map, cl.outputPath))
            throw std::invalid_argument(map + ": is also the image (-o); give the map another name");
    }
    if (!cl.errorMapPath.empty() && same(cl.errorMapPath, cl.sampleMapPath))
        throw std::invalid_argument(cl.errorMapPath + ": given as both --error-map and --sample-map; give each its own name");
    checkImageFitsInMemory(cl.render.width, cl.render.height);
    const Scene scene = loadWithWarnings(cl);
    // The device as for a uniform render (render_steps.h openGpu): --device auto takes the CPU
    // reference where Vulkan runs on the CPU.
    std::unique_ptr<GpuRenderer> gpu = openGpu(cl);
    std::optional<GpuSceneData> gpuData;
    std::optional<SceneAccel> accel;
    if (gpu) {
        const ExitAtOnceOnInterrupt scope;
        gpuData.emplace(GpuRenderer::prepare(scene));
    }
    const double pixels = pixelsOf(cl.render);
    const adaptive::RoundDone onRound = [&](const adaptive::AdaptiveRound& r, const adaptive::PixelAccumulation& acc) {
        if (cl.render.checkpoints >= 1) {
            Image soFar = meanImage(acc);
            clampOverflowedPixels(soFar);
            writeImage(withExposure(std::move(soFar), cl.exposure), cl.outputPath);
        }
        if (cl.render.quiet) return;
        char target[48] = "";
        if (cl.adaptive.targetError) std::snprintf(target, sizeof target, " (target %g)", *cl.adaptive.targetError);
        std::fprintf(stderr, "round %d: estimated error %s%s, %u-%u rpp (mean %.1f), %.3fs%s%s\n", r.number,
                     errorText(r.estimate).c_str(), target, r.minCount, r.maxCount, r.samples / pixels, r.seconds,
                     cl.render.checkpoints >= 1 ? " -> " : "", cl.render.checkpoints >= 1 ? cl.outputPath.c_str() : "");
    };
    const auto onCpu = [&] {
        {
            const ExitAtOnceOnInterrupt scope;  // the tree of a large mesh takes seconds
            accel.emplace(prepareCpuScene(scene));
        }
        return runRounds(nullptr, nullptr, scene, &*accel, cl.render, cl.adaptive, onRound, GpuKernel::Auto);
    };
    const DeviceRounds rounds = [&] {
        if (!gpu) return onCpu();
        try {
            return runRounds(gpu.get(), &*gpuData, scene, nullptr, cl.render, cl.adaptive, onRound, gpuSettingsOf(cl).kernel);
        } catch (const GpuKernelError& e) {
            // The kernel refused this scene (lavapipe's loop limiter): under --device auto the CPU
            // reference computes the same image from the start.
            if (cl.device != DeviceChoice::Auto) throw;  // app.cpp names the scene file
            noteCpuFallback(scene.path, e);
            return onCpu();
        }
    }();
    const adaptive::AdaptiveResult& result = rounds.result;

    Image image = meanImage(result.acc);
    const std::size_t overflowed = clampOverflowedPixels(image);
    writeImage(withExposure(std::move(image), cl.exposure), cl.outputPath);
    if (!cl.errorMapPath.empty()) {
        Image errors(cl.render.width, cl.render.height);
        errors.pixels = adaptive::errorMap(result.acc);
        writeImage(errors, cl.errorMapPath);
    }
    if (!cl.sampleMapPath.empty()) {
        if (lowerExtension(cl.sampleMapPath) == ".exr") {
            Image counts(cl.render.width, cl.render.height);
            for (std::size_t p = 0; p < counts.pixels.size(); ++p) counts.pixels[p] = glm::vec3(static_cast<float>(result.acc.count[p]));
            writeImage(counts, cl.sampleMapPath);
        } else {
            writeImage(sampleCountHeatMap(result.acc.count, cl.render.width, cl.render.height), cl.sampleMapPath);
        }
    }
    if (!cl.render.quiet) {
        if (rounds.nonFiniteSamples > 0)
            std::cerr << "warning: " << rounds.nonFiniteSamples << " samples were NaN/Inf and were replaced by black\n";
        if (rounds.onGpu)
            if (auto log = gpu->validationLog(); log && log->count() > 0)
                std::cerr << "warning: " << log->count() << " Vulkan validation message(s):\n" << log->joined();
        if (overflowed > 0)
            std::cerr << "warning: " << overflowed << " pixel(s) summed their samples past float's range: clamped to 3.4e38\n";
        const adaptive::AdaptiveRound& r = result.last;
        std::fprintf(stderr,
                     "%s: %dx%d, adaptive %s on %s: estimated error %s (%s) after %d rounds, %u-%u rpp "
                     "(mean %.1f): render %.3fs, total %.3fs -> %s\n",
                     cl.scenePath.c_str(), cl.render.width, cl.render.height, samplerName(cl.render.sampler).c_str(), rounds.device.c_str(),
                     errorText(r.estimate).c_str(), adaptive::stopReasonText(result.stop).c_str(), r.number, r.minCount, r.maxCount,
                     r.samples / pixels, r.seconds, secondsSince(start), cl.outputPath.c_str());
    }
    return 0;
}

DeviceRender renderAdaptivePrepared(GpuRenderer* gpu, const GpuSceneData* gpuData, const Scene& scene, const SceneAccel* accel,
                                    const RenderOptions& options, const adaptive::AdaptiveOptions& adaptiveOptions, GpuKernel kernel) {
    const double pixels = pixelsOf(options);
    const DeviceRounds rounds =
        runRounds(gpu, gpuData, scene, accel, options, adaptiveOptions,
                  [&](const adaptive::AdaptiveRound& r, const adaptive::PixelAccumulation& acc) {
                      if (!options.onCheckpoint) return;
                      Image soFar = meanImage(acc);
                      clampOverflowedPixels(soFar);
                      options.onCheckpoint->checkpoint(soFar, static_cast<int>(std::lround(r.samples / pixels)));
                  },
                  kernel);
    DeviceRender out;
    out.image = meanImage(rounds.result.acc);
    clampOverflowedPixels(out.image);
    const adaptive::AdaptiveRound& r = rounds.result.last;
    char text[200];
    std::snprintf(text, sizeof text, "; adaptive: estimated error %s (%s) after %d rounds, %u-%u rpp (mean %.1f)",
                  errorText(r.estimate).c_str(), adaptive::stopReasonText(rounds.result.stop).c_str(), r.number, r.minCount,
                  r.maxCount, r.samples / pixels);
    out.device = rounds.device + text;
    out.seconds = r.seconds;
    out.onGpu = rounds.onGpu;
    return out;
}

}  // namespace vkrt
