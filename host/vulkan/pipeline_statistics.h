// What a driver's compiler reports of a pipeline it built (VK_KHR_pipeline_executable_properties):
// registers, spills, scratch, occupancy. RADV reports all of these; NVIDIA some; lavapipe nothing.
// The pipeline must have been created with vk::PipelineCreateFlagBits::eCaptureStatisticsKHR on
// a context with statisticsEnabled().
#pragma once

#include <string>
#include <vector>

#include <vulkan/vulkan_raii.hpp>

#include "context.h"

namespace vkrt {

struct ExecutableStatistics {
    std::string name;  // the driver's name for the executable ("Compute Shader")
    struct Value {
        std::string name;  // as the driver spells it: "VGPRs", "Spilled VGPRs", "Scratch size", ...
        double value = 0.0;
    };
    std::vector<Value> values;
    // The named statistic, or -1 when the driver does not report it.
    double get(const std::string& statistic) const;
};

std::vector<ExecutableStatistics> pipelineStatistics(const Context& context, vk::Pipeline pipeline);

}  // namespace vkrt
