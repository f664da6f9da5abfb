#include "instance.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "vulkan_errors.h"

namespace vkrt {

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

// Loads libvulkan; vk::raii::Context throws a plain std::runtime_error when it cannot.
vk::raii::Context loadVulkan() {
    try {
        return vk::raii::Context();
    } catch (const std::exception& e) {
        throw VulkanUnavailable(std::string("the Vulkan loader (libvulkan.so.1) cannot be loaded: ") + e.what());
    }
}

const char* severityName(VkDebugUtilsMessageSeverityFlagBitsEXT severity) {
    if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) return "error";
    if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) return "warning";
    if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_INFO_BIT_EXT) return "info";
    return "verbose";
}

VKAPI_ATTR VkBool32 VKAPI_CALL recordMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                             VkDebugUtilsMessageTypeFlagsEXT,
                                             const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    std::string text = std::string("[") + severityName(severity) + "] ";
    if (data->pMessageIdName) text += std::string(data->pMessageIdName) + ": ";
    if (data->pMessage) text += data->pMessage;
    static_cast<ValidationLog*>(user)->record(std::move(text));
    return VK_FALSE;  // never abort the call: the test decides what a message means
}

// Warnings and errors of every kind: a test fails on any of them. Info and verbose messages are
// the loader's and layers' chatter (which libraries were loaded), not findings.
vk::DebugUtilsMessengerCreateInfoEXT messengerInfo(ValidationLog* log) {
    vk::DebugUtilsMessengerCreateInfoEXT info;
    info.messageSeverity = vk::DebugUtilsMessageSeverityFlagBitsEXT::eWarning | vk::DebugUtilsMessageSeverityFlagBitsEXT::eError;
    info.messageType = vk::DebugUtilsMessageTypeFlagBitsEXT::eGeneral | vk::DebugUtilsMessageTypeFlagBitsEXT::eValidation |
                       vk::DebugUtilsMessageTypeFlagBitsEXT::ePerformance;
    info.pfnUserCallback = recordMessage;
    info.pUserData = log;
    return info;
}

bool hasLayer(const vk::raii::Context& context, const char* name) {
    const auto layers = context.enumerateInstanceLayerProperties();
    return std::any_of(layers.begin(), layers.end(), [&](const vk::LayerProperties& l) { return std::strcmp(l.layerName, name) == 0; });
}

bool layerHasExtension(const vk::raii::Context& context, const char* layer, const char* extension) {
    const auto extensions = context.enumerateInstanceExtensionProperties(std::string(layer));
    return std::any_of(extensions.begin(), extensions.end(),
                       [&](const vk::ExtensionProperties& e) { return std::strcmp(e.extensionName, extension) == 0; });
}

}  // namespace

bool validationMayBeAbsent() {
    const char* mode = std::getenv("VKRT_VALIDATION");
    return mode && std::strcmp(mode, "if-present") == 0;
}

VulkanInstance::VulkanInstance(ValidationLog* log) : context_(loadVulkan()) {
    if (context_.enumerateInstanceVersion() < VK_API_VERSION_1_2)
        throw VulkanUnavailable("the Vulkan loader supports only API " + apiVersionString(context_.enumerateInstanceVersion()) +
                                "; vkrt needs Vulkan 1.2");

    vk::ApplicationInfo app("vkrt", 1, "vkrt", 1, VK_API_VERSION_1_2);
    std::vector<const char*> layers;
    std::vector<const char*> extensions;
    vk::DebugUtilsMessengerCreateInfoEXT debugInfo = messengerInfo(log);
    // Synchronization validation catches missing barriers between dispatches and copies, the
    // kind of bug that works on lavapipe (which runs submissions in order) and breaks on a GPU.
    const vk::ValidationFeatureEnableEXT enables[] = {vk::ValidationFeatureEnableEXT::eSynchronizationValidation};
    vk::ValidationFeaturesEXT features;
    features.setEnabledValidationFeatures(enables);

    vk::InstanceCreateInfo info({}, &app);
    if (log && !hasLayer(context_, kValidationLayer)) {
        if (!validationMayBeAbsent())
            throw std::runtime_error(std::string("validation was requested but ") + kValidationLayer +
                                     " is not installed (Debian package vulkan-validationlayers; a bundle carries it, "
                                     "tools/bundle.sh; VKRT_VALIDATION=if-present runs without it)");
        std::fprintf(stderr, "note: %s is not installed: running without validation (VKRT_VALIDATION=if-present)\n",
                     kValidationLayer);
        log = nullptr;
    }
    validating_ = log != nullptr;
    if (log) {
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        // Chained into instance creation too, so messages from vkCreateInstance and
        // vkDestroyInstance are recorded as well.
        info.pNext = &debugInfo;
        if (layerHasExtension(context_, kValidationLayer, VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME)) {
            extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
            debugInfo.pNext = &features;
        }
    }
    info.setPEnabledLayerNames(layers);
    info.setPEnabledExtensionNames(extensions);
    try {
        instance_ = vk::raii::Instance(context_, info);
        if (log) messenger_ = vk::raii::DebugUtilsMessengerEXT(instance_, messengerInfo(log));
    } catch (const vk::IncompatibleDriverError&) {
        throw VulkanUnavailable("no Vulkan 1.2 driver is installed (the loader found no ICD that accepts a Vulkan 1.2 instance)");
    } catch (const vk::SystemError& e) {
        throw VulkanUnavailable(std::string("cannot create a Vulkan 1.2 instance: ") + e.what());
    }
}

std::vector<vk::raii::PhysicalDevice> VulkanInstance::physicalDevices() const {
    try {
        return vk::raii::PhysicalDevices(instance_);
    } catch (const vk::SystemError& e) {
        throw VulkanUnavailable(std::string("cannot enumerate Vulkan devices: ") + e.what());
    }
}

int computeQueueFamily(const vk::raii::PhysicalDevice& device) {
    const auto families = device.getQueueFamilyProperties();
    // A compute-only family first: on a discrete GPU it is the async-compute engine, which the
    // display and graphics work never share; else the first family with compute.
    int any = -1;
    for (std::size_t i = 0; i < families.size(); ++i) {
        const vk::QueueFlags flags = families[i].queueFlags;
        if (!(flags & vk::QueueFlagBits::eCompute)) continue;
        if (!(flags & vk::QueueFlagBits::eGraphics)) return static_cast<int>(i);
        if (any < 0) any = static_cast<int>(i);
    }
    return any;
}

namespace {

std::string typeName(vk::PhysicalDeviceType type) {
    switch (type) {
    case vk::PhysicalDeviceType::eDiscreteGpu: return "discrete";
    case vk::PhysicalDeviceType::eIntegratedGpu: return "integrated";
    case vk::PhysicalDeviceType::eVirtualGpu: return "virtual";
    case vk::PhysicalDeviceType::eCpu: return "cpu";
    default: return "other";
    }
}

}  // namespace

DeviceInfo describePhysicalDevice(const vk::raii::PhysicalDevice& device, int index) {
    DeviceInfo info;
    info.index = index;
    const vk::PhysicalDeviceProperties props = device.getProperties();
    info.name = props.deviceName.data();
    info.type = typeName(props.deviceType);
    info.apiVersion = props.apiVersion;
    info.maxStorageBufferRange = props.limits.maxStorageBufferRange;
    info.maxTexelBufferElements = props.limits.maxTexelBufferElements;
    info.maxUniformBufferRange = props.limits.maxUniformBufferRange;
    info.maxWorkGroupCountX = props.limits.maxComputeWorkGroupCount[0];
    info.vendorId = props.vendorID;
    info.deviceId = props.deviceID;
    info.driverVersion = props.driverVersion;
    for (std::size_t i = 0; i < info.pipelineCacheUuid.size(); ++i) info.pipelineCacheUuid[i] = props.pipelineCacheUUID[i];

    if (props.apiVersion < VK_API_VERSION_1_2) {
        info.driver = "driver version " + std::to_string(props.driverVersion);
        info.unusableReason = "supports only Vulkan " + apiVersionString(props.apiVersion) + "; vkrt needs 1.2";
        return info;
    }
    // Vulkan 1.1/1.2 core property structs (the device supports 1.2, checked above).
    const auto chain = device.getProperties2<vk::PhysicalDeviceProperties2, vk::PhysicalDeviceMaintenance3Properties,
                                             vk::PhysicalDeviceDriverProperties, vk::PhysicalDeviceSubgroupProperties>();
    const auto& driver = chain.get<vk::PhysicalDeviceDriverProperties>();
    info.driver = std::string(driver.driverName.data()) + " (" + driver.driverInfo.data() + ")";
    info.lavapipe = driver.driverID == vk::DriverId::eMesaLlvmpipe;
    // driverInfo reads "Mesa 22.3.6"; a lavapipe that does not say is taken for an old one.
    const std::string mesa = driver.driverInfo.data();
    const std::size_t at = mesa.find("Mesa ");
    info.loopLimiter = info.lavapipe && (at == std::string::npos || std::atoi(mesa.c_str() + at + 5) < 25);
    info.maxMemoryAllocationSize = chain.get<vk::PhysicalDeviceMaintenance3Properties>().maxMemoryAllocationSize;
    info.subgroupSize = chain.get<vk::PhysicalDeviceSubgroupProperties>().subgroupSize;

    const vk::PhysicalDeviceMemoryProperties memory = device.getMemoryProperties();
    for (std::uint32_t h = 0; h < memory.memoryHeapCount; ++h)
        if (memory.memoryHeaps[h].flags & vk::MemoryHeapFlagBits::eDeviceLocal)
            info.deviceLocalHeapBytes = std::max<std::uint64_t>(info.deviceLocalHeapBytes, memory.memoryHeaps[h].size);

    const int family = computeQueueFamily(device);
    if (family < 0) {
        info.unusableReason = "has no compute queue";
        return info;
    }
    const vk::QueueFamilyProperties queues = device.getQueueFamilyProperties()[static_cast<std::size_t>(family)];
    info.queueFamily = static_cast<std::uint32_t>(family);
    info.computeOnlyQueue = !(queues.queueFlags & vk::QueueFlagBits::eGraphics);
    info.timestampValidBits = queues.timestampValidBits;
    info.timestampPeriodNs = props.limits.timestampPeriod;
    for (const vk::ExtensionProperties& e : device.enumerateDeviceExtensionProperties())
        if (std::string(e.extensionName.data()) == VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME) info.pipelineStatistics = true;
    if (info.deviceLocalHeapBytes == 0) {
        info.compileOnly = true;
        info.unusableReason = "has no device memory: it compiles kernels but cannot run them (RADV's null device, "
                              "RADV_FORCE_FAMILY); vkrt-bench gpu kernels reads its compiler's statistics";
        return info;
    }
    info.usable = true;
    return info;
}

}  // namespace vkrt
