// Compute pipelines from SPIR-V with specialization constants, and the descriptor and pipeline
// layout every render kernel shares (the bindings of shaders/shared/device_host.h).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <vulkan/vulkan_raii.hpp>

#include "context.h"

namespace vkrt {

struct SpecConstant {
    std::uint32_t id;
    std::uint32_t value;  // bool constants take VK_TRUE / VK_FALSE (32-bit)
};

vk::raii::ShaderModule makeShaderModule(const Context& context, std::span<const std::uint32_t> spirv);

// Entry point "main". `cache` may be nullptr. Render kernels need
// vk::PipelineCreateFlagBits::eDispatchBase (partial dispatches with vkCmdDispatchBase).
vk::raii::Pipeline makeComputePipeline(const Context& context, const vk::raii::PipelineCache* cache,
                                       vk::PipelineLayout layout, vk::ShaderModule module,
                                       std::span<const SpecConstant> constants, vk::PipelineCreateFlags flags = {});

// A kernel's interface: descriptor set 0 and one push-constant range.
class KernelLayout {
public:
    KernelLayout(const Context& context, std::span<const vk::DescriptorSetLayoutBinding> bindings, std::uint32_t pushBytes);
    vk::DescriptorSetLayout setLayout() const { return *setLayout_; }
    vk::PipelineLayout pipelineLayout() const { return *pipelineLayout_; }

private:
    vk::raii::DescriptorSetLayout setLayout_;
    vk::raii::PipelineLayout pipelineLayout_;
};

// render.comp: the twelve bindings of device_host.h (BINDING_NODES .. BINDING_STATUS), PassParams.
KernelLayout renderLayout(const Context& context);
// trace_rays.comp: nodes, primitives, instances, frame, status, rays, hits; TraceParams.
KernelLayout traceLayout(const Context& context);

}  // namespace vkrt
