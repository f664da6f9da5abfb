#include "device_choice.h"

namespace vkrt {

AutoDevice chooseAutoDevice(const std::vector<DeviceInfo>& devices) {
    std::string cpuDevices;
    int usable = 0;
    for (const DeviceInfo& d : devices) {
        if (!d.usable) continue;
        if (d.type != "cpu") return {};
        cpuDevices += (usable++ == 0 ? "" : ", ") + d.name;
    }
    if (usable == 0) return {};
    const bool one = usable == 1;
    return {true, "rendering on the CPU reference: the only Vulkan " + std::string(one ? "device, " : "devices, ") + cpuDevices +
                      (one ? ", runs on the CPU and renders" : ", run on the CPU and render") +
                      " slower than the reference (--device gpu renders on " + (one ? "it" : "them") + ")"};
}

}  // namespace vkrt
