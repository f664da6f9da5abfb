// --device auto: which renderer this machine's Vulkan devices call for. A Vulkan driver that runs
// on the CPU (Mesa's lavapipe/llvmpipe) renders slower than the CPU reference on the same cores:
// one sphere took 1.5 s on lavapipe against 0.2 s with --device cpu, dragons00 8.6 s against 3.5 s
// (issue 39, on the 2-core development machine). So auto takes a GPU when one is usable and the CPU
// reference when every usable device is a CPU implementation. --device gpu and --gpu N still run
// on any Vulkan device, lavapipe included; compare and sweep always use Vulkan for their GPU side.
#pragma once

#include <string>
#include <vector>

#include "device_list.h"

namespace vkrt {

struct AutoDevice {
    bool cpuReference = false;  // render on the CPU reference instead of Vulkan
    std::string reason;         // when cpuReference: why, naming the devices (the note vkrt prints)
};

// Vulkan when any usable device is not of type "cpu" (a discrete, integrated or virtual GPU, or
// one Vulkan calls "other"). With no usable device at all it also answers Vulkan: opening one then
// fails with the loader's or the driver's own reason, which --device auto prints as it falls back.
AutoDevice chooseAutoDevice(const std::vector<DeviceInfo>& devices);

}  // namespace vkrt
