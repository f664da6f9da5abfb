// The Vulkan instance (and, on request, the validation layer with a messenger that records every
// message it sends).
#pragma once

#include <vector>

#include <vulkan/vulkan_raii.hpp>

#include "device_list.h"
#include "validation_log.h"

namespace vkrt {

class VulkanInstance {
public:
    // log != nullptr enables VK_LAYER_KHRONOS_validation (with synchronization validation) and
    // records its messages there; the log must outlive the instance.
    // Throws VulkanUnavailable when the loader or a Vulkan 1.2 instance is not available, and
    // std::runtime_error when validation is asked for but the layer is not installed.
    explicit VulkanInstance(ValidationLog* log);

    const vk::raii::Instance& instance() const { return instance_; }
    std::vector<vk::raii::PhysicalDevice> physicalDevices() const;

private:
    vk::raii::Context context_;
    vk::raii::Instance instance_ = nullptr;
    vk::raii::DebugUtilsMessengerEXT messenger_ = nullptr;
};

// What listDevices reports for one device.
DeviceInfo describePhysicalDevice(const vk::raii::PhysicalDevice& device, int index);

// The first queue family with compute support, or -1.
int computeQueueFamily(const vk::raii::PhysicalDevice& device);

}  // namespace vkrt
