// One kernel, specialised per feature set and samples per dispatch: pipelines are created on first use and kept
// (lavapipe's LLVM compile takes ~0.05 s or more per variant), plus a VkPipelineCache, kept on disk
// between processes (pipeline_cache_file.h), so drivers that cache compiled code reuse it across
// variants and runs.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <vulkan/vulkan_raii.hpp>

#include "compute_pipeline.h"
#include "context.h"
#include "feature_set.h"
#include "kernel_modules.h"
#include "pipeline_cache_file.h"

namespace vkrt {

// The render kernel's specialization constants for `features` at `samplesPerDispatch`, on `device`
// (one constant is the device's, not the scene's).
std::vector<SpecConstant> kernelConstants(const FeatureSet& features, std::uint32_t samplesPerDispatch, const DeviceInfo& device);

class KernelCache {
public:
    // `spirv`: the kernel `source` names (the megakernel's, or trace_rays'); the wavefront stages'
    // modules come from where `source` says, on first use (kernel_modules.h).
    KernelCache(const Context& context, const KernelLayout& layout, const KernelSource& source, const std::vector<std::uint32_t>& spirv);

    // The pipeline for `features` (its wavefrontStage picks the module) computing `samplesPerDispatch` samples per invocation
    // (sample_batching.h); *creationSeconds gets the time spent creating it (0 if cached).
    const vk::raii::Pipeline& pipeline(const FeatureSet& features, std::uint32_t samplesPerDispatch,
                                       double* creationSeconds = nullptr);
    std::size_t size() const { return pipelines_.size(); }
    // The cache file's notes (an ignored or unwritable file), for the caller to show.
    const std::vector<std::string>& notes() const { return file_.notes; }

    // Writes the pipeline cache's data to its file (also done on destruction).
    void save();
    ~KernelCache();

private:
    const Context& context_;
    const KernelLayout& layout_;
    KernelModules modules_;
    PipelineCacheFile file_;
    vk::raii::PipelineCache cache_;
    std::map<std::pair<FeatureSet, std::uint32_t>, vk::raii::Pipeline> pipelines_;
};

}  // namespace vkrt
