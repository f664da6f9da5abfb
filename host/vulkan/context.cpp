#include "context.h"

#include <algorithm>
#include <cstdio>

#include "vulkan_errors.h"

namespace vkrt {

namespace {

std::shared_ptr<ValidationLog> makeLog(bool validation) {
    return validation ? std::make_shared<ValidationLog>() : nullptr;
}

// True when a memory type is device-local and host-visible/coherent (every type on a CPU
// device, all memory of an integrated GPU): then mapping beats a staging copy.
bool deviceLocalIsMappable(const vk::PhysicalDeviceMemoryProperties& memory) {
    const auto wanted = vk::MemoryPropertyFlagBits::eDeviceLocal | vk::MemoryPropertyFlagBits::eHostVisible |
                        vk::MemoryPropertyFlagBits::eHostCoherent;
    for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i)
        if ((memory.memoryTypes[i].propertyFlags & wanted) == wanted) return true;
    return false;
}

}  // namespace

Context::Context(const ContextOptions& options) : log_(makeLog(options.validation)), instance_(log_.get()) {
    auto physical = instance_.physicalDevices();
    std::vector<DeviceInfo> devices;
    for (std::size_t i = 0; i < physical.size(); ++i) devices.push_back(describePhysicalDevice(physical[i], static_cast<int>(i)));

    // A driver may list a device and then fail to open it. With fallBack (--device auto) the next
    // one is tried and stderr says so; without it (--device gpu) the best device must open: a user
    // who asked for the GPU must not get lavapipe silently.
    std::vector<int> candidates;
    if (options.compileOnly) {
        // A compiler's verdict is wanted, not a render: a compile-only device (by --gpu, or the
        // first there is) before the usable ones.
        for (std::size_t i = 0; i < devices.size(); ++i)
            if (devices[i].compileOnly && (options.gpu < 0 || options.gpu == static_cast<int>(i))) candidates.push_back(static_cast<int>(i));
    }
    if (candidates.empty()) candidates = deviceCandidates(devices, options.gpu);
    std::string failures;
    for (const int candidate : candidates) {
        if (!failures.empty() && !options.fallBack) break;
        try {
            openDevice(std::move(physical[candidate]), devices[candidate], options.compileOnly);
            if (!failures.empty())
                std::fprintf(stderr, "note: could not open a Vulkan device (%s ); using %s\n", failures.c_str(),
                             devices[candidate].name.c_str());
            break;
        } catch (const vk::SystemError& e) {
            failures += " " + devices[candidate].name + ": " + e.what() + ";";
        }
    }
    if (!*device_) throw VulkanUnavailable("cannot create a Vulkan device:" + failures);

    limits_ = limitsOf(info_);
    std::optional<std::uint64_t> cap = options.maxBufferBytes;
    std::string note = "limited for testing to " + std::to_string(cap.value_or(0)) + " bytes";
    if (const auto env = maxBufferBytesFromEnvironment(); env && (!cap || *env < *cap)) {
        cap = env;
        note = "limited by VKRT_MAX_BUFFER_BYTES=" + std::to_string(*env);
    }
    if (cap) limits_ = capLimits(limits_, *cap, note);

    // The "cpu" device type with mappable device-local memory is lavapipe's case; integrated GPUs
    // would also qualify, but staying with staging there keeps one well-tested path per kind.
    mapsDeviceMemory_ = !options.forceStaging && info_.type == "cpu" && deviceLocalIsMappable(memory_);
}

void Context::openDevice(vk::raii::PhysicalDevice physical, const DeviceInfo& info, bool compileOnly) {
    const auto family = static_cast<std::uint32_t>(computeQueueFamily(physical));
    const float priority = 1.0f;
    vk::DeviceQueueCreateInfo queueInfo({}, family, 1, &priority);
    vk::DeviceCreateInfo create({}, queueInfo);
    vk::PhysicalDevicePipelineExecutablePropertiesFeaturesKHR statistics(VK_TRUE);
    const char* statisticsExtension = VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME;
    statisticsEnabled_ = compileOnly && info.pipelineStatistics;
    if (statisticsEnabled_) {
        create.setPEnabledExtensionNames(statisticsExtension);
        create.setPNext(&statistics);
    }
    device_ = vk::raii::Device(physical, create);  // unchanged if this throws
    queue_ = vk::raii::Queue(device_, family, 0);
    info_ = info;
    queueFamily_ = family;
    memory_ = physical.getMemoryProperties();
}

Context::~Context() {
    // Work still queued when the owner unwinds (an exception mid-render) must finish before its
    // buffers and pipelines are destroyed.
    try {
        // Nothing ever runs on a compile-only device, and RADV's null device crashes in vkDeviceWaitIdle.
        if (*device_ && !info_.compileOnly) device_.waitIdle();
    } catch (const vk::SystemError&) {
        // Device lost: nothing is running any more, destruction may proceed.
    }
}

}  // namespace vkrt
