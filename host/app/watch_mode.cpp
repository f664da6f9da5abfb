#include "watch_mode.h"

#include "scene_inputs.h"

#include <atomic>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <exception>
#include <filesystem>
#include <iostream>
#include <optional>
#include <set>
#include <thread>
#include <string>
#include <vector>

#include "cpu_renderer.h"
#include "exposure.h"
#include "file_watcher.h"
#include "gpu_renderer.h"
#include "interrupt.h"
#include "progressive_output.h"
#include "adaptive_command.h"
#include "render_steps.h"
#include "watch_preview.h"

namespace vkrt {

namespace {

using Clock = std::chrono::steady_clock;

// A save is a burst of events (write, rename, attributes) within a few milliseconds; 50 ms of quiet
// ends it without a delay anyone notices.
constexpr std::chrono::milliseconds kQuiet{50};

// The GLSL a --shader-dir kernel is compiled from: render.comp and what it includes.
const std::set<std::string> kShaderExtensions{".comp", ".glsl", ".h"};

// Every file the scene was read from (scene_inputs.h).
std::vector<std::filesystem::path> inputFiles(const Scene& scene) {
    std::vector<std::filesystem::path> files;
    for (const SceneInput& input : sceneInputs(scene)) files.push_back(input.path);
    return files;
}

std::string clockTime() {
    const std::time_t now = std::time(nullptr);
    char text[16];
    std::strftime(text, sizeof text, "%H:%M:%S", std::localtime(&now));
    return text;
}

// What changed, for the log line: the first file's name and how many more.
std::string describe(const std::set<std::filesystem::path>& files) {
    if (files.empty()) return "";
    std::string text = files.begin()->filename().string();
    if (files.size() > 1) text += " and " + std::to_string(files.size() - 1) + " more";
    return text;
}

// The scene as loaded and prepared for the device that renders it; what a shader edit keeps.
struct LoadedScene {
    Scene scene;
    std::optional<GpuSceneData> gpu;  // refers to `scene`: destroyed first
    std::optional<SceneAccel> cpu;
};

// A progressive pass: written to the output (ProgressiveOutput) and shown on the preview page, both
// with --exposure applied.
class WatchedPasses : public CheckpointSink {
public:
    WatchedPasses(ProgressiveOutput& file, WatchPreview& preview, int round, int rpp, float exposure)
        : file_(file), preview_(preview), round_(round), rpp_(rpp), exposure_(exposure) {}
    void checkpoint(const Image& soFar, int samplesDone) override {
        file_.checkpoint(soFar, samplesDone);
        preview_.image(withExposure(soFar, exposure_), "render " + std::to_string(round_) + ": " + std::to_string(samplesDone) + "/" +
                                  std::to_string(rpp_) + " rpp so far (" + clockTime() + ")");
    }

private:
    ProgressiveOutput& file_;
    WatchPreview& preview_;
    int round_, rpp_;
    float exposure_;
};

class Watcher {
public:
    explicit Watcher(CommandLine& cl) : cl_(cl), preview_(cl.previewPort, cl.scenePath) {
        if (preview_.enabled()) std::fprintf(stderr, "vkrt: preview on http://127.0.0.1:%d/\n", preview_.port());
        watcher_.ignore(cl.outputPath);
        watcher_.watch({cl.scenePath});
        gpu_ = openGpu(cl);
        if (!cl.shaderDir.empty()) {
            if (gpu_)
                watcher_.watch({}, {cl.shaderDir}, kShaderExtensions);
            else
                std::cerr << "note: --shader-dir: the CPU reference runs no GLSL; its files are not watched\n";
        }
    }

    int run() {
        bool reloadScene = true, reloadKernel = false;
        const auto interrupted = [this] { return cl_.render.cancel && cl_.render.cancel->load(); };
        for (int round = 1;; ++round) {
            // Changes seen while rendering (which stopped the render) start the next round at once.
            std::optional<FileChanges> changes = renderOnce(round, reloadScene, reloadKernel);
            if (round == 1 && !cl_.render.quiet)
                std::fprintf(stderr, "vkrt: watching %zu folder(s) for changes (Ctrl-C stops)\n", watcher_.folderCount());
            // After a scene that did not load, a file appearing beside it may be what it was
            // missing (a mesh not yet copied): any change in the watched folders renders again.
            if (!changes) changes = watcher_.wait(interrupted, kQuiet, !loaded_);
            if (!changes) {
                std::cerr << "vkrt: watch stopped\n";
                return 0;
            }
            reloadScene = reloadScene || !changes->files.empty() || !loaded_;
            reloadKernel = reloadKernel || !changes->trees.empty();
            if (!cl_.render.quiet)
                std::fprintf(stderr, "[%s] changed: %s\n", clockTime().c_str(),
                             describe(changes->files.empty() ? (changes->trees.empty() ? changes->others : changes->trees)
                                                             : changes->files)
                                 .c_str());
        }
    }

private:
    // One render: reload what changed, render, write. Prints the times, or the error. The flags are
    // cleared when their work succeeded. A change while it renders stops the render (its image would
    // be stale) and is returned; Ctrl-C throws RenderCancelled.
    std::optional<FileChanges> renderOnce(int round, bool& reloadScene, bool& reloadKernel) {
        const auto start = Clock::now();
        std::string steps;
        char text[64];
        try {
            if (reloadKernel && gpu_) {
                std::snprintf(text, sizeof text, "kernel %.3fs, ", gpu_->reloadKernel());
                steps += text;
            }
            reloadKernel = false;
            if (reloadScene) {
                loaded_.reset();
                const auto loadStart = Clock::now();
                auto loaded = std::make_unique<LoadedScene>(LoadedScene{loadWithWarnings(cl_), {}, {}});
                watcher_.watch(inputFiles(loaded->scene));  // also the files of a scene that fails later
                {
                    const ExitAtOnceOnInterrupt scope;  // the trees of a large mesh take seconds
                    if (gpu_)
                        loaded->gpu.emplace(GpuRenderer::prepare(loaded->scene));
                    else
                        loaded->cpu.emplace(prepareCpuScene(loaded->scene));
                }
                std::snprintf(text, sizeof text, "load %.3fs, ", secondsSince(loadStart));
                steps += text;
                loaded_ = std::move(loaded);
                reloadScene = false;
            }
            ProgressiveOutput file(cl_.outputPath, cl_.render.samplesPerPixel, cl_.exposure, cl_.render.quiet, "  ");
            WatchedPasses passes(file, preview_, round, cl_.render.samplesPerPixel, cl_.exposure);
            RenderOptions options = cl_.render;
            // Adaptive sampling writes each round under any --progressive N (its N is not used).
            if (options.checkpoints > (cl_.adaptiveSampling ? 0 : 1)) options.onCheckpoint = &passes;
            preview_.rendering("render " + std::to_string(round) + ": rendering (" + clockTime() + ")");
            std::optional<FileChanges> during;
            std::optional<DeviceRender> result = renderUnlessChanged(options, during);
            if (!result) {
                std::fprintf(stderr, "[%s] render %d: stopped after %.3fs: an input changed\n", clockTime().c_str(), round,
                             secondsSince(start));
                return during;
            }
            const Image written = withExposure(std::move(result->image), cl_.exposure);
            writeImage(written, cl_.outputPath);
            char line[512];
            const std::string rpp = cl_.adaptiveSampling ? std::string("adaptive") : std::to_string(cl_.render.samplesPerPixel) + " rpp";
            std::snprintf(line, sizeof line, "render %d: %dx%d, %s on %s: %spipeline %.3fs, render %.3fs, total %.3fs -> %s", round,
                          cl_.render.width, cl_.render.height, rpp.c_str(), result->device.c_str(), steps.c_str(),
                          result->pipelineSeconds, result->seconds, secondsSince(start), cl_.outputPath.c_str());
            if (!cl_.render.quiet) std::fprintf(stderr, "[%s] %s\n", clockTime().c_str(), line);
            preview_.image(written, std::string(line) + " (" + clockTime() + ")");
            return during;
        } catch (const RenderCancelled&) {
            throw;
        } catch (const std::exception& e) {
            std::fprintf(stderr, "[%s] render %d: error: %s\n", clockTime().c_str(), round, e.what());
            preview_.error("render " + std::to_string(round) + " (" + clockTime() + "): " + e.what());
            return std::nullopt;
        }
    }

    // Renders while a second thread waits for changes: one stops the render (nullopt, the changes
    // in `during`). Ctrl-C stops it too and throws RenderCancelled. A change that comes as the
    // render ends is returned in `during` with the image.
    std::optional<DeviceRender> renderUnlessChanged(RenderOptions options, std::optional<FileChanges>& during) {
        std::atomic<bool> stopRender{false}, rendered{false};
        const std::atomic<bool>* interrupt = cl_.render.cancel;
        options.cancel = &stopRender;
        std::thread sentinel([&] {
            try {
                during = watcher_.wait([&] { return rendered.load() || (interrupt && interrupt->load()); }, kQuiet, false);
            } catch (...) {  // the watcher failed: the render goes on, and the next wait() reports it
            }
            stopRender = true;
        });
        const auto finish = [&] {
            rendered = true;
            watcher_.wake();
            sentinel.join();
        };
        try {
            DeviceRender result = render(options);
            finish();
            return result;
        } catch (const RenderCancelled&) {
            finish();
            if (interrupt && interrupt->load()) throw;
            return std::nullopt;
        } catch (...) {
            finish();
            throw;
        }
    }

    DeviceRender render(const RenderOptions& options) {
        if (cl_.adaptiveSampling) {
            // Adaptive sampling's rounds, shown as --progressive's passes are (adaptive_command.h).
            if (loaded_->gpu) {
                try {
                    return renderAdaptivePrepared(gpu_.get(), &*loaded_->gpu, loaded_->scene, nullptr, options, cl_.adaptive,
                                                  gpuSettingsOf(cl_).kernel);
                } catch (const GpuKernelError& e) {
                    if (cl_.device != DeviceChoice::Auto) throw kernelErrorIn(loaded_->scene.path, e);
                    noteCpuFallback(loaded_->scene.path, e);
                }
            }
            if (!loaded_->cpu) loaded_->cpu.emplace(prepareCpuScene(loaded_->scene));
            return renderAdaptivePrepared(nullptr, nullptr, loaded_->scene, &*loaded_->cpu, options, cl_.adaptive);
        }
        if (loaded_->gpu) {
            try {
                return renderPreparedOnGpu(*gpu_, *loaded_->gpu, options, gpuSettingsOf(cl_));
            } catch (const GpuKernelError& e) {
                if (cl_.device != DeviceChoice::Auto) throw kernelErrorIn(loaded_->scene.path, e);
                noteCpuFallback(loaded_->scene.path, e);
                if (!loaded_->cpu) loaded_->cpu.emplace(prepareCpuScene(loaded_->scene));
            }
        }
        return renderPreparedOnCpu(loaded_->scene, *loaded_->cpu, options);
    }

    CommandLine& cl_;
    WatchPreview preview_;
    FileWatcher watcher_;
    std::unique_ptr<GpuRenderer> gpu_;
    std::unique_ptr<LoadedScene> loaded_;
};

}  // namespace

int runWatch(CommandLine& cl) {
    checkOutputBeforeRendering(cl.outputPath, cl.scenePath);
    checkImageFitsInMemory(cl.render.width, cl.render.height);
    Watcher watcher(cl);
    return watcher.run();
}

}  // namespace vkrt
