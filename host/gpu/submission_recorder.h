// Records one submission of the render: a run of workgroups of a tile for a run of sample passes,
// one dispatch per pass (each pass k samples: sample_batching.h), with the barriers that keep a
// pixel's samples accumulating in order.
// The pipeline must be created with VK_PIPELINE_CREATE_DISPATCH_BASE_BIT.
#pragma once

#include <vulkan/vulkan_raii.hpp>

#include "device_host.h"
#include "sample_batching.h"
#include "tile_planner.h"

namespace vkrt {

// One workgroup over an empty tile: computes nothing, but lavapipe JIT-compiles the pipeline for
// the bound resources at its first dispatch, so this keeps compile time out of the first
// measured submission.
void recordWarmUp(const vk::raii::CommandBuffer& commands, vk::Pipeline pipeline, vk::PipelineLayout layout,
                  vk::DescriptorSet set);

// The submission's sample passes are TilePlanner's passes over `batching.passes()`.
void recordSubmission(const vk::raii::CommandBuffer& commands, vk::Pipeline pipeline, vk::PipelineLayout layout,
                      vk::DescriptorSet set, const Submission& submission, const SampleBatching& batching);

// Adaptive sampling (render.comp's ADAPTIVE kernel): one dispatch over work-list entries
// [firstEntry, firstEntry + entries), each computing its pixel's samples from samplesDone into its
// range, at most k.
void recordAdaptivePass(const vk::raii::CommandBuffer& commands, vk::Pipeline pipeline, vk::PipelineLayout layout,
                        vk::DescriptorSet set, std::uint32_t firstEntry, std::uint32_t entries, std::uint32_t samplesDone,
                        std::uint32_t k);

}  // namespace vkrt
