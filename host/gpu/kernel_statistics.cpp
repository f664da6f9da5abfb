#include "kernel_statistics.h"

#include <chrono>
#include <map>
#include <utility>

#include "compute_pipeline.h"
#include "context.h"
#include "kernel_cache.h"
#include "kernel_layouts.h"
#include "kernel_modules.h"
#include "kernel_source.h"
#include "pipeline_statistics.h"

namespace vkrt {

namespace {

ContextOptions compileOnlyContext(const GpuRendererOptions& options) {
    ContextOptions c = contextOptions(options, {});
    c.compileOnly = true;
    return c;
}

}  // namespace

struct KernelStatisticsCompiler::Impl {
    explicit Impl(const GpuRendererOptions& options)
        : source(kernelSource("render", options, {})), context(compileOnlyContext(options)), layout(renderLayout(context)),
          modules(context, source, loadKernel(source)) {}
    KernelSource source;
    Context context;
    KernelLayout layout;
    KernelModules modules;
    std::map<std::pair<FeatureSet, std::uint32_t>, KernelVariantReport> done;
};

KernelStatisticsCompiler::KernelStatisticsCompiler(const GpuRendererOptions& options) : impl_(std::make_unique<Impl>(options)) {}
KernelStatisticsCompiler::~KernelStatisticsCompiler() = default;

std::string KernelStatisticsCompiler::deviceName() const { return impl_->context.info().name; }
std::string KernelStatisticsCompiler::driver() const { return impl_->context.info().driver; }
bool KernelStatisticsCompiler::hasStatistics() const { return impl_->context.statisticsEnabled(); }
std::size_t KernelStatisticsCompiler::variants() const { return impl_->done.size(); }

KernelVariantReport KernelStatisticsCompiler::compile(const GpuSceneData& data, const RenderOptions& options, KernelVariant variant,
                                                      bool adaptive, std::uint32_t wavefrontStage) {
    const std::uint64_t lockstep = impl_->context.info().loopLimiter ? kLockstepFactor : 1;
    KernelInputs in = makeKernelInputs(data, options, variant, 0, lockstep);
    in.features.adaptive = adaptive;
    in.features.wavefrontStage = wavefrontStage;
    if (wavefrontStage != gpu::WAVEFRONT_OFF) in.batching.perDispatch = 1;  // the stages' pipelines (wavefront_renderer.cpp)
    const auto key = std::make_pair(in.features, in.batching.perDispatch);
    if (auto found = impl_->done.find(key); found != impl_->done.end()) {
        KernelVariantReport again = found->second;
        again.cached = true;
        return again;
    }
    KernelVariantReport r;
    if (wavefrontStage != gpu::WAVEFRONT_OFF) r.stage = wavefrontStageName(wavefrontStage);
    r.features = in.features.describe();
    r.samplesPerDispatch = in.batching.perDispatch;
    const std::vector<SpecConstant> constants = kernelConstants(in.features, in.batching.perDispatch, impl_->context.info());
    vk::PipelineCreateFlags flags = vk::PipelineCreateFlagBits::eDispatchBase;
    if (impl_->context.statisticsEnabled()) flags |= vk::PipelineCreateFlagBits::eCaptureStatisticsKHR;
    const auto start = std::chrono::steady_clock::now();
    const vk::raii::Pipeline pipeline =
        makeComputePipeline(impl_->context, nullptr, impl_->layout.pipelineLayout(), *impl_->modules.module(wavefrontStage),
                            constants, flags);
    r.compileSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (const ExecutableStatistics& e : pipelineStatistics(impl_->context, *pipeline)) {
        r.vgprs = e.get("VGPRs");
        r.sgprs = e.get("SGPRs");
        r.spilledVgprs = e.get("Spilled VGPRs");
        r.spilledSgprs = e.get("Spilled SGPRs");
        r.scratchBytes = e.get("Scratch size");
        r.wavesPerSimd = e.get("Subgroups per SIMD");
    }
    impl_->done.emplace(key, r);
    return r;
}

}  // namespace vkrt
