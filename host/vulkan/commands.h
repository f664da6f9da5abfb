// Records one command buffer, submits it and waits for it with a fence and a timeout.
#pragma once

#include <chrono>
#include <functional>

#include <vulkan/vulkan_raii.hpp>

#include "context.h"

namespace vkrt {

class CommandRunner {
public:
    explicit CommandRunner(const Context& context);

    // Records `record` into the command buffer, submits it and blocks until the device has
    // finished it. Throws std::runtime_error when it does not finish within `timeout` (then the
    // device is probably hung: the message says so), vk::SystemError on device loss.
    // Returns the wall-clock seconds from submission to completion.
    double run(const std::function<void(const vk::raii::CommandBuffer&)>& record,
               std::chrono::milliseconds timeout = std::chrono::seconds(120));

private:
    const Context& context_;
    vk::raii::CommandPool pool_;
    vk::raii::CommandBuffer commands_;
    vk::raii::Fence fence_;
};

// A memory barrier making compute-shader writes visible to later compute reads and writes
// (successive sample passes add to the same pixels).
void computeToComputeBarrier(const vk::raii::CommandBuffer& commands);
// Compute-shader writes -> host reads after the fence (results read through a mapping).
void computeToHostBarrier(const vk::raii::CommandBuffer& commands);

}  // namespace vkrt
