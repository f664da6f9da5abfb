#include "adaptive_command.h"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <stdexcept>

#include "cpu_renderer.h"
#include "device_choice.h"
#include "device_list.h"
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

// The GPU renderer has no per-pixel sample ranges yet: adaptive sampling runs on the CPU
// reference; asking for Vulkan is an error, and auto on a machine with a GPU says so.
void checkDevice(const CommandLine& cl) {
    const char* flag = cl.adaptive.targetError ? "--target-error" : "--time";
    if (cl.device == DeviceChoice::Gpu || asksForVulkan(cl))
        throw std::invalid_argument(std::string(flag) + " runs on the CPU reference only (the GPU renderer does not yet give "
                                    "pixels their own sample counts): use --device cpu or auto");
    if (cl.device == DeviceChoice::Auto && !cl.render.quiet) {
        try {
            if (!chooseAutoDevice(listDevices()).cpuReference)
                std::cerr << "note: " << flag << " renders on the CPU reference (the GPU renderer does not yet give pixels "
                          << "their own sample counts)\n";
        } catch (const VulkanUnavailable&) {
        }
    }
}

std::string errorText(const adaptive::ImageErrorEstimate& e) {
    char text[64];
    std::snprintf(text, sizeof text, "%.4g", e.relative());
    return text;
}

}  // namespace

int runAdaptiveRender(CommandLine& cl) {
    const auto start = std::chrono::steady_clock::now();
    checkDevice(cl);
    checkOutputBeforeRendering(cl.outputPath, cl.scenePath);
    for (const std::string& map : {cl.errorMapPath, cl.sampleMapPath})
        if (!map.empty()) checkOutputBeforeRendering(map, cl.scenePath);
    checkImageFitsInMemory(cl.render.width, cl.render.height);
    const Scene scene = loadWithWarnings(cl);
    const SceneAccel accel = [&] {
        const ExitAtOnceOnInterrupt scope;
        return prepareCpuScene(scene);
    }();
    CpuSampleRanges cpu(scene, accel, cl.render);
    const bool quiet = cl.render.quiet;
    const adaptive::AdaptiveResult result = adaptive::renderAdaptive(
        cl.render.width, cl.render.height, rowsOf(cl.render), cl.adaptive,
        [&](const std::vector<std::uint32_t>& next, adaptive::PixelAccumulation& acc) { cpu.add(next, acc); },
        [&](const adaptive::AdaptiveRound& r, const adaptive::PixelAccumulation& acc) {
            if (cl.render.checkpoints > 1) {
                Image soFar = meanImage(acc);
                clampOverflowedPixels(soFar);
                writeImage(withExposure(std::move(soFar), cl.exposure), cl.outputPath);
            }
            if (quiet) return;
            const double pixels = static_cast<double>(cl.render.width) * (rowsOf(cl.render).y - rowsOf(cl.render).x);
            char target[48] = "";
            if (cl.adaptive.targetError) std::snprintf(target, sizeof target, " (target %g)", *cl.adaptive.targetError);
            std::fprintf(stderr, "round %d: estimated error %s%s, %u-%u rpp (mean %.1f), %.3fs%s%s\n", r.number,
                         errorText(r.estimate).c_str(), target,
                         r.minCount, r.maxCount, r.samples / pixels, r.seconds, cl.render.checkpoints > 1 ? " -> " : "",
                         cl.render.checkpoints > 1 ? cl.outputPath.c_str() : "");
        });

    Image image = meanImage(result.acc);
    const std::size_t overflowed = clampOverflowedPixels(image);
    writeImage(withExposure(std::move(image), cl.exposure), cl.outputPath);
    if (!cl.errorMapPath.empty()) {
        Image errors(cl.render.width, cl.render.height);
        errors.pixels = adaptive::standardErrors(result.acc, result.variance);
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
    if (!quiet) {
        const RenderStats& stats = cpu.stats();
        if (stats.nonFiniteSamples > 0)
            std::cerr << "warning: " << stats.nonFiniteSamples << " samples were NaN/Inf and were replaced by black\n";
        if (overflowed > 0)
            std::cerr << "warning: " << overflowed << " pixel(s) summed their samples past float's range: clamped to 3.4e38\n";
        const adaptive::AdaptiveRound& r = result.last;
        const double pixels = static_cast<double>(cl.render.width) * (rowsOf(cl.render).y - rowsOf(cl.render).x);
        std::fprintf(stderr,
                     "%s: %dx%d, adaptive %s on cpu (%d threads): estimated error %s (%s) after %d rounds, %u-%u rpp "
                     "(mean %.1f): render %.3fs, total %.3fs -> %s\n",
                     cl.scenePath.c_str(), cl.render.width, cl.render.height, samplerName(cl.render.sampler).c_str(), stats.threads,
                     errorText(r.estimate).c_str(), adaptive::stopReasonText(result.stop).c_str(), r.number, r.minCount, r.maxCount,
                     r.samples / pixels, r.seconds, secondsSince(start), cl.outputPath.c_str());
    }
    return 0;
}

}  // namespace vkrt
