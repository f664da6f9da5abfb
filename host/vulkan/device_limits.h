// The device limits a scene buffer must fit, checked before anything is allocated so that a scene
// too large for the device is refused with an error that names the limit, the buffer and both
// sizes (instead of a driver error, a crash or a silently truncated binding).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "device_list.h"

namespace vkrt {

enum class BufferKind {
    Storage,       // SSBO: maxStorageBufferRange
    StorageTexel,  // read-only storage texel buffer (imageLoad): maxTexelBufferElements (texels, not bytes)
    Uniform,       // UBO: maxUniformBufferRange
    Plain          // not bound to a shader (staging, readback): allocation size only
};

struct BufferLimits {
    std::uint64_t maxStorageBufferRange = 0;
    std::uint64_t maxTexelBufferElements = 0;
    std::uint64_t maxUniformBufferRange = 0;
    std::uint64_t maxMemoryAllocationSize = 0;
    std::uint64_t heapBytes = 0;  // the device-local heap all scene buffers share
    std::string capNote;          // set when a test override lowered the limits, quoted in errors
};

BufferLimits limitsOf(const DeviceInfo& device);

// Lowers every per-buffer limit to at most maxBytes (texel elements to maxBytes / 16), for tests
// of both sides of a limit without a multi-GiB scene. The heap size is not capped.
BufferLimits capLimits(BufferLimits limits, std::uint64_t maxBytes, std::string note);

// VKRT_MAX_BUFFER_BYTES from the environment, if set; throws std::invalid_argument for a value
// that is not a positive integer.
std::optional<std::uint64_t> maxBufferBytesFromEnvironment();

// Throws DeviceLimitExceeded naming the limit, the buffer and both sizes.
// texelBytes: the size of one texel of a StorageTexel buffer (16 for RGBA32UI).
void checkBufferFits(const BufferLimits& limits, std::string_view buffer, BufferKind kind, std::uint64_t bytes,
                     std::uint64_t texelBytes = 16);

// All scene buffers together must fit the device-local heap.
void checkTotalFits(const BufferLimits& limits, std::uint64_t totalBytes);

// "200.0 MiB (209715200 bytes)"
std::string formatBytes(std::uint64_t bytes);

}  // namespace vkrt
