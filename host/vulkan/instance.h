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
    // std::runtime_error when validation is asked for but the layer is not installed, unless
    // validationMayBeAbsent(): then it says so on stderr and runs without.
    explicit VulkanInstance(ValidationLog* log);

    // Whether the validation layer is on (asked for, and present or required).
    bool validating() const { return validating_; }

    const vk::raii::Instance& instance() const { return instance_; }
    std::vector<vk::raii::PhysicalDevice> physicalDevices() const;

private:
    vk::raii::Context context_;
    vk::raii::Instance instance_ = nullptr;
    vk::raii::DebugUtilsMessengerEXT messenger_ = nullptr;
    bool validating_ = false;
};

// VKRT_VALIDATION=if-present: validation asked for (--validate, the tests) runs only where the
// layer is installed. Unset, a missing layer is an error: here and in CI, where setup.sh installs
// it, a test must never pass because validation silently did not run.
bool validationMayBeAbsent();

// What listDevices reports for one device.
DeviceInfo describePhysicalDevice(const vk::raii::PhysicalDevice& device, int index);

// A compute-only queue family when the device has one, else the first with compute; -1 if none.
int computeQueueFamily(const vk::raii::PhysicalDevice& device);

}  // namespace vkrt
