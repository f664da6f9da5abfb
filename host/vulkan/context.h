// A compute-only Vulkan 1.2 device: instance, chosen physical device, logical device and one
// compute queue. No window, no surface.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>

#include <vulkan/vulkan_raii.hpp>

#include "device_limits.h"
#include "device_list.h"
#include "instance.h"
#include "validation_log.h"

namespace vkrt {

struct ContextOptions {
    int gpu = -1;             // index from listDevices() (--gpu N); -1 chooses (discrete first)
    bool validation = false;  // VK_LAYER_KHRONOS_validation; messages go to validationLog()
    // When the chosen device fails to open, try the next best (saying so on stderr); false: throw.
    bool fallBack = true;
    // Caps every per-buffer limit (tests of both sides of a limit); VKRT_MAX_BUFFER_BYTES in the
    // environment does the same, and the smaller of the two wins.
    std::optional<std::uint64_t> maxBufferBytes;
    // Move data through staging buffers even when device memory can be mapped (tests of the
    // path discrete GPUs take).
    bool forceStaging = false;
    // Compile kernels, never run them (vkrt-bench gpu kernels): compile-only devices (RADV's null
    // device, DeviceInfo::compileOnly) may be opened, and are preferred; pipeline executable
    // statistics (VK_KHR_pipeline_executable_properties) are enabled where the device offers them.
    bool compileOnly = false;
};

// Not copyable or movable: the validation messenger points at the log.
class Context {
public:
    // Throws VulkanUnavailable when no usable device exists.
    explicit Context(const ContextOptions& options = {});
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    const vk::raii::Device& device() const { return device_; }
    const vk::raii::Queue& queue() const { return queue_; }
    std::uint32_t queueFamily() const { return queueFamily_; }
    const DeviceInfo& info() const { return info_; }
    const BufferLimits& limits() const { return limits_; }
    const vk::PhysicalDeviceMemoryProperties& memoryProperties() const { return memory_; }
    // Device-local buffers are written and read through a mapping (CPU devices and unified
    // memory), instead of staging copies.
    bool mapsDeviceMemory() const { return mapsDeviceMemory_; }
    // nullptr when validation is off. Shared so that a test can still read the messages sent
    // while this context is destroyed.
    std::shared_ptr<const ValidationLog> validationLog() const { return log_; }
    // Whether the validation layer runs (it may be absent under VKRT_VALIDATION=if-present).
    bool validating() const { return instance_.validating(); }
    // Pipelines may be created with eCaptureStatisticsKHR and queried (pipeline_statistics.h).
    bool statisticsEnabled() const { return statisticsEnabled_; }

private:
    void openDevice(vk::raii::PhysicalDevice physical, const DeviceInfo& info, bool compileOnly);

    std::shared_ptr<ValidationLog> log_;  // declared first: outlives the messenger
    VulkanInstance instance_;
    vk::raii::Device device_ = nullptr;
    vk::raii::Queue queue_ = nullptr;
    std::uint32_t queueFamily_ = 0;
    DeviceInfo info_;
    BufferLimits limits_;
    vk::PhysicalDeviceMemoryProperties memory_;
    bool mapsDeviceMemory_ = false;
    bool statisticsEnabled_ = false;
};

}  // namespace vkrt
