// The failures of the Vulkan plumbing that callers treat differently from a plain std::runtime_error.
#pragma once

#include <stdexcept>
#include <string>

namespace vkrt {

// No usable Vulkan: the loader is missing, no device supports Vulkan 1.2 compute, or device
// creation failed. The CLI catches this and renders with the CPU reference instead.
class VulkanUnavailable : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A scene buffer is larger than a device limit (maxStorageBufferRange, maxTexelBufferElements,
// maxMemoryAllocationSize, a memory heap). The message names the limit, the buffer and both sizes.
class DeviceLimitExceeded : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// GLSL that glslang rejects; the message carries glslang's "file:line: error" lines.
class ShaderCompileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace vkrt
