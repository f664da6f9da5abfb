#include "compute_pipeline.h"

#include <array>

#include "device_host.h"

namespace vkrt {

vk::raii::ShaderModule makeShaderModule(const Context& context, std::span<const std::uint32_t> spirv) {
    vk::ShaderModuleCreateInfo info({}, spirv.size_bytes(), spirv.data());
    return vk::raii::ShaderModule(context.device(), info);
}

vk::raii::Pipeline makeComputePipeline(const Context& context, const vk::raii::PipelineCache* cache,
                                       vk::PipelineLayout layout, vk::ShaderModule module,
                                       std::span<const SpecConstant> constants, vk::PipelineCreateFlags flags) {
    std::vector<vk::SpecializationMapEntry> entries;
    std::vector<std::uint32_t> data;
    for (const SpecConstant& c : constants) {
        entries.emplace_back(c.id, static_cast<std::uint32_t>(data.size() * sizeof(std::uint32_t)), sizeof(std::uint32_t));
        data.push_back(c.value);
    }
    vk::SpecializationInfo specialization;
    specialization.setMapEntries(entries);
    specialization.setData<std::uint32_t>(data);
    vk::PipelineShaderStageCreateInfo stage({}, vk::ShaderStageFlagBits::eCompute, module, "main",
                                            entries.empty() ? nullptr : &specialization);
    vk::ComputePipelineCreateInfo info(flags, stage, layout);
    return vk::raii::Pipeline(context.device(), cache ? vk::Optional<const vk::raii::PipelineCache>(*cache) : nullptr, info);
}

namespace {

vk::raii::DescriptorSetLayout makeSetLayout(const Context& context) {
    using T = vk::DescriptorType;
    const auto compute = vk::ShaderStageFlagBits::eCompute;
    const std::array bindings = {
        vk::DescriptorSetLayoutBinding(gpu::BINDING_NODES, T::eUniformTexelBuffer, 1, compute),
        vk::DescriptorSetLayoutBinding(gpu::BINDING_PRIMS, T::eUniformTexelBuffer, 1, compute),
        vk::DescriptorSetLayoutBinding(gpu::BINDING_PRIM_INFO, T::eStorageBuffer, 1, compute),
        vk::DescriptorSetLayoutBinding(gpu::BINDING_VERTEX_ATTRIBS, T::eStorageBuffer, 1, compute),
        vk::DescriptorSetLayoutBinding(gpu::BINDING_INSTANCES, T::eStorageBuffer, 1, compute),
        vk::DescriptorSetLayoutBinding(gpu::BINDING_SHADERS, T::eStorageBuffer, 1, compute),
        vk::DescriptorSetLayoutBinding(gpu::BINDING_LIGHTS, T::eStorageBuffer, 1, compute),
        vk::DescriptorSetLayoutBinding(gpu::BINDING_TEXTURES, T::eStorageBuffer, 1, compute),
        vk::DescriptorSetLayoutBinding(gpu::BINDING_TEXELS, T::eStorageBuffer, 1, compute),
        vk::DescriptorSetLayoutBinding(gpu::BINDING_FRAME, T::eUniformBuffer, 1, compute),
        vk::DescriptorSetLayoutBinding(gpu::BINDING_ACCUM, T::eStorageBuffer, 1, compute),
        vk::DescriptorSetLayoutBinding(gpu::BINDING_STATUS, T::eStorageBuffer, 1, compute),
    };
    return vk::raii::DescriptorSetLayout(context.device(), vk::DescriptorSetLayoutCreateInfo({}, bindings));
}

vk::raii::PipelineLayout makePipelineLayout(const Context& context, const vk::raii::DescriptorSetLayout& setLayout) {
    const vk::PushConstantRange push(vk::ShaderStageFlagBits::eCompute, 0, sizeof(gpu::PassParams));
    const vk::DescriptorSetLayout layouts[] = {*setLayout};
    return vk::raii::PipelineLayout(context.device(), vk::PipelineLayoutCreateInfo({}, layouts, push));
}

}  // namespace

RenderLayout::RenderLayout(const Context& context)
    : setLayout_(makeSetLayout(context)), pipelineLayout_(makePipelineLayout(context, setLayout_)) {}

}  // namespace vkrt
