// Records one submission of the render: a run of workgroups of a tile for a run of sample passes,
// one dispatch per pass, with the barriers that keep a pixel's samples accumulating in order.
// The pipeline must be created with VK_PIPELINE_CREATE_DISPATCH_BASE_BIT.
#pragma once

#include <vulkan/vulkan_raii.hpp>

#include "device_host.h"
#include "tile_planner.h"

namespace vkrt {

// PassParams for sample `sample` of `tile` (device_host.h; render.comp's block mapping).
gpu::PassParams passParams(const TileRect& tile, std::uint32_t sample);

// One workgroup over an empty tile: computes nothing, but lavapipe JIT-compiles the pipeline for
// the bound resources at its first dispatch, so this keeps compile time out of the first
// measured submission.
void recordWarmUp(const vk::raii::CommandBuffer& commands, vk::Pipeline pipeline, vk::PipelineLayout layout,
                  vk::DescriptorSet set);

void recordSubmission(const vk::raii::CommandBuffer& commands, vk::Pipeline pipeline, vk::PipelineLayout layout,
                      vk::DescriptorSet set, const Submission& submission);

}  // namespace vkrt
