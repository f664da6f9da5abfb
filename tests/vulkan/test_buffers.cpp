// Buffers: upload and readback through a mapping and through staging copies, zero fill, memory
// type choice, and RGBA32UI texel buffers read by imageLoad returning every bit unchanged.
#include <cstring>
#include <random>

#include <gtest/gtest.h>

#include "buffer.h"
#include "commands.h"
#include "compute_pipeline.h"
#include "vulkan_test_support.h"

namespace vkrt {
namespace {

using test::VulkanTest;

const vk::BufferUsageFlags kStorage =
    vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eTransferDst | vk::BufferUsageFlagBits::eTransferSrc;

std::vector<std::uint32_t> pattern(std::size_t n, std::uint32_t seed) {
    std::mt19937 random(seed);
    std::vector<std::uint32_t> words(n);
    for (auto& w : words) w = random();
    return words;
}

void roundTrip(const Context& context, bool expectMapped) {
    CommandRunner runner(context);
    Transfers transfers(context, runner);
    const std::vector<std::uint32_t> data = pattern(10007, 1);  // odd size: no power-of-two luck
    Buffer buffer(context, "round trip", data.size() * 4, kStorage, MemoryUse::Device);
    EXPECT_EQ(buffer.mapped() != nullptr, expectMapped);
    transfers.upload(buffer, std::as_bytes(std::span(data)));
    std::vector<std::uint32_t> back(data.size(), 0);
    transfers.download(buffer, std::as_writable_bytes(std::span(back)));
    EXPECT_EQ(back, data);

    transfers.zero(buffer);
    transfers.download(buffer, std::as_writable_bytes(std::span(back)));
    EXPECT_EQ(back, std::vector<std::uint32_t>(data.size(), 0u));
}

TEST_F(VulkanTest, BufferRoundTripThroughTheDefaultPath) {
    const Context& c = context();
    roundTrip(c, c.mapsDeviceMemory());
}

TEST_F(VulkanTest, BufferRoundTripThroughStagingCopies) {
    const Context& c = context({.forceStaging = true});
    ASSERT_FALSE(c.mapsDeviceMemory());
    roundTrip(c, false);
}

TEST_F(VulkanTest, OversizedUploadIsALogicError) {
    const Context& c = context();
    CommandRunner runner(c);
    Transfers transfers(c, runner);
    Buffer buffer(c, "small", 16, kStorage, MemoryUse::Device);
    const std::vector<std::byte> data(17);
    EXPECT_THROW(transfers.upload(buffer, data), std::logic_error);
    EXPECT_THROW(Buffer(c, "empty", 0, kStorage, MemoryUse::Device), std::logic_error);
}

TEST(MemoryType, RequiredFlagsAreMandatoryPreferredOnesWin) {
    vk::PhysicalDeviceMemoryProperties memory{};
    using F = vk::MemoryPropertyFlagBits;
    memory.memoryTypeCount = 3;
    memory.memoryTypes[0].propertyFlags = F::eDeviceLocal;
    memory.memoryTypes[1].propertyFlags = F::eHostVisible | F::eHostCoherent;
    memory.memoryTypes[2].propertyFlags = F::eHostVisible | F::eHostCoherent | F::eHostCached;
    const vk::MemoryPropertyFlags hostCoherent = F::eHostVisible | F::eHostCoherent;
    EXPECT_EQ(chooseMemoryType(memory, 0b111, hostCoherent, F::eHostCached, "b"), 2u);
    EXPECT_EQ(chooseMemoryType(memory, 0b011, hostCoherent, F::eHostCached, "b"), 1u);  // type 2 not allowed
    EXPECT_EQ(chooseMemoryType(memory, 0b111, {}, F::eDeviceLocal, "b"), 0u);
    EXPECT_EQ(chooseMemoryType(memory, 0b110, {}, F::eDeviceLocal, "b"), 1u);           // fallback
    EXPECT_THROW(chooseMemoryType(memory, 0b001, hostCoherent, {}, "b"), std::runtime_error);
}

// texel_copy.comp: out[i] = imageLoad(texels, i) for every texel of an RGBA32UI buffer.
void texelRoundTrip(const Context& context) {
    const vk::raii::Device& device = context.device();
    const vk::DescriptorSetLayoutBinding bindings[] = {
        {0, vk::DescriptorType::eStorageTexelBuffer, 1, vk::ShaderStageFlagBits::eCompute},
        {1, vk::DescriptorType::eStorageBuffer, 1, vk::ShaderStageFlagBits::eCompute}};
    vk::raii::DescriptorSetLayout setLayout(device, vk::DescriptorSetLayoutCreateInfo({}, bindings));
    const vk::DescriptorSetLayout setLayouts[] = {*setLayout};
    vk::raii::PipelineLayout layout(device, vk::PipelineLayoutCreateInfo({}, setLayouts));
    const auto spirv = test::testKernel("texel_copy");
    vk::raii::ShaderModule module = makeShaderModule(context, spirv);
    vk::raii::Pipeline pipeline = makeComputePipeline(context, nullptr, *layout, *module, {});

    // Float bit patterns the kernel stores in texels: NaNs, infinities, denormals, -0. An
    // integer texel must come back bit for bit, never canonicalised.
    std::vector<std::uint32_t> words = pattern(4 * 1000, 2);
    const std::uint32_t special[] = {0x7fc00001u, 0xffffffffu, 0x7f800000u, 0xff800000u, 0x00000001u, 0x80000000u, 0x7f7fffffu};
    std::copy(std::begin(special), std::end(special), words.begin());
    const std::size_t texels = words.size() / 4;

    CommandRunner runner(context);
    Transfers transfers(context, runner);
    Buffer input(context, "texels", words.size() * 4,
                 vk::BufferUsageFlagBits::eStorageTexelBuffer | vk::BufferUsageFlagBits::eTransferDst, MemoryUse::Device);
    Buffer output(context, "copied", words.size() * 4, kStorage, MemoryUse::Device);
    transfers.upload(input, std::as_bytes(std::span(words)));
    transfers.zero(output);
    vk::raii::BufferView view = makeTexelView(context, input);

    const vk::DescriptorPoolSize sizes[] = {{vk::DescriptorType::eStorageTexelBuffer, 1}, {vk::DescriptorType::eStorageBuffer, 1}};
    vk::raii::DescriptorPool pool(device, vk::DescriptorPoolCreateInfo(vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, 1, sizes));
    vk::raii::DescriptorSet set = std::move(vk::raii::DescriptorSets(device, vk::DescriptorSetAllocateInfo(*pool, setLayouts)).front());
    const vk::BufferView views[] = {*view};
    const vk::DescriptorBufferInfo outInfo(output.handle(), 0, VK_WHOLE_SIZE);
    const vk::WriteDescriptorSet writes[] = {
        vk::WriteDescriptorSet(*set, 0, 0, vk::DescriptorType::eStorageTexelBuffer, {}, {}, views),
        vk::WriteDescriptorSet(*set, 1, 0, vk::DescriptorType::eStorageBuffer, {}, outInfo)};
    device.updateDescriptorSets(writes, {});

    runner.run([&](const vk::raii::CommandBuffer& commands) {
        computeToComputeBarrier(commands);
        commands.bindPipeline(vk::PipelineBindPoint::eCompute, *pipeline);
        commands.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *layout, 0, *set, {});
        commands.dispatch(static_cast<std::uint32_t>((texels + 63) / 64), 1, 1);
        computeToHostBarrier(commands);
    });
    std::vector<std::uint32_t> back(words.size(), 0);
    transfers.download(output, std::as_writable_bytes(std::span(back)));
    EXPECT_EQ(back, words);
}

TEST_F(VulkanTest, TexelBufferFetchReturnsEveryBit) { texelRoundTrip(context()); }

TEST_F(VulkanTest, TexelBufferFetchReturnsEveryBitAfterStaging) { texelRoundTrip(context({.forceStaging = true})); }

}  // namespace
}  // namespace vkrt
