// A prepared scene's device data: its arrays and the current render's frame (kernel_inputs.h)
// uploaded into the buffers of device_host.h's bindings, the accumulation and status buffers, and
// the descriptor set binding them all. Every buffer is checked against the device limits before
// anything is allocated.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <vulkan/vulkan_raii.hpp>

#include "buffer.h"
#include "compute_pipeline.h"
#include "context.h"
#include "device_limits.h"
#include "kernel_inputs.h"

namespace vkrt {

// A buffer about to be created: its name (for errors), how it is bound, and its bytes.
struct BufferPlan {
    std::string name;
    BufferKind kind;
    std::uint64_t bytes;
    std::uint64_t texelBytes = 16;  // StorageTexel only: RGBA32UI (16) or R32UI (4)
};

// The buffers a render needs, in binding order; empty tables get one zeroed element because
// Vulkan has no empty buffers.
// nodeBytes: the BVH nodes as uploaded (node_packing.h).
std::vector<BufferPlan> planSceneBuffers(const SceneTables& tables, const bvh::SceneBvh& bvh, std::uint64_t nodeBytes,
                                         std::uint64_t pixels);

// Throws DeviceLimitExceeded for the first buffer over a limit, or when all together exceed the heap.
void checkSceneBuffers(const BufferLimits& limits, const std::vector<BufferPlan>& plan);

class SceneUpload {
public:
    SceneUpload(const Context& context, Transfers& transfers, const KernelLayout& layout, const GpuSceneData& data,
                const gpu::FrameParams& frame);

    // Another render of the same prepared scene: its frame uploaded, the accumulation buffer grown
    // when the image has more pixels (checked against the limits first), the sums and the status
    // zeroed. The scene's tables stay as they are.
    void beginRender(const Context& context, Transfers& transfers, const gpu::FrameParams& frame);

    // Adaptive sampling's round (render.comp's ADAPTIVE kernel): the frame uploaded, the accumulation
    // buffer grown to hold `accum` (per pixel the sum and the odd samples' sum, then the work list)
    // and `extraTexels` more (the wavefront stages' paths), filled with `accum`, the status zeroed.
    void beginAdaptiveRound(const Context& context, Transfers& transfers, const gpu::FrameParams& frame,
                            std::span<const glm::uvec4> accum, std::uint64_t extraTexels = 0);

    // A wavefront render (wavefront_renderer.h): the frame uploaded, the accumulation buffer grown
    // to the pixel sums and `stateTexels` texels of paths in flight after them, all zeroed, and
    // the status zeroed.
    void beginWavefront(const Context& context, Transfers& transfers, const gpu::FrameParams& frame, std::uint64_t stateTexels);

    vk::DescriptorSet descriptorSet() const { return *set_; }
    const Buffer& accum() const { return buffers_[gpu::BINDING_ACCUM]; }
    vk::Buffer statusBuffer() const { return buffers_[gpu::BINDING_STATUS].handle(); }
    // Mapped: the host reads it after every submission.
    const gpu::RenderStatus& status() const { return *reinterpret_cast<const gpu::RenderStatus*>(buffers_[gpu::BINDING_STATUS].mapped()); }
    std::uint64_t bytes() const { return bytes_; }

private:
    // Replaces the accumulation buffer with one of `bytes` when it is smaller (checked first).
    void growAccum(const Context& context, std::uint64_t bytes);

    std::vector<Buffer> buffers_;  // indexed by binding
    std::vector<vk::raii::BufferView> views_;  // indexed by binding: the texel buffers' views, else null
    vk::raii::DescriptorPool pool_ = nullptr;
    vk::raii::DescriptorSet set_ = nullptr;
    std::uint64_t bytes_ = 0;
};

}  // namespace vkrt
