// Compute pipelines from SPIR-V with specialization constants, and a kernel's descriptor and
// pipeline layout (one descriptor set, one push-constant range).
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

// One compute-stage binding of descriptor set 0.
vk::DescriptorSetLayoutBinding computeBinding(std::uint32_t binding, vk::DescriptorType type);

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

}  // namespace vkrt
