#include "gpu_ray_tracer.h"

#include <algorithm>
#include <array>

#include "buffer.h"
#include "commands.h"
#include "compute_pipeline.h"
#include "context.h"
#include "device_limits.h"
#include "feature_set.h"
#include "kernel_cache.h"
#include "kernel_error.h"
#include "kernel_layouts.h"
#include "kernel_source.h"
#include "node_packing.h"
#include "traversal_stack.h"
#include "vulkan_errors.h"

namespace vkrt {

namespace {

constexpr std::uint32_t kLocalSize = 64;  // trace_rays.comp's local_size_x
// Rays per submission: one dispatch of at most 65535 workgroups; 1M rays keep a submission
// well under a second on lavapipe even for incoherent shadow rays (~3 Mrays/s).
constexpr std::uint32_t kBatchRays = 1u << 20;

template <class T>
std::span<const std::byte> bytesOf(const std::vector<T>& items) {
    return std::as_bytes(std::span(items));
}

constexpr vk::BufferUsageFlags kStorage =
    vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eTransferDst | vk::BufferUsageFlagBits::eTransferSrc;
constexpr vk::BufferUsageFlags kTexels = vk::BufferUsageFlagBits::eStorageTexelBuffer | vk::BufferUsageFlagBits::eTransferDst;

template <class T>
std::uint64_t paddedBytes(const std::vector<T>& items) {
    return std::max<std::uint64_t>(1, items.size()) * sizeof(T);
}

}  // namespace

struct GpuRayTracer::Impl {
    Impl(const bvh::SceneBvh& bvh, const GpuRendererOptions& options, const GpuTestHooks& hooks);

    Context context;
    CommandRunner runner;
    Transfers transfers;
    KernelLayout layout;
    KernelCache kernels;
    std::uint32_t batch;
    GpuNodes nodeData;  // after batch: checkedBatch refuses unfit leaves before gpuNodes meets them
    FeatureSet features;
    Buffer nodes, prims, instances, frame, status, rays, hits;
    vk::raii::BufferView nodeView = nullptr, primView = nullptr, instanceView = nullptr, rayView = nullptr, hitView = nullptr;
    vk::raii::DescriptorPool pool = nullptr;
    vk::raii::DescriptorSet set = nullptr;
};

namespace {

// The ray texel buffer of one batch, sized off the lengths that change lavapipe's JIT key.
std::uint64_t rayBytes(std::uint64_t batch) { return stableTexelBufferBytes(batch * sizeof(gpu::TraceRayInput)); }
// The hit words of one batch (device_host.h, TRACE_HIT_WORDS): room for the instanced layout,
// whichever the BVH needs.
std::uint64_t hitBytes(std::uint64_t batch) {
    return stableTexelBufferBytes(batch * gpu::TRACE_HIT_WORDS_INSTANCED * sizeof(std::uint32_t));
}

// Rays per submission: what the ray and hit texel buffers and one dispatch can hold, in whole
// workgroups.
std::uint32_t batchRays(const Context& context) {
    const BufferLimits& limits = context.limits();
    const std::uint64_t byRays = std::uint64_t{limits.maxTexelBufferElements} * 16 / sizeof(gpu::TraceRayInput);
    const std::uint64_t byDispatch = static_cast<std::uint64_t>(std::min(context.info().maxWorkGroupCountX, 65535u)) * kLocalSize;
    std::uint64_t batch = std::min({byRays, byDispatch, std::uint64_t{kBatchRays}}) / kLocalSize * kLocalSize;
    while (batch > kLocalSize && (rayBytes(batch) / 16 > limits.maxTexelBufferElements ||
                                  hitBytes(batch) / sizeof(std::uint32_t) > limits.maxTexelBufferElements))
        batch -= kLocalSize;
    return static_cast<std::uint32_t>(std::max<std::uint64_t>(kLocalSize, batch));
}

// The nodes' bytes in the larger of the two layouts (node_packing.h), for the checks made before
// the layout is chosen.
std::uint64_t exactNodeBytes(const bvh::SceneBvh& bvh) {
    return std::max<std::uint64_t>(1, bvh.nodes.size()) * sizeof(gpu::GpuExactBvhNode);
}

// Checks every buffer before any is created (the limits are checked in Impl's initialiser).
std::uint32_t checkedBatch(const Context& context, const bvh::SceneBvh& bvh) {
    const std::uint32_t batch = batchRays(context);
    const BufferLimits& limits = context.limits();
    checkBufferFits(limits, "BVH nodes", BufferKind::StorageTexel, stableTexelBufferBytes(exactNodeBytes(bvh)));
    checkBufferFits(limits, "primitives", BufferKind::StorageTexel, stableTexelBufferBytes(paddedBytes(bvh.prims)));
    checkBufferFits(limits, "instances", BufferKind::StorageTexel, stableTexelBufferBytes(paddedBytes(bvh.instances)));
    checkBufferFits(limits, "rays", BufferKind::StorageTexel, rayBytes(batch));
    checkBufferFits(limits, "hits", BufferKind::StorageTexel, hitBytes(batch));
    checkTotalFits(limits, stableTexelBufferBytes(exactNodeBytes(bvh)) + stableTexelBufferBytes(paddedBytes(bvh.prims)) +
                               stableTexelBufferBytes(paddedBytes(bvh.instances)) + rayBytes(batch) + hitBytes(batch));
    checkTraversalStack(bvh, needsTopLevel(bvh));
    return batch;
}

}  // namespace

GpuRayTracer::Impl::Impl(const bvh::SceneBvh& bvh, const GpuRendererOptions& options, const GpuTestHooks& hooks)
    : context(contextOptions(options, hooks)), runner(context), transfers(context, runner), layout(traceLayout(context)),
      kernels(context, layout, kernelSource("trace_rays", options, hooks), loadKernel(kernelSource("trace_rays", options, hooks))), batch(checkedBatch(context, bvh)),
      nodeData(gpuNodes(bvh)), features(traversalFeatureSet(bvh, nodeData.packed)),
      nodes(context, "BVH nodes", stableTexelBufferBytes(nodeBytes(nodeData)), kTexels, MemoryUse::Device),
      prims(context, "primitives", stableTexelBufferBytes(paddedBytes(bvh.prims)), kTexels, MemoryUse::Device),
      instances(context, "instances", stableTexelBufferBytes(paddedBytes(bvh.instances)), kTexels, MemoryUse::Device),
      frame(context, "frame parameters", sizeof(gpu::FrameParams),
            vk::BufferUsageFlagBits::eUniformBuffer | vk::BufferUsageFlagBits::eTransferDst, MemoryUse::Device),
      // Bound because the layout shared with render.comp declares it; trace_rays.comp reports
      // failures in each hit's w instead.
      status(context, "render status", sizeof(gpu::RenderStatus), kStorage, MemoryUse::Shared),
      rays(context, "rays", rayBytes(batch), kTexels, MemoryUse::Device),
      hits(context, "hits", hitBytes(batch), kTexels | vk::BufferUsageFlagBits::eTransferSrc, MemoryUse::Device) {
    transfers.upload(nodes, bytesOf(nodeData.texels));
    transfers.upload(prims, bytesOf(bvh.prims));
    transfers.upload(instances, bytesOf(bvh.instances));
    gpu::FrameParams params{};
    // The only fields traversal reads: the top-level root and the inlined world's ranges.
    params.scene.w = bvh.topRoot;
    params.world = nodeData.world;
    transfers.upload(frame, std::as_bytes(std::span(&params, 1)));
    transfers.zero(status);
    nodeView = makeTexelView(context, nodes);
    primView = makeTexelView(context, prims);
    instanceView = makeTexelView(context, instances);
    rayView = makeTexelView(context, rays);
    hitView = makeTexelView(context, hits, sizeof(std::uint32_t));  // R32UI words

    const std::array sizes = {vk::DescriptorPoolSize(vk::DescriptorType::eStorageTexelBuffer, 5),
                              vk::DescriptorPoolSize(vk::DescriptorType::eStorageBuffer, 1),
                              vk::DescriptorPoolSize(vk::DescriptorType::eUniformBuffer, 1)};
    pool = vk::raii::DescriptorPool(context.device(),
                                    vk::DescriptorPoolCreateInfo(vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, 1, sizes));
    const vk::DescriptorSetLayout setLayout = layout.setLayout();
    set = std::move(vk::raii::DescriptorSets(context.device(), vk::DescriptorSetAllocateInfo(*pool, setLayout)).front());

    const vk::BufferView views[] = {*nodeView, *primView, *instanceView, *rayView, *hitView};
    const vk::DescriptorBufferInfo infos[] = {{frame.handle(), 0, VK_WHOLE_SIZE}, {status.handle(), 0, VK_WHOLE_SIZE}};
    using T = vk::DescriptorType;
    const std::array writes = {
        vk::WriteDescriptorSet(*set, gpu::BINDING_NODES, 0, 1, T::eStorageTexelBuffer, nullptr, nullptr, &views[0]),
        vk::WriteDescriptorSet(*set, gpu::BINDING_PRIMS, 0, 1, T::eStorageTexelBuffer, nullptr, nullptr, &views[1]),
        vk::WriteDescriptorSet(*set, gpu::BINDING_INSTANCES, 0, 1, T::eStorageTexelBuffer, nullptr, nullptr, &views[2]),
        vk::WriteDescriptorSet(*set, gpu::BINDING_FRAME, 0, 1, T::eUniformBuffer, nullptr, &infos[0]),
        vk::WriteDescriptorSet(*set, gpu::BINDING_STATUS, 0, 1, T::eStorageBuffer, nullptr, &infos[1]),
        vk::WriteDescriptorSet(*set, gpu::BINDING_RAYS, 0, 1, T::eStorageTexelBuffer, nullptr, nullptr, &views[3]),
        vk::WriteDescriptorSet(*set, gpu::BINDING_HITS, 0, 1, T::eStorageTexelBuffer, nullptr, nullptr, &views[4]),
    };
    context.device().updateDescriptorSets(writes, {});
}

GpuRayTracer::GpuRayTracer(const bvh::SceneBvh& bvh, const GpuRendererOptions& options, const GpuTestHooks& hooks)
    : impl_(std::make_unique<Impl>(bvh, options, hooks)) {}
GpuRayTracer::~GpuRayTracer() = default;

std::uint32_t GpuRayTracer::maxRaysPerSubmission() const { return impl_->batch; }
std::string GpuRayTracer::deviceName() const { return impl_->context.info().name; }
bool GpuRayTracer::packedNodes() const { return impl_->nodeData.packed; }
double GpuRayTracer::nodeAreaGrowth() const { return impl_->nodeData.areaGrowth; }
std::shared_ptr<const ValidationLog> GpuRayTracer::validationLog() const { return impl_->context.validationLog(); }

std::vector<gpu::TraceHitOutput> GpuRayTracer::trace(std::span<const gpu::TraceRayInput> rays, bool anyHit, GpuTraceStats* statsOut) {
    Impl& m = *impl_;
    GpuTraceStats stats;
    const vk::raii::Pipeline& pipeline = m.kernels.pipeline(m.features, 1, &stats.pipelineSeconds);
    std::vector<gpu::TraceHitOutput> hits(rays.size());
    const std::uint32_t wordsPerRay = m.features.instances ? gpu::TRACE_HIT_WORDS_INSTANCED : gpu::TRACE_HIT_WORDS;
    std::vector<std::uint32_t> words(std::size_t{m.batch} * wordsPerRay);
    for (std::size_t first = 0; first < rays.size(); first += m.batch) {
        const auto count = static_cast<std::uint32_t>(std::min<std::size_t>(m.batch, rays.size() - first));
        m.transfers.upload(m.rays, std::as_bytes(rays.subspan(first, count)));
        const gpu::TraceParams params{glm::uvec4(count, anyHit ? 1u : 0u, 0u, 0u)};
        stats.traceSeconds += m.runner.run([&](const vk::raii::CommandBuffer& commands) {
            computeToComputeBarrier(commands);
            commands.bindPipeline(vk::PipelineBindPoint::eCompute, *pipeline);
            commands.bindDescriptorSets(vk::PipelineBindPoint::eCompute, m.layout.pipelineLayout(), 0, *m.set, {});
            commands.pushConstants<gpu::TraceParams>(m.layout.pipelineLayout(), vk::ShaderStageFlagBits::eCompute, 0, params);
            // 1 x 1: trace_rays.comp reads its push constants at gl_NumWorkGroups.z - 1 (bindings.glsl).
            commands.dispatch((count + kLocalSize - 1) / kLocalSize, 1, 1);
            computeToHostBarrier(commands);
        });
        if (m.runner.lastDeviceSeconds() >= 0.0) stats.kernelSeconds = std::max(stats.kernelSeconds, 0.0) + m.runner.lastDeviceSeconds();
        ++stats.submissions;
        m.transfers.download(m.hits, std::as_writable_bytes(std::span(words).first(std::size_t{count} * wordsPerRay)));
        // The kernel reports failures per ray in its words (trace_rays.comp), not through atomics,
        // so the error can name the first ray that failed.
        std::uint32_t failures = 0;
        std::size_t failed = rays.size();
        for (std::size_t i = first; i < first + count; ++i) {
            const std::uint32_t* w = &words[(i - first) * wordsPerRay];
            const std::uint32_t instance = m.features.instances ? w[2] : 0u;
            if (w[0] == gpu::TRACE_FAILED) {
                hits[i].hit = glm::uvec4(gpu::TRACE_MISS, 0u, 0u, w[1]);
                if (failed == rays.size()) failed = i;
                failures |= w[1];
            } else {
                hits[i].hit = glm::uvec4(w[0], w[0] == gpu::TRACE_MISS ? 0u : w[1], w[0] == gpu::TRACE_MISS ? 0u : instance, 0u);
            }
        }
        if (failures == 0) continue;
        const glm::vec4 o = rays[failed].origin, d = rays[failed].direction;
        const std::string ray = "ray " + std::to_string(failed) + " of " + std::to_string(rays.size()) + " (origin " +
                                std::to_string(o.x) + ", " + std::to_string(o.y) + ", " + std::to_string(o.z) + ", direction " +
                                std::to_string(d.x) + ", " + std::to_string(d.y) + ", " + std::to_string(d.z) + ")";
        if (failures & gpu::STATUS_LOOP_BUDGET_EXCEEDED)
            throw GpuKernelError(ray + " needed more than " + std::to_string(gpu::LOOP_BUDGET) + " traversal steps (the kernel's loop budget" +
                                 (m.context.info().loopLimiter ? "; lavapipe before Mesa 25 cuts loops off silently at 65,535 passes)" : ")"));
        if (failures & gpu::STATUS_LOOP_CUT_OFF)
            throw GpuKernelError("the traversal of " + ray +
                                 (m.context.info().loopLimiter
                                      ? " was cut off by the driver's loop limiter (lavapipe before Mesa 25 ends every loop "
                                        "silently after 65,535 passes per group of 8 lanes)"
                                      : " ended before it finished, which this driver is not known to do: please report it"));
        if (failures & gpu::STATUS_RAY_STACK_OVERFLOW)
            throw GpuKernelError("the BVH traversal stack (" + std::to_string(gpu::TRAVERSAL_STACK_SIZE) + " entries) overflowed on " + ray);
        throw GpuKernelError("unknown failure flags " + std::to_string(failures) + " on " + ray);
    }
    if (statsOut) *statsOut = stats;
    return hits;
}

}  // namespace vkrt
