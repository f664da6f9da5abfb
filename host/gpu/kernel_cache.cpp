#include "kernel_cache.h"

#include <chrono>

namespace vkrt {

KernelCache::KernelCache(const Context& context, const KernelLayout& layout, const std::vector<std::uint32_t>& spirv)
    : context_(context), layout_(layout), module_(makeShaderModule(context, spirv)),
      cache_(context.device(), vk::PipelineCacheCreateInfo()) {}

const vk::raii::Pipeline& KernelCache::pipeline(const FeatureSet& features, std::uint32_t samplesPerDispatch,
                                                double* creationSeconds) {
    if (creationSeconds) *creationSeconds = 0.0;
    const auto key = std::make_pair(features, samplesPerDispatch);
    if (auto found = pipelines_.find(key); found != pipelines_.end()) return found->second;

    const auto start = std::chrono::steady_clock::now();
    const auto values = features.specializationValues(samplesPerDispatch);
    std::vector<SpecConstant> constants;
    for (std::uint32_t id = 0; id < values.size(); ++id) constants.push_back({id, values[id]});
    vk::raii::Pipeline created = makeComputePipeline(context_, &cache_, layout_.pipelineLayout(), *module_, constants,
                                                     vk::PipelineCreateFlagBits::eDispatchBase);
    if (creationSeconds) *creationSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return pipelines_.emplace(key, std::move(created)).first->second;
}

}  // namespace vkrt
