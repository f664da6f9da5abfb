#include "gpu_renderer.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <optional>

#include "buffer.h"
#include "commands.h"
#include "compute_pipeline.h"
#include "float_range.h"
#include "context.h"
#include "kernel_cache.h"
#include "kernel_layouts.h"
#include "kernel_source.h"
#include "progress.h"
#include "render_cancel.h"
#include "render_status.h"
#include "scene_upload.h"
#include "pixel_sums.h"
#include "submission_recorder.h"
#include "wavefront_renderer.h"

namespace vkrt {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

struct GpuRenderer::Impl {
    Impl(const GpuRendererOptions& options, const GpuTestHooks& hooks)
        : source(kernelSource("render", options, hooks)), context(contextOptions(options, hooks)), runner(context),
          transfers(context, runner), layout(renderLayout(context)) {
        kernels.emplace(context, layout, source, loadKernel(source));
    }

    KernelSource source;
    Context context;
    CommandRunner runner;
    Transfers transfers;
    KernelLayout layout;
    std::optional<KernelCache> kernels;  // replaced by reloadKernel()
    std::optional<SceneUpload> upload;   // the last prepared scene rendered (GpuSceneData::uploadKey)
    std::uint64_t uploadKey = 0;

    // The scene's buffers: kept from the last render when it was the same prepared scene.
    SceneUpload& uploadScene(const GpuSceneData& data, const gpu::FrameParams& frame, GpuRenderStats& stats) {
        if (!upload || uploadKey != data.uploadKey) {
            upload.reset();  // the last scene's buffers go before the next one's are made
            upload.emplace(context, transfers, layout, data, frame);
            uploadKey = data.uploadKey;
            stats.sceneUploaded = true;
        }
        return *upload;
    }
};

void countSubmission(GpuRenderStats& stats, double wallSeconds, double deviceSeconds) {
    if (deviceSeconds >= 0.0) stats.kernelSeconds = std::max(stats.kernelSeconds, 0.0) + deviceSeconds;
    stats.maxSubmissionSeconds = std::max(stats.maxSubmissionSeconds, wallSeconds);
    ++stats.submissions;
}

GpuKernel chooseGpuKernel(const DeviceInfo& device) { return device.lavapipe ? GpuKernel::Megakernel : GpuKernel::Wavefront; }

namespace {

// Auto's kernel: VKRT_GPU_KERNEL=megakernel or wavefront overrides the device's choice, so that
// whole test suites run on the other kernel (tests/CMakeLists.txt) without a flag in every call.
GpuKernel autoKernel(const DeviceInfo& device) {
    const char* forced = std::getenv("VKRT_GPU_KERNEL");
    if (forced && std::string(forced) == "wavefront") return GpuKernel::Wavefront;
    if (forced && std::string(forced) == "megakernel") return GpuKernel::Megakernel;
    return chooseGpuKernel(device);
}

}  // namespace

GpuRenderer::GpuRenderer(const GpuRendererOptions& options, const GpuTestHooks& hooks)
    : impl_(std::make_unique<Impl>(options, hooks)) {}
GpuRenderer::~GpuRenderer() = default;

std::string GpuRenderer::deviceName() const { return impl_->context.info().name; }
const DeviceInfo& GpuRenderer::deviceInfo() const { return impl_->context.info(); }
std::shared_ptr<const ValidationLog> GpuRenderer::validationLog() const { return impl_->context.validationLog(); }
std::size_t GpuRenderer::pipelineCount() const { return impl_->kernels->size(); }

double GpuRenderer::reloadKernel() {
    const auto start = Clock::now();
    std::vector<std::uint32_t> spirv = loadKernel(impl_->source);  // throws before anything is replaced
    impl_->context.device().waitIdle();
    impl_->kernels.reset();  // saves the pipeline cache file; the new cache reads it back
    impl_->kernels.emplace(impl_->context, impl_->layout, impl_->source, spirv);
    return secondsSince(start);
}

Image GpuRenderer::renderWavefront(const GpuSceneData& data, const KernelInputs& in, const RenderOptions& options,
                                   std::uint64_t wavePaths, GpuRenderStats& stats, GpuRenderStats* statsOut) {
    stats.wavefront = true;
    stats.samplesPerDispatch = 1;
    const auto start = Clock::now();
    SceneUpload& gpuScene = impl_->uploadScene(data, in.frame, stats);
    stats.uploadSeconds = secondsSince(start);
    std::vector<glm::vec4> sums;
    const GpuRenderDevice device{impl_->context, impl_->runner, impl_->transfers, impl_->layout, *impl_->kernels};
    vkrt::renderWavefront(device, gpuScene, data, in, options, wavePaths, stats, sums);
    const auto readback = Clock::now();
    Image image = resolve(sums, options.width, options.height, options.samplesPerPixel);
    stats.overflowedPixels = clampOverflowedPixels(image);
    stats.readbackSeconds = secondsSince(readback);
    if (statsOut) *statsOut = stats;
    return image;
}

Image GpuRenderer::render(const GpuSceneData& data, const RenderOptions& options, GpuRenderStats* statsOut,
                          const GpuRenderSettings& settings) {
    GpuRenderStats stats;
    stats.device = impl_->context.info().name;
    // lavapipe's loop limiter counts a group of lanes together (sample_batching.h); other drivers count nothing.
    const std::uint64_t lockstep = impl_->context.info().loopLimiter ? kLockstepFactor : 1;
    const KernelInputs in = makeKernelInputs(data, options, settings.variant, settings.samplesPerDispatch, lockstep);
    const SampleBatching& batching = in.batching;
    stats.features = in.features.describe();
    stats.generalKernel = settings.variant == KernelVariant::General;
    stats.samplesPerDispatch = batching.perDispatch;
    const GpuKernel kernel = settings.kernel == GpuKernel::Auto ? autoKernel(impl_->context.info()) : settings.kernel;
    if (kernel == GpuKernel::Wavefront) return renderWavefront(data, in, options, settings.wavePaths, stats, statsOut);
    const vk::raii::Pipeline& pipeline = impl_->kernels->pipeline(in.features, batching.perDispatch, &stats.pipelineSeconds);

    // The prepared scene's tables go to the device once; later renders of it (a sweep, watch mode's
    // option changes, --stat) upload only their frame and zero the sums.
    auto start = Clock::now();
    const bool kept = impl_->upload && impl_->uploadKey == data.uploadKey;
    SceneUpload& gpuScene = impl_->uploadScene(data, in.frame, stats);
    if (kept) gpuScene.beginRender(impl_->context, impl_->transfers, in.frame);
    stats.uploadSeconds = secondsSince(start);
    stats.sceneBytes = gpuScene.bytes();

    stats.warmUpSeconds = impl_->runner.run([&](const vk::raii::CommandBuffer& commands) {
        recordWarmUp(commands, *pipeline, impl_->layout.pipelineLayout(), gpuScene.descriptorSet());
    });

    TilingPolicy tiling = settings.tiling;
    tiling.maxWorkgroups = std::min(tiling.maxWorkgroups, impl_->context.info().maxWorkGroupCountX);
    const auto width = static_cast<std::uint32_t>(options.width);
    // Only the rows asked for (a --part): tiles are planned over them and moved down to them; the
    // accumulation buffer's other rows stay zero (black).
    const glm::ivec2 rows = rowsOf(options);
    TilePlanner planner(width, static_cast<std::uint32_t>(rows.y - rows.x), batching.passes(), tiling);
    const std::vector<int> checkpoints = checkpointEnds(static_cast<int>(batching.passes()), options.checkpoints);
    if (options.onCheckpoint) planner.stopAtPasses(checkpoints);
    std::vector<glm::vec4> sums(static_cast<std::size_t>(options.width) * options.height);
    Progress progress("GPU render", options.quiet);
    start = Clock::now();
    while (!planner.done()) {
        throwIfCancelled(impl_->context, options);
        Submission submission = planner.next();
        submission.tile.y += static_cast<std::uint32_t>(rows.x);
        const double seconds = impl_->runner.run([&](const vk::raii::CommandBuffer& commands) {
            recordSubmission(commands, *pipeline, impl_->layout.pipelineLayout(), gpuScene.descriptorSet(), submission, batching);
        });
        planner.reportSeconds(seconds);
        countSubmission(stats, seconds, impl_->runner.lastDeviceSeconds());
        stats.dispatches += submission.sampleCount;
        throwIfKernelFailed(gpuScene.status(), width, impl_->context.info().loopLimiter);
        progress.update(planner.fractionDone());
        if (options.onCheckpoint && submission.endsPasses) {
            const auto passesDone = static_cast<int>(submission.firstSample + submission.sampleCount);
            const bool last = planner.done();
            if (!last && std::find(checkpoints.begin(), checkpoints.end(), passesDone) != checkpoints.end()) {
                impl_->transfers.download(gpuScene.accum(), std::as_writable_bytes(std::span(sums)));
                const int samplesDone = static_cast<int>(std::min(batching.samplesPerPixel, batching.first(passesDone)));
                Image soFar = resolveSoFar(sums, options.width, options.height, planner.tiles(), submission.tileIndex, samplesDone,
                                           options.samplesPerPixel, rows.x);
                clampOverflowedPixels(soFar);
                options.onCheckpoint->checkpoint(soFar, samplesDone);
            }
        }
    }
    stats.renderSeconds = secondsSince(start);
    stats.nonFiniteSamples = gpu::statusNonFiniteSamples(gpuScene.status());

    start = Clock::now();
    impl_->transfers.download(gpuScene.accum(), std::as_writable_bytes(std::span(sums)));
    Image image = resolve(sums, options.width, options.height, options.samplesPerPixel);
    stats.overflowedPixels = clampOverflowedPixels(image);
    stats.readbackSeconds = secondsSince(start);
    if (statsOut) *statsOut = stats;
    return image;
}

void GpuRenderer::addSampleRanges(const GpuSceneData& data, const RenderOptions& options, const std::vector<std::uint32_t>& next,
                                  adaptive::PixelAccumulation& acc, GpuRenderStats* statsOut, GpuKernel kernel) {
    GpuRenderStats stats;
    stats.device = impl_->context.info().name;
    const std::uint64_t lockstep = impl_->context.info().loopLimiter ? kLockstepFactor : 1;
    KernelInputs in = makeKernelInputs(data, options, KernelVariant::Specialised, 0, lockstep);
    in.features.adaptive = true;
    const std::uint32_t k = in.batching.perDispatch;
    stats.features = in.features.describe();
    stats.samplesPerDispatch = k;

    // The accumulation buffer of the ADAPTIVE kernel: per pixel its sum and its odd samples' sum
    // (float bits), then the work list: the pixels with samples to add, most samples first (pass
    // j then dispatches a prefix of it), in the image's 8x8 blocks within equal counts so that
    // neighbouring lanes trace neighbouring pixels.
    const std::size_t pixels = acc.pixels();
    std::vector<glm::uvec4> contents(2 * pixels);
    for (std::size_t p = 0; p < pixels; ++p) {
        contents[2 * p] = glm::uvec4(glm::floatBitsToUint(acc.sum[p]), 0u);
        contents[2 * p + 1] = glm::uvec4(glm::floatBitsToUint(acc.oddSum[p]), 0u);
    }
    std::vector<glm::uvec4> work;
    for (int by = acc.rows.x; by < acc.rows.y; by += 8)
        for (int bx = 0; bx < acc.width; bx += 8)
            for (int y = by; y < std::min(by + 8, acc.rows.y); ++y)
                for (int x = bx; x < std::min(bx + 8, acc.width); ++x) {
                    const std::size_t p = acc.index(x, y);
                    if (next[p] > acc.count[p]) work.emplace_back(static_cast<std::uint32_t>(p), acc.count[p], next[p], 0u);
                }
    std::stable_sort(work.begin(), work.end(), [](const glm::uvec4& a, const glm::uvec4& b) { return a.z - a.y > b.z - b.y; });
    contents.insert(contents.end(), work.begin(), work.end());

    auto start = Clock::now();
    SceneUpload& gpuScene = impl_->uploadScene(data, in.frame, stats);
    stats.uploadSeconds = secondsSince(start);
    if ((kernel == GpuKernel::Auto ? autoKernel(impl_->context.info()) : kernel) == GpuKernel::Wavefront) {
        stats.wavefront = true;
        stats.samplesPerDispatch = 1;
        const GpuRenderDevice device{impl_->context, impl_->runner, impl_->transfers, impl_->layout, *impl_->kernels};
        addSampleRangesWavefront(device, gpuScene, data, in, options, contents, pixels, stats);
    } else {
        addSampleRangesMegakernel(gpuScene, in, options, contents, work, acc.width, stats);
    }

    start = Clock::now();
    std::vector<glm::uvec4> sums(2 * pixels);
    impl_->transfers.download(gpuScene.accum(), std::as_writable_bytes(std::span(sums)));
    for (std::size_t p = 0; p < pixels; ++p) {
        acc.sum[p] = glm::uintBitsToFloat(glm::uvec3(sums[2 * p]));
        acc.oddSum[p] = glm::uintBitsToFloat(glm::uvec3(sums[2 * p + 1]));
    }
    acc.count = next;
    stats.readbackSeconds = secondsSince(start);
    if (statsOut) *statsOut = stats;
}

void GpuRenderer::addSampleRangesMegakernel(SceneUpload& gpuScene, const KernelInputs& in, const RenderOptions& options,
                                            const std::vector<glm::uvec4>& contents, const std::vector<glm::uvec4>& work,
                                            int width, GpuRenderStats& stats) {
    const std::uint32_t k = in.batching.perDispatch;
    const vk::raii::Pipeline& pipeline = impl_->kernels->pipeline(in.features, k, &stats.pipelineSeconds);
    auto start = Clock::now();
    gpuScene.beginAdaptiveRound(impl_->context, impl_->transfers, in.frame, contents);
    stats.uploadSeconds += secondsSince(start);
    stats.warmUpSeconds = impl_->runner.run([&](const vk::raii::CommandBuffer& commands) {
        recordWarmUp(commands, *pipeline, impl_->layout.pipelineLayout(), gpuScene.descriptorSet());
    });

    // Entries per dispatch: about a 256x256 tile's pixels, so that a submission stays short.
    constexpr std::uint32_t kEntriesPerDispatch = 1u << 16;
    const std::uint32_t most = work.empty() ? 0u : work.front().z - work.front().y;
    const std::uint32_t passes = (most + k - 1) / k;
    std::size_t active = work.size();
    Progress progress("GPU round", options.quiet);
    start = Clock::now();
    for (std::uint32_t pass = 0; pass < passes; ++pass) {
        while (active > 0 && work[active - 1].z - work[active - 1].y <= pass * k) --active;
        for (std::size_t first = 0; first < active; first += kEntriesPerDispatch) {
            throwIfCancelled(impl_->context, options);
            const auto count = static_cast<std::uint32_t>(std::min<std::size_t>(kEntriesPerDispatch, active - first));
            const double seconds = impl_->runner.run([&](const vk::raii::CommandBuffer& commands) {
                recordAdaptivePass(commands, *pipeline, impl_->layout.pipelineLayout(), gpuScene.descriptorSet(),
                                   static_cast<std::uint32_t>(first), count, pass * k, k);
            });
            countSubmission(stats, seconds, impl_->runner.lastDeviceSeconds());
            ++stats.dispatches;
            throwIfKernelFailed(gpuScene.status(), static_cast<std::uint32_t>(width), impl_->context.info().loopLimiter);
        }
        progress.update(static_cast<double>(pass + 1) / passes);
    }
    stats.renderSeconds = secondsSince(start);
    stats.nonFiniteSamples = gpu::statusNonFiniteSamples(gpuScene.status());
}

}  // namespace vkrt
