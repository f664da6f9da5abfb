#include "device_list.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "instance.h"
#include "vulkan_errors.h"

namespace vkrt {

std::vector<DeviceInfo> listDevices() {
    VulkanInstance instance(nullptr);
    std::vector<DeviceInfo> devices;
    const auto physical = instance.physicalDevices();
    for (std::size_t i = 0; i < physical.size(); ++i) devices.push_back(describePhysicalDevice(physical[i], static_cast<int>(i)));
    return devices;
}

std::string apiVersionString(std::uint32_t version) {
    return std::to_string(VK_API_VERSION_MAJOR(version)) + "." + std::to_string(VK_API_VERSION_MINOR(version)) + "." +
           std::to_string(VK_API_VERSION_PATCH(version));
}

namespace {

std::string mib(std::uint64_t bytes) {
    std::ostringstream out;
    out.precision(1);
    out << std::fixed << static_cast<double>(bytes) / (1024.0 * 1024.0) << " MiB";
    return out.str();
}

int typeRank(const std::string& type) {
    if (type == "discrete") return 0;
    if (type == "integrated") return 1;
    if (type == "virtual") return 2;
    if (type == "cpu") return 3;
    return 4;
}

std::string oneLine(const DeviceInfo& d) {
    return std::to_string(d.index) + ": " + d.name + " (" + d.type + ")";
}

}  // namespace

std::string formatDeviceList(const std::vector<DeviceInfo>& devices) {
    if (devices.empty()) return "no Vulkan devices found\n";
    std::ostringstream out;
    for (const DeviceInfo& d : devices) {
        out << oneLine(d) << (d.usable ? "" : "  [unusable: " + d.unusableReason + "]") << "\n"
            << "   driver: " << d.driver << "\n"
            << "   Vulkan " << apiVersionString(d.apiVersion) << ", subgroup size " << d.subgroupSize << "\n"
            << "   maxStorageBufferRange " << mib(d.maxStorageBufferRange) << ", maxTexelBufferElements "
            << d.maxTexelBufferElements << ", maxMemoryAllocationSize " << mib(d.maxMemoryAllocationSize) << "\n"
            << "   device-local heap " << mib(d.deviceLocalHeapBytes) << ", maxComputeWorkGroupCount[0] "
            << d.maxWorkGroupCountX << "\n"
            << "   queue family " << d.queueFamily << (d.computeOnlyQueue ? " (compute only)" : " (graphics and compute)")
            << ", timestamps " << (d.timestampValidBits > 0 ? std::to_string(d.timestampValidBits) + " bits, " +
                                                                  std::to_string(d.timestampPeriodNs) + " ns per tick"
                                                            : std::string("none"))
            << "\n";
    }
    return out.str();
}

int chooseDevice(const std::vector<DeviceInfo>& devices, int requested) {
    if (requested >= 0) {
        if (requested >= static_cast<int>(devices.size())) {
            std::ostringstream message;
            message << "--gpu " << requested << ": there are only " << devices.size() << " Vulkan device(s)";
            for (const DeviceInfo& d : devices) message << "; " << oneLine(d);
            throw std::invalid_argument(message.str());
        }
        const DeviceInfo& d = devices[requested];
        if (!d.usable) {
            std::ostringstream message;
            message << "--gpu " << requested << ": " << d.name << " " << d.unusableReason;
            throw std::invalid_argument(message.str());
        }
        return requested;
    }
    int best = -1;
    for (std::size_t i = 0; i < devices.size(); ++i)
        if (devices[i].usable && (best < 0 || typeRank(devices[i].type) < typeRank(devices[best].type))) best = static_cast<int>(i);
    if (best < 0) {
        std::ostringstream why;
        why << (devices.empty() ? "no Vulkan device was found" : "no Vulkan device is usable:");
        for (const DeviceInfo& d : devices) why << " " << oneLine(d) << " " << d.unusableReason << ";";
        throw VulkanUnavailable(why.str());
    }
    return best;
}

std::vector<int> deviceCandidates(const std::vector<DeviceInfo>& devices, int requested) {
    const int first = chooseDevice(devices, requested);  // validates `requested`, throws if nothing is usable
    if (requested >= 0) return {first};
    std::vector<int> order;
    for (std::size_t i = 0; i < devices.size(); ++i)
        if (devices[i].usable) order.push_back(static_cast<int>(i));
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return typeRank(devices[a].type) < typeRank(devices[b].type); });
    return order;
}

int deviceForLocalRank(const std::vector<DeviceInfo>& devices, int localRank) {
    std::vector<int> best;
    for (const DeviceInfo& d : devices) {
        if (!d.usable) continue;
        if (!best.empty() && typeRank(d.type) > typeRank(devices[best.front()].type)) continue;
        if (!best.empty() && typeRank(d.type) < typeRank(devices[best.front()].type)) best.clear();
        best.push_back(d.index);
    }
    if (best.empty()) return -1;
    return best[static_cast<std::size_t>(std::max(localRank, 0)) % best.size()];
}

}  // namespace vkrt
