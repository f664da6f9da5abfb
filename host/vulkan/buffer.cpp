#include "buffer.h"

#include <algorithm>
#include <cstring>
#include <vector>
#include <stdexcept>

namespace vkrt {

std::uint32_t chooseMemoryType(const vk::PhysicalDeviceMemoryProperties& memory, std::uint32_t typeBits,
                               vk::MemoryPropertyFlags required, vk::MemoryPropertyFlags preferred,
                               const std::string& buffer) {
    int fallback = -1;
    for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
        if (!(typeBits & (1u << i))) continue;
        const vk::MemoryPropertyFlags flags = memory.memoryTypes[i].propertyFlags;
        if ((flags & required) != required) continue;
        if ((flags & preferred) == preferred) return i;
        if (fallback < 0) fallback = static_cast<int>(i);
    }
    if (fallback < 0)
        throw std::runtime_error("buffer '" + buffer + "': the device has no memory type with " + vk::to_string(required));
    return static_cast<std::uint32_t>(fallback);
}

namespace {

struct MemoryChoice {
    vk::MemoryPropertyFlags required;
    vk::MemoryPropertyFlags preferred;
    bool map = false;
};

MemoryChoice memoryChoice(const Context& context, MemoryUse use) {
    using F = vk::MemoryPropertyFlagBits;
    const vk::MemoryPropertyFlags hostCoherent = F::eHostVisible | F::eHostCoherent;
    switch (use) {
    case MemoryUse::Device:
        if (context.mapsDeviceMemory()) return {F::eDeviceLocal | hostCoherent, {}, true};
        return {{}, F::eDeviceLocal, false};
    case MemoryUse::Staging: return {hostCoherent, {}, true};
    case MemoryUse::Readback: return {hostCoherent, F::eHostCached, true};
    case MemoryUse::Shared: return {hostCoherent, F::eDeviceLocal, true};
    }
    return {};
}

vk::raii::Buffer createBuffer(const Context& context, const std::string& name, vk::DeviceSize size, vk::BufferUsageFlags usage) {
    if (size == 0) throw std::logic_error("buffer '" + name + "' has size 0 (Vulkan needs at least one byte)");
    return vk::raii::Buffer(context.device(), vk::BufferCreateInfo({}, size, usage, vk::SharingMode::eExclusive));
}

}  // namespace

Buffer::Buffer(const Context& context, std::string name, vk::DeviceSize size, vk::BufferUsageFlags usage, MemoryUse use)
    : name_(std::move(name)), size_(size), buffer_(createBuffer(context, name_, size, usage)) {
    const vk::MemoryRequirements needs = buffer_.getMemoryRequirements();
    const MemoryChoice choice = memoryChoice(context, use);
    const std::uint32_t type = chooseMemoryType(context.memoryProperties(), needs.memoryTypeBits, choice.required, choice.preferred, name_);
    try {
        memory_ = vk::raii::DeviceMemory(context.device(), vk::MemoryAllocateInfo(needs.size, type));
    } catch (const vk::OutOfDeviceMemoryError&) {
        throw std::runtime_error("out of device memory allocating buffer '" + name_ + "' (" + std::to_string(needs.size) + " bytes)");
    } catch (const vk::OutOfHostMemoryError&) {
        throw std::runtime_error("out of host memory allocating buffer '" + name_ + "' (" + std::to_string(needs.size) + " bytes)");
    }
    buffer_.bindMemory(*memory_, 0);
    if (choice.map) mapped_ = static_cast<std::byte*>(memory_.mapMemory(0, VK_WHOLE_SIZE));
}

vk::raii::BufferView makeTexelView(const Context& context, const Buffer& buffer, std::uint64_t texelBytes) {
    const vk::Format format = texelBytes == 4 ? vk::Format::eR32Uint : vk::Format::eR32G32B32A32Uint;
    vk::BufferViewCreateInfo info({}, buffer.handle(), format, 0, VK_WHOLE_SIZE);
    return vk::raii::BufferView(context.device(), info);
}

std::uint64_t stableTexelBufferBytes(std::uint64_t bytes) {
    auto unstable = [](std::uint64_t b) { return (b & (b - 1)) == 0 || ((b >> 8) & 0xff) == 0; };
    while (unstable(bytes)) bytes += 16;  // at most 16 + 256 bytes more
    return bytes;
}

namespace {

constexpr vk::BufferUsageFlags kStagingUsage = vk::BufferUsageFlagBits::eTransferSrc | vk::BufferUsageFlagBits::eTransferDst;

// Earlier kernels or copies may have touched the buffer: their writes must be visible to the
// transfer, and the transfer's writes to later kernels.
void beforeTransfer(const vk::raii::CommandBuffer& commands) {
    vk::MemoryBarrier barrier(vk::AccessFlagBits::eShaderWrite | vk::AccessFlagBits::eTransferWrite,
                              vk::AccessFlagBits::eTransferRead | vk::AccessFlagBits::eTransferWrite);
    commands.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader | vk::PipelineStageFlagBits::eTransfer,
                             vk::PipelineStageFlagBits::eTransfer, {}, barrier, {}, {});
}

void afterTransfer(const vk::raii::CommandBuffer& commands) {
    vk::MemoryBarrier barrier(vk::AccessFlagBits::eTransferWrite,
                              vk::AccessFlagBits::eShaderRead | vk::AccessFlagBits::eShaderWrite | vk::AccessFlagBits::eHostRead);
    commands.pipelineBarrier(vk::PipelineStageFlagBits::eTransfer,
                             vk::PipelineStageFlagBits::eComputeShader | vk::PipelineStageFlagBits::eHost, {}, barrier, {}, {});
}

void checkSize(const Buffer& buffer, std::size_t bytes, const char* what) {
    if (bytes > buffer.size())
        throw std::logic_error(std::string(what) + " of " + std::to_string(bytes) + " bytes does not fit buffer '" + buffer.name() +
                               "' of " + std::to_string(buffer.size()) + " bytes");
}

}  // namespace

void Transfers::upload(const Buffer& destination, std::span<const std::byte> data) {
    checkSize(destination, data.size(), "upload");
    if (data.empty()) return;
    if (destination.mapped()) {
        // Host-coherent memory: the next vkQueueSubmit makes these writes visible to the device.
        std::memcpy(destination.mapped(), data.data(), data.size());
        return;
    }
    Buffer staging(context_, destination.name() + " (staging)", data.size(), kStagingUsage, MemoryUse::Staging);
    std::memcpy(staging.mapped(), data.data(), data.size());
    runner_.run([&](const vk::raii::CommandBuffer& commands) {
        beforeTransfer(commands);
        commands.copyBuffer(staging.handle(), destination.handle(), vk::BufferCopy(0, 0, data.size()));
        afterTransfer(commands);
    });
}

void Transfers::uploadAll(std::span<const Upload> uploads) {
    constexpr std::uint64_t kAlign = 16;  // copy offsets: optimalBufferCopyOffsetAlignment is at most this in practice
    const auto sizeOf = [](const Upload& u) { return std::max<std::uint64_t>(u.bytes, u.data.size()); };
    // Mapped buffers are written in place; the others go through staging, in batches.
    std::vector<const Upload*> staged;
    for (const Upload& u : uploads) {
        checkSize(*u.destination, sizeOf(u), "upload");
        if (sizeOf(u) == 0) continue;
        if (std::byte* to = u.destination->mapped()) {
            std::memcpy(to, u.data.data(), u.data.size());
            std::memset(to + u.data.size(), 0, sizeOf(u) - u.data.size());
        } else {
            staged.push_back(&u);
        }
    }
    std::size_t first = 0;
    while (first < staged.size()) {
        std::uint64_t bytes = 0;  // one batch: the uploads that fit kStagingBatchBytes together (at least one)
        std::size_t end = first;
        for (; end < staged.size(); ++end) {
            const std::uint64_t size = (sizeOf(*staged[end]) + kAlign - 1) / kAlign * kAlign;
            if (bytes > 0 && bytes + size > kStagingBatchBytes) break;
            bytes += size;
        }
        Buffer staging(context_, "uploads (staging)", bytes, kStagingUsage, MemoryUse::Staging);
        std::vector<std::uint64_t> offsets;
        std::uint64_t offset = 0;
        for (std::size_t i = first; i < end; ++i) {
            const Upload& u = *staged[i];
            std::memcpy(staging.mapped() + offset, u.data.data(), u.data.size());
            std::memset(staging.mapped() + offset + u.data.size(), 0, sizeOf(u) - u.data.size());
            offsets.push_back(offset);
            offset += (sizeOf(u) + kAlign - 1) / kAlign * kAlign;
        }
        runner_.run([&](const vk::raii::CommandBuffer& commands) {
            beforeTransfer(commands);
            for (std::size_t i = first; i < end; ++i)
                commands.copyBuffer(staging.handle(), staged[i]->destination->handle(),
                                    vk::BufferCopy(offsets[i - first], 0, sizeOf(*staged[i])));
            afterTransfer(commands);
        });
        first = end;
    }
}

void Transfers::download(const Buffer& source, std::span<std::byte> out) {
    checkSize(source, out.size(), "download");
    if (out.empty()) return;
    if (source.mapped()) {
        // The submission that wrote it ended with a barrier to host reads and was waited for.
        std::memcpy(out.data(), source.mapped(), out.size());
        return;
    }
    Buffer readback(context_, source.name() + " (readback)", out.size(), kStagingUsage, MemoryUse::Readback);
    runner_.run([&](const vk::raii::CommandBuffer& commands) {
        beforeTransfer(commands);
        commands.copyBuffer(source.handle(), readback.handle(), vk::BufferCopy(0, 0, out.size()));
        afterTransfer(commands);
    });
    std::memcpy(out.data(), readback.mapped(), out.size());
}

void Transfers::zero(const Buffer& buffer) {
    if (buffer.mapped()) {
        std::memset(buffer.mapped(), 0, buffer.size());
        return;
    }
    runner_.run([&](const vk::raii::CommandBuffer& commands) {
        beforeTransfer(commands);
        commands.fillBuffer(buffer.handle(), 0, VK_WHOLE_SIZE, 0u);
        afterTransfer(commands);
    });
}

}  // namespace vkrt
