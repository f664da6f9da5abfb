// A VkBuffer with its own memory allocation, and the moves of data in and out of it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include <vulkan/vulkan_raii.hpp>

#include "commands.h"
#include "context.h"

namespace vkrt {

enum class MemoryUse {
    Device,   // read or written by kernels; device-local (mapped too when the context maps it)
    Staging,  // host writes, the device copies from it
    Readback, // the device copies into it, the host reads (cached when the device offers it)
    Shared    // small buffers both sides touch every submission (render status): always mapped
};

class Buffer {
public:
    // size > 0. Allocates dedicated memory (vkrt has a dozen buffers per scene, far below
    // maxMemoryAllocationCount, so no sub-allocator is needed).
    Buffer(const Context& context, std::string name, vk::DeviceSize size, vk::BufferUsageFlags usage, MemoryUse use);

    vk::Buffer handle() const { return *buffer_; }
    vk::DeviceSize size() const { return size_; }
    const std::string& name() const { return name_; }
    // Host address of the whole buffer, or nullptr when it is not host-visible.
    std::byte* mapped() const { return mapped_; }

private:
    std::string name_;
    vk::DeviceSize size_;
    vk::raii::Buffer buffer_;
    vk::raii::DeviceMemory memory_ = nullptr;
    std::byte* mapped_ = nullptr;
};

// A typed view of a buffer for `uimageBuffer` imageLoad reads: RGBA32UI texels (16 bytes), or
// R32UI (4 bytes, the packed RGBA8 texture texels).
vk::raii::BufferView makeTexelView(const Context& context, const Buffer& buffer, std::uint64_t texelBytes = 16);

// The size to give a texel buffer of `bytes` (a multiple of 16): a few zero texels more, so
// that lavapipe compiles a kernel once per process instead of once per scene. llvmpipe (Mesa
// 22.3) keys its compiled kernels on each bound texel buffer's "power-of-two width" and on a
// "level zero only" bit that, for buffers, aliases bits 8-15 of the view's byte size; sizes
// that are not powers of two and have a non-zero byte 1 give every scene the same key.
std::uint64_t stableTexelBufferBytes(std::uint64_t bytes);

// The index of a memory type allowed by `typeBits` with all of `required`, preferring one with
// all of `preferred`; throws std::runtime_error naming the buffer when there is none.
std::uint32_t chooseMemoryType(const vk::PhysicalDeviceMemoryProperties& memory, std::uint32_t typeBits,
                               vk::MemoryPropertyFlags required, vk::MemoryPropertyFlags preferred,
                               const std::string& buffer);

// Moves bytes between the host and buffers: through the mapping when the buffer has one,
// otherwise through a temporary staging buffer and a copy on the device.
class Transfers {
public:
    Transfers(const Context& context, CommandRunner& runner) : context_(context), runner_(runner) {}

    void upload(const Buffer& destination, std::span<const std::byte> data);
    // Several uploads through one staging buffer and one submission per kStagingBatchBytes (a
    // scene's dozen tables: one wait for the device instead of a dozen). Each buffer's bytes as
    // upload() would write them.
    struct Upload {
        const Buffer* destination;
        std::span<const std::byte> data;
        std::uint64_t bytes = 0;  // bytes written: data, then zeros up to this (0: data.size())
    };
    void uploadAll(std::span<const Upload> uploads);
    static constexpr std::uint64_t kStagingBatchBytes = std::uint64_t(256) << 20;
    void download(const Buffer& source, std::span<std::byte> out);
    void zero(const Buffer& buffer);

private:
    const Context& context_;
    CommandRunner& runner_;
};

}  // namespace vkrt
