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

    // The device's own time for the last run(): from a timestamp written before the recorded
    // commands to one written after them (vkCmdWriteTimestamp), so submission and fence latency
    // are not in it. Negative when the queue cannot write timestamps (timestampValidBits 0).
    double lastDeviceSeconds() const { return lastDeviceSeconds_; }

private:
    const Context& context_;
    vk::raii::CommandPool pool_;
    vk::raii::CommandBuffer commands_;
    vk::raii::Fence fence_;
    vk::raii::QueryPool timestamps_ = nullptr;  // two queries; null without timestamp support
    double lastDeviceSeconds_ = -1.0;
};

// A memory barrier making compute-shader writes visible to later compute reads and writes
// (successive sample passes add to the same pixels).
void computeToComputeBarrier(const vk::raii::CommandBuffer& commands);
// The same, and the writes also visible to a later vkCmdDispatchIndirect's read of its arguments
// (kernels that size the next dispatch).
void computeToIndirectBarrier(const vk::raii::CommandBuffer& commands);
// Compute-shader writes -> host reads after the fence (results read through a mapping).
void computeToHostBarrier(const vk::raii::CommandBuffer& commands);

}  // namespace vkrt
