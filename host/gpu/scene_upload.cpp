#include "scene_upload.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <span>
#include <stdexcept>

namespace vkrt {

namespace {

template <class T>
std::uint64_t bytesOf(const std::vector<T>& items) {
    return std::max<std::uint64_t>(1, items.size()) * sizeof(T);
}

// The data for a binding, padded to the planned size with zeros (empty tables, the status).
template <class T>
std::vector<std::byte> padded(const std::vector<T>& items, std::uint64_t bytes) {
    std::vector<std::byte> data(bytes, std::byte{0});
    if (!items.empty()) std::memcpy(data.data(), items.data(), items.size() * sizeof(T));
    return data;
}

vk::BufferUsageFlags usageOf(BufferKind kind) {
    const vk::BufferUsageFlags transfers = vk::BufferUsageFlagBits::eTransferDst | vk::BufferUsageFlagBits::eTransferSrc;
    switch (kind) {
    case BufferKind::Storage: return transfers | vk::BufferUsageFlagBits::eStorageBuffer;
    case BufferKind::StorageTexel: return transfers | vk::BufferUsageFlagBits::eStorageTexelBuffer;
    case BufferKind::Uniform: return transfers | vk::BufferUsageFlagBits::eUniformBuffer;
    case BufferKind::Plain: return transfers;
    }
    return transfers;
}

}  // namespace

std::vector<BufferPlan> planSceneBuffers(const SceneTables& tables, const bvh::SceneBvh& bvh, std::uint64_t nodeBytes,
                                         std::uint64_t pixels) {
    std::vector<BufferPlan> plan(gpu::RENDER_BINDING_COUNT);
    // Every table the kernel reads is a texel buffer, sized past the lengths that change lavapipe's
    // JIT key (stableTexelBufferBytes, buffer.h).
    auto texels = [](std::uint64_t bytes) { return stableTexelBufferBytes(bytes); };
    plan[gpu::BINDING_NODES] = {"BVH nodes", BufferKind::StorageTexel, texels(nodeBytes)};
    plan[gpu::BINDING_PRIMS] = {"primitives", BufferKind::StorageTexel, texels(bytesOf(bvh.prims))};
    plan[gpu::BINDING_PRIM_INFO] = {"primitive info", BufferKind::StorageTexel, texels(bytesOf(tables.primInfos))};
    plan[gpu::BINDING_VERTEX_ATTRIBS] = {"vertex attributes", BufferKind::StorageTexel, texels(bytesOf(tables.vertexAttribs))};
    // The moving instances' motion records follow the instances (Instance::info.w points at them).
    plan[gpu::BINDING_INSTANCES] = {"instances", BufferKind::StorageTexel,
                                    texels(bytesOf(bvh.instances) + bvh.motions.size() * sizeof(gpu::InstanceMotion))};
    plan[gpu::BINDING_SHADERS] = {"materials", BufferKind::StorageTexel, texels(bytesOf(tables.materials))};
    plan[gpu::BINDING_LIGHTS] = {"lights", BufferKind::StorageTexel, texels(bytesOf(tables.lights))};
    plan[gpu::BINDING_TEXTURES] = {"texture info", BufferKind::StorageTexel, texels(bytesOf(tables.textures))};
    plan[gpu::BINDING_TEXELS] = {"texels", BufferKind::StorageTexel, texels(bytesOf(tables.texels)), 4};
    plan[gpu::BINDING_FRAME] = {"frame parameters", BufferKind::Uniform, sizeof(gpu::FrameParams)};
    plan[gpu::BINDING_ACCUM] = {"accumulation (one vec4 per pixel)", BufferKind::StorageTexel,
                                texels(std::max<std::uint64_t>(1, pixels) * sizeof(glm::vec4))};
    plan[gpu::BINDING_STATUS] = {"render status", BufferKind::Storage, sizeof(gpu::RenderStatus)};
    const SceneLighting& lighting = *tables.lighting;
    plan[gpu::BINDING_EMITTERS] = {"emitters", BufferKind::StorageTexel, texels(bytesOf(lighting.emitters.records))};
    plan[gpu::BINDING_EMITTER_TRIANGLES] = {"emitter triangles", BufferKind::StorageTexel, texels(bytesOf(lighting.emitters.triangles))};
    plan[gpu::BINDING_ENVIRONMENT] = {"environment map", BufferKind::StorageTexel, texels(bytesOf(lighting.environment.texels)), 4};
    plan[gpu::BINDING_ENVIRONMENT_CDF] = {"environment distribution", BufferKind::StorageTexel,
                                          texels(bytesOf(lighting.environmentLights.table)), 4};
    return plan;
}

void checkSceneBuffers(const BufferLimits& limits, const std::vector<BufferPlan>& plan) {
    std::uint64_t total = 0;
    for (const BufferPlan& p : plan) {
        checkBufferFits(limits, p.name, p.kind, p.bytes, p.texelBytes);
        total += p.bytes;
    }
    checkTotalFits(limits, total);
}

SceneUpload::SceneUpload(const Context& context, Transfers& transfers, const KernelLayout& layout, const GpuSceneData& data,
                         const gpu::FrameParams& frame) {
    const SceneTables& tables = data.tables;
    const bvh::SceneBvh& bvh = data.accel.bvh;
    const GpuNodes& nodes = data.nodes;
    const std::uint64_t pixels = static_cast<std::uint64_t>(gpu::frameWidth(frame)) * gpu::frameHeight(frame);
    const std::vector<BufferPlan> plan = planSceneBuffers(tables, bvh, nodeBytes(nodes), pixels);
    checkSceneBuffers(context.limits(), plan);

    buffers_.reserve(plan.size());
    for (std::size_t binding = 0; binding < plan.size(); ++binding) {
        const BufferPlan& p = plan[binding];
        const bool status = binding == gpu::BINDING_STATUS;
        const MemoryUse use = status ? MemoryUse::Shared : MemoryUse::Device;
        // The status also holds the wavefront stages' dispatch sizes (RenderStatus::queueGroups).
        const vk::BufferUsageFlags usage = usageOf(p.kind) | (status ? vk::BufferUsageFlagBits::eIndirectBuffer : vk::BufferUsageFlags{});
        buffers_.emplace_back(context, p.name, p.bytes, usage, use);
        bytes_ += p.bytes;
    }
    // Every table in one batch of staging copies (Transfers::uploadAll), each padded with zeros to
    // its planned size (empty tables, the texel buffers' stable sizes).
    std::vector<Transfers::Upload> uploads;
    auto upload = [&](std::uint32_t binding, const auto& items) {
        uploads.push_back({&buffers_[binding], std::as_bytes(std::span(items)), plan[binding].bytes});
    };
    upload(gpu::BINDING_NODES, nodes.texels);
    upload(gpu::BINDING_PRIMS, bvh.prims);
    upload(gpu::BINDING_PRIM_INFO, tables.primInfos);
    upload(gpu::BINDING_VERTEX_ATTRIBS, tables.vertexAttribs);
    std::vector<std::byte> instanceTable = padded(bvh.instances, plan[gpu::BINDING_INSTANCES].bytes);
    if (!bvh.motions.empty())
        std::memcpy(instanceTable.data() + bvh.instances.size() * sizeof(gpu::Instance), bvh.motions.data(),
                    bvh.motions.size() * sizeof(gpu::InstanceMotion));
    upload(gpu::BINDING_INSTANCES, instanceTable);
    upload(gpu::BINDING_SHADERS, tables.materials);
    upload(gpu::BINDING_LIGHTS, tables.lights);
    upload(gpu::BINDING_TEXTURES, tables.textures);
    upload(gpu::BINDING_TEXELS, tables.texels);
    const std::array<gpu::FrameParams, 1> frames = {frame};
    upload(gpu::BINDING_FRAME, frames);
    upload(gpu::BINDING_EMITTERS, tables.lighting->emitters.records);
    upload(gpu::BINDING_EMITTER_TRIANGLES, tables.lighting->emitters.triangles);
    upload(gpu::BINDING_ENVIRONMENT, tables.lighting->environment.texels);
    upload(gpu::BINDING_ENVIRONMENT_CDF, tables.lighting->environmentLights.table);
    transfers.uploadAll(uploads);
    transfers.zero(buffers_[gpu::BINDING_ACCUM]);
    transfers.zero(buffers_[gpu::BINDING_STATUS]);

    std::uint32_t texelBindings = 0, storageBindings = 0;
    views_.reserve(plan.size());
    for (std::size_t binding = 0; binding < plan.size(); ++binding) {
        views_.emplace_back(nullptr);
        if (plan[binding].kind == BufferKind::StorageTexel) {
            views_[binding] = makeTexelView(context, buffers_[binding], plan[binding].texelBytes);
            ++texelBindings;
        } else if (plan[binding].kind == BufferKind::Storage) {
            ++storageBindings;
        }
    }

    const std::array sizes = {vk::DescriptorPoolSize(vk::DescriptorType::eStorageTexelBuffer, texelBindings),
                              vk::DescriptorPoolSize(vk::DescriptorType::eStorageBuffer, storageBindings),
                              vk::DescriptorPoolSize(vk::DescriptorType::eUniformBuffer, 1)};
    pool_ = vk::raii::DescriptorPool(context.device(),
                                     vk::DescriptorPoolCreateInfo(vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, 1, sizes));
    const vk::DescriptorSetLayout setLayout = layout.setLayout();
    set_ = std::move(vk::raii::DescriptorSets(context.device(), vk::DescriptorSetAllocateInfo(*pool_, setLayout)).front());

    std::vector<vk::DescriptorBufferInfo> infos(plan.size());
    std::vector<vk::WriteDescriptorSet> writes;
    std::vector<vk::BufferView> texelViews(plan.size());
    for (std::uint32_t binding = 0; binding < plan.size(); ++binding) {
        vk::WriteDescriptorSet write(*set_, binding, 0, 1, vk::DescriptorType::eStorageBuffer);
        if (plan[binding].kind == BufferKind::StorageTexel) {
            texelViews[binding] = *views_[binding];
            write.descriptorType = vk::DescriptorType::eStorageTexelBuffer;
            write.pTexelBufferView = &texelViews[binding];
        } else {
            if (plan[binding].kind == BufferKind::Uniform) write.descriptorType = vk::DescriptorType::eUniformBuffer;
            infos[binding] = vk::DescriptorBufferInfo(buffers_[binding].handle(), 0, VK_WHOLE_SIZE);
            write.pBufferInfo = &infos[binding];
        }
        writes.push_back(write);
    }
    context.device().updateDescriptorSets(writes, {});
}

void SceneUpload::growAccum(const Context& context, std::uint64_t bytes) {
    if (bytes <= buffers_[gpu::BINDING_ACCUM].size()) return;
    const BufferPlan accum = planSceneBuffers(SceneTables{}, bvh::SceneBvh{}, 16, 1)[gpu::BINDING_ACCUM];
    checkBufferFits(context.limits(), accum.name, accum.kind, bytes, accum.texelBytes);
    bytes_ -= buffers_[gpu::BINDING_ACCUM].size();
    context.device().waitIdle();  // the old buffer may not be in use when it is replaced
    buffers_[gpu::BINDING_ACCUM] = Buffer(context, accum.name, bytes, usageOf(accum.kind), MemoryUse::Device);
    bytes_ += bytes;
    views_[gpu::BINDING_ACCUM] = makeTexelView(context, buffers_[gpu::BINDING_ACCUM], accum.texelBytes);
    const vk::BufferView view = *views_[gpu::BINDING_ACCUM];
    vk::WriteDescriptorSet write(*set_, gpu::BINDING_ACCUM, 0, 1, vk::DescriptorType::eStorageTexelBuffer);
    write.pTexelBufferView = &view;
    context.device().updateDescriptorSets(write, {});
}

void SceneUpload::beginRender(const Context& context, Transfers& transfers, const gpu::FrameParams& frame) {
    const std::uint64_t pixels = static_cast<std::uint64_t>(gpu::frameWidth(frame)) * gpu::frameHeight(frame);
    growAccum(context, planSceneBuffers(SceneTables{}, bvh::SceneBvh{}, 16, pixels)[gpu::BINDING_ACCUM].bytes);
    const std::array<gpu::FrameParams, 1> frames = {frame};
    transfers.upload(buffers_[gpu::BINDING_FRAME], std::as_bytes(std::span(frames)));
    transfers.zero(buffers_[gpu::BINDING_ACCUM]);
    transfers.zero(buffers_[gpu::BINDING_STATUS]);
}

void SceneUpload::beginAdaptiveRound(const Context& context, Transfers& transfers, const gpu::FrameParams& frame,
                                     std::span<const glm::uvec4> accum, std::uint64_t extraTexels) {
    // The texel buffer's size is kept stable as the tables' are (buffer.h), so that rounds with
    // work lists of different lengths do not change lavapipe's JIT key.
    growAccum(context, stableTexelBufferBytes(accum.size_bytes() + extraTexels * sizeof(glm::uvec4)));
    const std::array<gpu::FrameParams, 1> frames = {frame};
    transfers.upload(buffers_[gpu::BINDING_FRAME], std::as_bytes(std::span(frames)));
    transfers.upload(buffers_[gpu::BINDING_ACCUM], std::as_bytes(accum));
    transfers.zero(buffers_[gpu::BINDING_STATUS]);
}

void SceneUpload::beginWavefront(const Context& context, Transfers& transfers, const gpu::FrameParams& frame,
                                 std::uint64_t stateTexels) {
    const std::uint64_t pixels = static_cast<std::uint64_t>(gpu::frameWidth(frame)) * gpu::frameHeight(frame);
    growAccum(context, stableTexelBufferBytes((pixels + stateTexels) * sizeof(glm::uvec4)));
    const std::array<gpu::FrameParams, 1> frames = {frame};
    transfers.upload(buffers_[gpu::BINDING_FRAME], std::as_bytes(std::span(frames)));
    transfers.zero(buffers_[gpu::BINDING_ACCUM]);
    transfers.zero(buffers_[gpu::BINDING_STATUS]);
}

}  // namespace vkrt
