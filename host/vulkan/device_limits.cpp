#include "device_limits.h"

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "vulkan_errors.h"

namespace vkrt {

BufferLimits limitsOf(const DeviceInfo& device) {
    BufferLimits limits;
    limits.maxStorageBufferRange = device.maxStorageBufferRange;
    limits.maxTexelBufferElements = device.maxTexelBufferElements;
    limits.maxUniformBufferRange = device.maxUniformBufferRange;
    limits.maxMemoryAllocationSize = device.maxMemoryAllocationSize;
    limits.heapBytes = device.deviceLocalHeapBytes;
    return limits;
}

BufferLimits capLimits(BufferLimits limits, std::uint64_t maxBytes, std::string note) {
    limits.maxStorageBufferRange = std::min(limits.maxStorageBufferRange, maxBytes);
    limits.maxTexelBufferElements = std::min(limits.maxTexelBufferElements, maxBytes / 16);
    limits.maxUniformBufferRange = std::min(limits.maxUniformBufferRange, maxBytes);
    limits.maxMemoryAllocationSize = std::min(limits.maxMemoryAllocationSize, maxBytes);
    limits.capNote = std::move(note);
    return limits;
}

std::optional<std::uint64_t> maxBufferBytesFromEnvironment() {
    const char* value = std::getenv("VKRT_MAX_BUFFER_BYTES");
    if (!value || !*value) return std::nullopt;
    char* end = nullptr;
    const unsigned long long bytes = std::strtoull(value, &end, 10);
    if (*end != '\0' || bytes == 0 || value[0] == '-')
        throw std::invalid_argument(std::string("VKRT_MAX_BUFFER_BYTES=") + value + ": expected a positive number of bytes");
    return bytes;
}

std::string formatBytes(std::uint64_t bytes) {
    std::ostringstream out;
    out.precision(1);
    out << std::fixed << static_cast<double>(bytes) / (1024.0 * 1024.0) << " MiB (" << bytes << " bytes)";
    return out.str();
}

namespace {

[[noreturn]] void refuse(const BufferLimits& limits, std::string_view buffer, const char* limit, const std::string& need,
                         const std::string& have) {
    std::string message = "scene buffer '" + std::string(buffer) + "' needs " + need + " but the device's " + limit + " is " +
                          have;
    if (!limits.capNote.empty()) message += " (" + limits.capNote + ")";
    message += "; render a smaller scene or use a device with a larger limit (--list-devices)";
    throw DeviceLimitExceeded(message);
}

}  // namespace

void checkBufferFits(const BufferLimits& limits, std::string_view buffer, BufferKind kind, std::uint64_t bytes,
                     std::uint64_t texelBytes) {
    switch (kind) {
    case BufferKind::Storage:
        if (bytes > limits.maxStorageBufferRange)
            refuse(limits, buffer, "maxStorageBufferRange", formatBytes(bytes), formatBytes(limits.maxStorageBufferRange));
        break;
    case BufferKind::StorageTexel: {
        const std::uint64_t texels = (bytes + texelBytes - 1) / texelBytes;
        if (texels > limits.maxTexelBufferElements)
            refuse(limits, buffer, "maxTexelBufferElements", std::to_string(texels) + " texels",
                   std::to_string(limits.maxTexelBufferElements) + " texels");
        break;
    }
    case BufferKind::Uniform:
        if (bytes > limits.maxUniformBufferRange)
            refuse(limits, buffer, "maxUniformBufferRange", formatBytes(bytes), formatBytes(limits.maxUniformBufferRange));
        break;
    case BufferKind::Plain:
        break;
    }
    if (bytes > limits.maxMemoryAllocationSize)
        refuse(limits, buffer, "maxMemoryAllocationSize", formatBytes(bytes), formatBytes(limits.maxMemoryAllocationSize));
}

void checkTotalFits(const BufferLimits& limits, std::uint64_t totalBytes) {
    if (totalBytes > limits.heapBytes) {
        std::string message = "the scene's GPU buffers need " + formatBytes(totalBytes) +
                              " together but the device-local memory heap holds " + formatBytes(limits.heapBytes);
        if (!limits.capNote.empty()) message += " (" + limits.capNote + ")";
        throw DeviceLimitExceeded(message + "; render a smaller scene or use a device with more memory (--list-devices)");
    }
}

}  // namespace vkrt
