// Turns the kernel's RenderStatus (device_host.h) into an error a user can act on.
#pragma once

#include <cstdint>

#include "device_host.h"
#include "kernel_error.h"

namespace vkrt {

// Throws GpuKernelError when a STATUS_* flag is set, naming the flag's meaning, the first
// offending pixel (x, y) and sample when the kernel recorded them, and what to reduce.
// `loopLimiter`: the device is lavapipe before Mesa 25 (DeviceInfo::loopLimiter), whose silent
// loop limit the message then explains; on other drivers a cut-off loop is not expected and the
// message says so instead of blaming lavapipe.
void throwIfKernelFailed(const gpu::RenderStatus& status, std::uint32_t imageWidth, bool loopLimiter);

}  // namespace vkrt
