#include "app.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <new>
#include <string>

#include <sys/resource.h>
#include <unistd.h>

#include "adaptive_command.h"
#include "check_command.h"
#include "command_line.h"
#include "image_parts.h"
#include "cpu_renderer.h"
#include "device_choice.h"
#include "device_list.h"
#include "exposure.h"
#include "gpu_renderer.h"
#include "heat_map.h"
#include "image_compare.h"
#include "interrupt.h"
#include "mpi_ranks.h"
#include "mpi_work_sharing.h"
#include "output_file.h"
#include "progressive_output.h"
#include "render_steps.h"
#include "scene_convert.h"
#include "scene_loader.h"
#include "statistical_compare.h"
#include "sweep.h"
#include "vulkan_errors.h"
#include "watch_mode.h"

namespace vkrt {

namespace {

constexpr int kExitFailure = 1;
constexpr int kExitDifferent = 3;  // compare: the agreement rule or (--stat) the z-test failed
constexpr int kExitInterrupted = 130;

// compare writes its heat map only where -o asks, so that it never litters the working folder.
void writeHeatMap(const Image& map, const std::string& path) {
    if (!path.empty()) writeImage(withDifferenceLegend(map), path);
}

// compare --keep: where the two renders go, beside the heat map (or in the working folder).
std::string keptRenderPath(const CommandLine& cl, const char* device) {
    const std::filesystem::path folder = std::filesystem::path(cl.heatMapPath).parent_path();
    return (folder / (std::filesystem::path(cl.scenePath).stem().string() + "_" + device + ".png")).string();
}
// The summary line's "compile 1.234s, " on the GPU: the kernel variant's pipeline creation and
// first dispatch (the driver's compile, lavapipe's LLVM JIT), which "render" leaves out and "total"
// includes. Nothing on the CPU reference, which compiles nothing at run time.
std::string compileText(const DeviceRender& result) {
    if (!result.onGpu) return "";
    char text[48];
    std::snprintf(text, sizeof text, "compile %.3fs, ", result.pipelineSeconds);
    return text;
}

std::string heatMapLine(const std::string& path) { return path.empty() ? "not written (-o FILE.png writes it)" : path; }

// One rank of `mpirun -np N vkrt ...`: `body` runs with the job's rank, size and local rank. An
// error on any rank is printed with the rank and ends every rank (MPI_Abort), so the job never hangs.
template <class Body>
int asMpiRank(Body body) {
    const mpi::Api& api = mpiApi();
    int rank = 0, size = 1, localRank = 0;
    std::string error;
    if (!api.init(&rank, &size, &localRank, error)) throw std::runtime_error(error);
    try {
        body(api, rank, size, localRank);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "vkrt: error (MPI rank %d of %d): %s\n", rank, size, e.what());
        std::fflush(stderr);
        api.abortAll(1);
    }
    api.finalize();
    return 0;
}

// Each rank on a device of the best type present, by local rank, unless --gpu is given
// (deviceForLocalRank). Without a usable device the rank renders as --device says; a render under
// --device auto where every device runs on the CPU stays on the CPU reference (device_choice.h),
// unless an option asks for Vulkan.
void pickGpuByLocalRank(CommandLine& cl, int localRank) {
    if (cl.gpuIndex >= 0 || cl.device == DeviceChoice::Cpu) return;
    try {
        const std::vector<DeviceInfo> devices = listDevices();
        if (cl.command == Command::Render && cl.device == DeviceChoice::Auto && !asksForVulkan(cl) &&
            chooseAutoDevice(devices).cpuReference)
            return;
        cl.gpuIndex = deviceForLocalRank(devices, localRank);
    } catch (const VulkanUnavailable&) {
        // no loader: openGpu says so, or falls back to the CPU
    }
}

// Rank r renders part r + 1 of N; rank 0 gathers the rows in rank order, which is the image's row
// order, and writes the image a single process would have written.
int runRenderAsMpiRank(CommandLine& cl) {
    const auto start = std::chrono::steady_clock::now();
    return asMpiRank([&](const mpi::Api& api, int rank, int size, int localRank) {
        std::string error;
        if (cl.parts > 0) throw std::runtime_error("--part and mpirun both split the image: use one of them");
        cl.part = rank + 1;
        cl.parts = size;
        if (size > cl.render.height)
            throw std::runtime_error(std::to_string(size) + " ranks for a " + std::to_string(cl.render.height) +
                                     "-row image would leave some ranks without a row");
        cl.render.rows = partRows(cl.render.height, cl.part, cl.parts);
        if (rank != 0) cl.render.quiet = true;
        pickGpuByLocalRank(cl, localRank);
        checkOutputBeforeRendering(cl.outputPath, cl.scenePath);
        checkImageFitsInMemory(cl.render.width, cl.render.height);
        DeviceRender result = renderScene(cl);
        const glm::ivec2 rows = rowsOf(cl.render);
        const long long mine = static_cast<long long>(rows.y - rows.x) * cl.render.width * 3;
        std::vector<long long> counts(static_cast<std::size_t>(size));
        if (!api.allCounts(mine, counts.data(), error)) throw std::runtime_error(error);
        Image image(cl.render.width, cl.render.height);
        const float* myRows = &result.image.at(0, rows.x).x;
        if (!api.gather(myRows, mine, &image.pixels[0].x, counts.data(), error)) throw std::runtime_error(error);
        if (rank == 0) {
            writeImage(withExposure(std::move(image), cl.exposure), cl.outputPath);
            if (!cl.render.quiet)
                std::fprintf(stderr, "%s: %dx%d, %d rpp over %d MPI ranks (rank 0 on %s): %srender %.3fs, total %.3fs -> %s\n",
                             cl.scenePath.c_str(), cl.render.width, cl.render.height, cl.render.samplesPerPixel, size,
                             result.device.c_str(), compileText(result).c_str(), result.seconds, secondsSince(start),
                             cl.outputPath.c_str());
        }
    });
}

int runRender(CommandLine& cl) {
    if (launchedAsMpiRank()) {
        if (cl.adaptiveSampling)
            throw std::runtime_error("adaptive sampling decides each pixel's samples from the whole image: run it without mpirun");
        if (cl.watch || cl.render.checkpoints > 1)
            throw std::runtime_error(std::string(cl.watch ? "--watch" : "--progressive") +
                                     " writes the image from one process, not from MPI ranks (run it without mpirun)");
        return runRenderAsMpiRank(cl);
    }
    if (cl.watch) return runWatch(cl);
    if (cl.adaptiveSampling) return runAdaptiveRender(cl);
    const auto start = std::chrono::steady_clock::now();
    checkOutputBeforeRendering(cl.outputPath, cl.scenePath);
    checkImageFitsInMemory(cl.render.width, cl.render.height);
    ProgressiveOutput passes(cl.outputPath, cl.render.samplesPerPixel, cl.exposure, cl.render.quiet, "pass: ");
    if (cl.render.checkpoints > 1) cl.render.onCheckpoint = &passes;
    DeviceRender result = renderScene(cl);
    writeImage(withExposure(std::move(result.image), cl.exposure), cl.outputPath,
               cl.parts > 0 ? partAttributes(cl, result.device) : ImageAttributes{});
    if (!cl.render.quiet) {
        const std::string part = cl.parts > 0 ? ", part " + std::to_string(cl.part) + "/" + std::to_string(cl.parts) : "";
        std::fprintf(stderr, "%s: %dx%d%s, %d rpp on %s: %srender %.3fs, total %.3fs -> %s\n", cl.scenePath.c_str(),
                     cl.render.width, cl.render.height, part.c_str(), cl.render.samplesPerPixel, result.device.c_str(),
                     compileText(result).c_str(), result.seconds, secondsSince(start), cl.outputPath.c_str());
    }
    return 0;
}

// vkrt merge: the parts of one render, as one image (image_parts.h). A part's pixels already carry
// its --exposure (and merge has none), so they are copied as they are.
int runMerge(const CommandLine& cl) {
    checkImageOutputPath(cl.outputPath);
    for (const std::string& input : cl.mergeInputs) checkNotTheInput(cl.outputPath, input);
    const Image image = mergeParts(cl.mergeInputs);
    writeImage(image, cl.outputPath);
    if (!cl.render.quiet)
        std::fprintf(stderr, "merge: %zu part(s), %dx%d -> %s\n", cl.mergeInputs.size(), image.width, image.height,
                     cl.outputPath.c_str());
    return 0;
}

// compare --stat: GPU and CPU with different seeds, judged by a z-test (host/study/z_test.h).
int runStatisticalCompare(CommandLine& cl) {
    const Scene scene = loadWithWarnings(cl);
    study::StudyRenderer renderer(gpuOptions(cl));
    RenderOptions options = cl.render;
    options.quiet = true;
    const study::StatisticalComparison c = study::compareDevicesStatistically(renderer, renderer.prepare(scene), options);
    if (auto log = renderer.validationLog(); log && log->count() > 0)
        std::cerr << "warning: " << log->count() << " Vulkan validation message(s):\n" << log->joined();
    // The z map is not a difference in /255 (grey: max |z| / limit, red: a failing value), so it
    // goes without the difference legend.
    if (!cl.heatMapPath.empty()) writeImage(c.test.map, cl.heatMapPath);
    const study::ZTestResult& z = c.test;
    std::printf("scene            %s (%dx%d, %s sampler)\n", cl.scenePath.c_str(), cl.render.width, cl.render.height,
                study::samplerName(cl.render.sampler).c_str());
    std::printf("gpu              %s, seed %u, %d rpp, %.3f s\n", renderer.gpuDeviceName().c_str(), c.gpuSeed, c.gpuRpp,
                c.gpuSeconds);
    std::printf("cpu reference    seed %u, %d rpp with per-pixel sample variance, %.3f s\n", c.cpuSeed, c.cpuRpp,
                c.cpuSeconds);
    std::printf("z-test           |z| limit %.2f (alpha 0.01, Sidak over %zu values), max |z| %.2f\n", z.zLimit, z.values,
                z.maxAbsZ);
    std::printf("values passing   %.3f%% (needs >= 99.75%%)\n", 100.0 * z.passedFraction());
    std::printf("z map            %s\n", heatMapLine(cl.heatMapPath).c_str());
    std::printf("result           %s\n", z.pass ? "PASS: the images agree up to their noise" : "FAIL: the images differ");
    return z.pass ? 0 : kExitDifferent;
}

int runSweep(CommandLine& cl, study::WorkSharing* sharing = nullptr) {
    const Scene scene = loadWithWarnings(cl);
    study::SweepOptions options = cl.sweep;
    options.render = cl.render;
    options.gpu = gpuOptions(cl);
    const study::SweepResult result = study::runSweep(options, scene, std::cerr, sharing);
    if (!result.leader) return 0;
    if (!result.validationMessages.empty()) std::cerr << "warning: Vulkan validation messages:\n" << result.validationMessages;
    if (!cl.render.quiet)
        std::fprintf(stderr, "sweep: %zu renders -> %s, %s, %s, %s\n", result.rows.size(), result.csv.c_str(),
                     result.plots.errorVsTime.c_str(), result.plots.errorVsRpp.c_str(), result.report.c_str());
    return 0;
}

int runCompare(CommandLine& cl) {
    if (!cl.heatMapPath.empty()) checkOutputBeforeRendering(cl.heatMapPath, cl.scenePath);
    if (cl.statistical) return runStatisticalCompare(cl);
    const Scene scene = loadWithWarnings(cl);
    // Each device prepares and renders as `vkrt scene.xml` would, from its own tree: the times are
    // the ones a user gets, and the images must agree although the trees differ.
    GpuRenderer gpu(gpuOptions(cl));
    const DeviceRender onGpu = renderOnGpu(gpu, scene, cl.render, gpuSettingsOf(cl));
    const DeviceRender onCpu = renderOnCpu(scene, cl.render);
    const ImageDifference diff = compareImages(onGpu.image, onCpu.image);
    writeHeatMap(diff.heatMap, cl.heatMapPath);
    const bool agree = meetsAgreementRule(diff);
    if (cl.keepRenders) {
        writeImage(onGpu.image, keptRenderPath(cl, "gpu"));
        writeImage(onCpu.image, keptRenderPath(cl, "cpu"));
    }
    std::printf("scene            %s (%dx%d, %d rpp, seed %u)\n", cl.scenePath.c_str(), cl.render.width,
                cl.render.height, cl.render.samplesPerPixel, cl.render.seed);
    std::printf("gpu              %s, prepare %.3f s, render %.3f s\n", onGpu.device.c_str(), onGpu.prepareSeconds,
                onGpu.seconds);
    std::printf("cpu              %s, prepare %.3f s, render %.3f s\n", onCpu.device.c_str(), onCpu.prepareSeconds,
                onCpu.seconds);
    std::printf("max abs diff     %.4f (%d/255)\n", diff.maxAbs, static_cast<int>(diff.maxAbs * 255.0 + 0.5));
    std::printf("mean abs diff    %.6f (%.3f/255)\n", diff.meanAbs, diff.meanAbs * 255.0);
    std::printf("pixels > 1/255   %.3f%%\n", 100.0 * diff.fractionOver1);
    std::printf("pixels > 2/255   %.3f%%\n", 100.0 * diff.fractionOver2);
    std::printf("psnr             %.2f dB\n", diff.psnr);
    std::printf("heat map         %s\n", heatMapLine(cl.heatMapPath).c_str());
    if (cl.keepRenders)
        std::printf("renders          %s, %s\n", keptRenderPath(cl, "gpu").c_str(), keptRenderPath(cl, "cpu").c_str());
    std::printf("result           %s\n", agree ? "PASS: the images meet the agreement rule (<= 0.5% of pixels over 2/255, mean <= 0.5/255)"
                                               : "FAIL: the images differ beyond the agreement rule (<= 0.5% of pixels over 2/255, mean <= 0.5/255)");
    return agree ? 0 : kExitDifferent;
}

int runConvert(const CommandLine& cl) {
    Diagnostics diagnostics(cl.strict);
    const auto start = std::chrono::steady_clock::now();
    // The input's warnings are printed whether the conversion succeeds or not.
    Conversion conversion;
    try {
        conversion = convertScene(cl.scenePath, cl.outputPath, diagnostics, cl.render.cancel);
    } catch (...) {
        printWarnings(diagnostics, cl.render.quiet);
        throw;
    }
    printWarnings(diagnostics, cl.render.quiet);
    if (conversion.renamedShaders > 0)
        std::cerr << "note: " << conversion.renamedShaders
                  << " nameless shader(s) written as 'unnamed shader N' (a shader needs a name to be referred to there)\n";
    if (conversion.escapedNames > 0)
        std::cerr << "note: " << conversion.escapedNames << " name(s) held characters " << conversion.format
                  << " cannot hold (" << (conversion.format == "json" ? "bytes that are not UTF-8" : "control characters")
                  << "); written with \\xNN escapes in their place\n";
    for (const std::string& name : conversion.definedPlaceholders)
        std::cerr << "note: shader '" << name << "' is named but not defined in " << cl.scenePath
                  << "; written as the grey Lambertian placeholder it renders as\n";
    if (!cl.render.quiet)
        std::fprintf(stderr, "%s -> %s (%s): %s; loads back as the same scene, %.3fs\n", cl.scenePath.c_str(),
                     cl.outputPath.c_str(), conversion.format.c_str(), conversion.counts.c_str(), secondsSince(start));
    return 0;
}

int runListDevices() {
    std::cout << formatDeviceList(listDevices()) << std::flush;
    if (!std::cout) throw std::runtime_error("cannot write the device list to standard output");
    return 0;
}

}  // namespace

int runVkrt(int argc, const char* const* argv) {
    ParseResult parsed = parseCommandLine(argc, argv);
    if (!parsed.commandLine) return parsed.exitCode;
    CommandLine cl = *parsed.commandLine;
    for (const std::string& notice : cl.notices) std::cerr << "note: " << notice << "\n";
    if (cl.verbose && cl.command != Command::ListDevices) std::cerr << describeSettings(cl);
    cl.render.cancel = installInterruptHandler();
    try {
        switch (cl.command) {
        case Command::ListDevices: return runListDevices();
        case Command::Compare: return runCompare(cl);
        case Command::Check: return runCheck(cl);
        case Command::Sweep:
            if (!launchedAsMpiRank()) return runSweep(cl);
            // The renders spread over the ranks, rank 0 writing the files (shared_renders.h).
            return asMpiRank([&](const mpi::Api& api, int rank, int size, int localRank) {
                if (rank != 0) cl.render.quiet = true;
                pickGpuByLocalRank(cl, localRank);
                MpiWorkSharing sharing(api, rank, size);
                runSweep(cl, &sharing);
            });
        case Command::Convert: return runConvert(cl);
        case Command::Merge: return runMerge(cl);
        case Command::Render: return runRender(cl);
        }
    } catch (const RenderCancelled&) {
        std::cerr << "vkrt: interrupted\n";
        return kExitInterrupted;
    } catch (const std::bad_alloc&) {
        // Most often the image (or its device buffers) does not fit: say how big it was.
        std::cerr << "vkrt: error: out of memory (the " << cl.render.width << "x" << cl.render.height
                  << " image's float pixels alone take " << imageMiB(cl.render.width, cl.render.height)
                  << " MiB; a smaller -w/-h needs less)\n";
        return kExitFailure;
    } catch (const GpuKernelError& e) {
        // The kernel names the pixel and sample; every command that renders (render, compare,
        // sweep, adaptive) renders one scene file, named here (watch mode names it in its own log).
        std::cerr << "vkrt: error: " << kernelErrorIn(cl.scenePath, e).what() << "\n";
        return kExitFailure;
    } catch (const std::exception& e) {
        std::cerr << "vkrt: error: " << e.what() << "\n";
        return kExitFailure;
    }
    return kExitFailure;
}

}  // namespace vkrt
