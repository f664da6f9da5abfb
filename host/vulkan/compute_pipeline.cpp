#include "compute_pipeline.h"

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

vk::DescriptorSetLayoutBinding computeBinding(std::uint32_t binding, vk::DescriptorType type) {
    return vk::DescriptorSetLayoutBinding(binding, type, 1, vk::ShaderStageFlagBits::eCompute);
}

namespace {

vk::raii::PipelineLayout makePipelineLayout(const Context& context, const vk::raii::DescriptorSetLayout& setLayout,
                                            std::uint32_t pushBytes) {
    const vk::PushConstantRange push(vk::ShaderStageFlagBits::eCompute, 0, pushBytes);
    const vk::DescriptorSetLayout layouts[] = {*setLayout};
    return vk::raii::PipelineLayout(context.device(), vk::PipelineLayoutCreateInfo({}, layouts, push));
}

}  // namespace

KernelLayout::KernelLayout(const Context& context, std::span<const vk::DescriptorSetLayoutBinding> bindings, std::uint32_t pushBytes)
    : setLayout_(context.device(), vk::DescriptorSetLayoutCreateInfo({}, bindings)),
      pipelineLayout_(makePipelineLayout(context, setLayout_, pushBytes)) {}

}  // namespace vkrt
