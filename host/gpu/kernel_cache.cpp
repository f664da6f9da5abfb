#include "kernel_cache.h"

#include <chrono>
#include <iostream>

namespace vkrt {

namespace {

vk::PipelineCacheCreateInfo cacheInfo(const PipelineCacheFile& file) {
    vk::PipelineCacheCreateInfo info;
    info.initialDataSize = file.data.size();
    info.pInitialData = file.data.empty() ? nullptr : file.data.data();
    return info;
}

}  // namespace

std::vector<SpecConstant> kernelConstants(const FeatureSet& features, std::uint32_t samplesPerDispatch, const DeviceInfo& device) {
    auto values = features.specializationValues(samplesPerDispatch);
    values[gpu::SPEC_UNIFORM_INDEX_FROM_GROUPS] = device.lavapipe ? 1u : 0u;  // a device's, not a scene's
    std::vector<SpecConstant> constants;
    for (std::uint32_t id = 0; id < values.size(); ++id) constants.push_back({id, values[id]});
    return constants;
}

KernelCache::KernelCache(const Context& context, const KernelLayout& layout, const KernelSource& source,
                         const std::vector<std::uint32_t>& spirv)
    : context_(context), layout_(layout), modules_(context, source, spirv),
      file_(openPipelineCacheFile(context.info())), cache_(context.device(), cacheInfo(file_)) {
    for (const std::string& note : file_.notes) std::cerr << "vkrt: note: " << note << "\n";
}

KernelCache::~KernelCache() {
    try {
        save();
    } catch (const std::exception& e) {  // a cache that cannot be written costs the next run a compile, nothing more
        std::cerr << "vkrt: note: pipeline cache not written: " << e.what() << "\n";
    }
}

void KernelCache::save() {
    if (file_.path.empty()) return;
    const std::size_t before = file_.notes.size();
    savePipelineCacheFile(file_, cache_.getData());
    for (std::size_t i = before; i < file_.notes.size(); ++i) std::cerr << "vkrt: note: " << file_.notes[i] << "\n";
}

const vk::raii::Pipeline& KernelCache::pipeline(const FeatureSet& features, std::uint32_t samplesPerDispatch,
                                                double* creationSeconds) {
    if (creationSeconds) *creationSeconds = 0.0;
    const auto key = std::make_pair(features, samplesPerDispatch);
    if (auto found = pipelines_.find(key); found != pipelines_.end()) return found->second;

    const auto start = std::chrono::steady_clock::now();
    const std::vector<SpecConstant> constants = kernelConstants(features, samplesPerDispatch, context_.info());
    const vk::ShaderModule module = *modules_.module(features.wavefrontStage);
    vk::raii::Pipeline created = makeComputePipeline(context_, &cache_, layout_.pipelineLayout(), module, constants,
                                                     vk::PipelineCreateFlagBits::eDispatchBase);
    if (creationSeconds) *creationSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return pipelines_.emplace(key, std::move(created)).first->second;
}

}  // namespace vkrt
