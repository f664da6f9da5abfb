#include "gpu_renderer.h"

#include <algorithm>
#include <chrono>

#include "buffer.h"
#include "commands.h"
#include "compute_pipeline.h"
#include "context.h"
#include "feature_set.h"
#include "frame_params.h"
#include "gpu_scene.h"
#include "kernel_cache.h"
#include "kernel_source.h"
#include "node_packing.h"
#include "progress.h"
#include "render_status.h"
#include "sample_batching.h"
#include "scene_tables.h"
#include "submission_recorder.h"
#include "traversal_stack.h"

namespace vkrt {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

ContextOptions contextOptions(const GpuRendererOptions& o) {
    ContextOptions c;
    c.gpu = o.gpu;
    c.validation = o.validation;
    c.maxBufferBytes = o.maxBufferBytes;
    c.forceStaging = o.forceStaging;
    return c;
}

KernelSource kernelSource(const GpuRendererOptions& o) {
    KernelSource k;
    k.shaderDir = o.shaderDir;
    k.spirv = o.kernelSpirv;
    return k;
}

// Pixel = sum of its samples (accumulated in sample order on the device) / rpp, the same float
// operations as the CPU reference: no reciprocal multiply, which could differ in the last bit.
Image resolve(const std::vector<glm::vec4>& sums, int width, int height, int samples) {
    Image image(width, height);
    const auto n = static_cast<float>(samples);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = glm::vec3(sums[i]) / n;
    return image;
}

}  // namespace

struct GpuRenderer::Impl {
    explicit Impl(const GpuRendererOptions& options)
        : context(contextOptions(options)), runner(context), transfers(context, runner), layout(renderLayout(context)),
          kernels(context, layout, loadKernel(kernelSource(options))) {}

    Context context;
    CommandRunner runner;
    Transfers transfers;
    KernelLayout layout;
    KernelCache kernels;
};

GpuRenderer::GpuRenderer(const GpuRendererOptions& options) : impl_(std::make_unique<Impl>(options)) {}
GpuRenderer::~GpuRenderer() = default;

std::string GpuRenderer::deviceName() const { return impl_->context.info().name; }
std::shared_ptr<const ValidationLog> GpuRenderer::validationLog() const { return impl_->context.validationLog(); }
std::size_t GpuRenderer::pipelineCount() const { return impl_->kernels.size(); }

Image GpuRenderer::render(const Scene& scene, const SceneAccel& accel, const RenderOptions& options, GpuRenderStats* statsOut,
                          const GpuRenderSettings& settings) {
    GpuRenderStats stats;
    stats.device = impl_->context.info().name;
    const gpu::FrameParams frame = makeFrameParams(scene, accel, options);  // validates the options
    const bool general = settings.variant == KernelVariant::General;
    FeatureSet features = general ? generalFeatureSet(options) : deriveFeatureSet(scene, accel, options);
    checkTraversalStack(accel.bvh, features.instances);
    auto start = Clock::now();
    const GpuNodes nodes = gpuNodes(accel.bvh);
    features.packedNodes = nodes.packed;
    stats.features = features.describe();
    stats.generalKernel = general;
    const double packSeconds = secondsSince(start);

    const auto samples = static_cast<std::uint32_t>(options.samplesPerPixel);
    const SampleBatching batching{samples, samplesPerDispatch(sampleLoopBound(scene, accel.bvh, features, options), samples,
                                                              settings.samplesPerDispatch)};
    features.samplesPerDispatch = batching.perDispatch;
    stats.samplesPerDispatch = batching.perDispatch;
    const vk::raii::Pipeline& pipeline = impl_->kernels.pipeline(features, &stats.pipelineSeconds);

    start = Clock::now();
    const GpuScene gpuScene(impl_->context, impl_->transfers, impl_->layout, buildSceneTables(scene, accel), accel.bvh, nodes, frame);
    stats.uploadSeconds = packSeconds + secondsSince(start);
    stats.sceneBytes = gpuScene.bytes();

    stats.warmUpSeconds = impl_->runner.run([&](const vk::raii::CommandBuffer& commands) {
        recordWarmUp(commands, *pipeline, impl_->layout.pipelineLayout(), gpuScene.descriptorSet());
    });

    TilingPolicy tiling = settings.tiling;
    tiling.maxWorkgroups = std::min(tiling.maxWorkgroups, impl_->context.info().maxWorkGroupCountX);
    const auto width = static_cast<std::uint32_t>(options.width);
    TilePlanner planner(width, static_cast<std::uint32_t>(options.height), batching.passes(), tiling);
    Progress progress("GPU render", options.quiet);
    start = Clock::now();
    while (!planner.done()) {
        if (options.cancel && options.cancel->load()) {
            impl_->context.device().waitIdle();
            throw RenderCancelled{};
        }
        const Submission submission = planner.next();
        const double seconds = impl_->runner.run([&](const vk::raii::CommandBuffer& commands) {
            recordSubmission(commands, *pipeline, impl_->layout.pipelineLayout(), gpuScene.descriptorSet(), submission, batching);
        });
        planner.reportSeconds(seconds);
        ++stats.submissions;
        stats.dispatches += submission.sampleCount;
        stats.maxSubmissionSeconds = std::max(stats.maxSubmissionSeconds, seconds);
        throwIfKernelFailed(gpuScene.status(), width);
        progress.update(planner.fractionDone());
    }
    stats.renderSeconds = secondsSince(start);
    stats.nonFiniteSamples = gpuScene.status().flags.w;

    start = Clock::now();
    std::vector<glm::vec4> sums(static_cast<std::size_t>(options.width) * options.height);
    impl_->transfers.download(gpuScene.accum(), std::as_writable_bytes(std::span(sums)));
    Image image = resolve(sums, options.width, options.height, options.samplesPerPixel);
    stats.readbackSeconds = secondsSince(start);
    if (statsOut) *statsOut = stats;
    return image;
}

Image renderGpu(const Scene& scene, const SceneAccel& accel, const RenderOptions& options, GpuRenderStats* stats,
                const GpuRendererOptions& gpu) {
    GpuRenderer renderer(gpu);
    return renderer.render(scene, accel, options, stats);
}

}  // namespace vkrt
