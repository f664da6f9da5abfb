#include "kernel_cache.h"

#include <chrono>

namespace vkrt {

KernelCache::KernelCache(const Context& context, const KernelLayout& layout, const std::vector<std::uint32_t>& spirv)
    : context_(context), layout_(layout), module_(makeShaderModule(context, spirv)),
      cache_(context.device(), vk::PipelineCacheCreateInfo()) {}

const vk::raii::Pipeline& KernelCache::pipeline(const FeatureSet& features, double* creationSeconds) {
    if (creationSeconds) *creationSeconds = 0.0;
    if (auto found = pipelines_.find(features); found != pipelines_.end()) return found->second;

    const auto start = std::chrono::steady_clock::now();
    const auto values = features.specializationValues();
    std::vector<SpecConstant> constants;
    for (std::uint32_t id = 0; id < values.size(); ++id) constants.push_back({id, values[id]});
    vk::raii::Pipeline created = makeComputePipeline(context_, &cache_, layout_.pipelineLayout(), *module_, constants,
                                                     vk::PipelineCreateFlagBits::eDispatchBase);
    if (creationSeconds) *creationSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return pipelines_.emplace(features, std::move(created)).first->second;
}

}  // namespace vkrt
