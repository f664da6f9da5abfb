#include "commands.h"

#include <stdexcept>
#include <string>

namespace vkrt {

namespace {

vk::raii::CommandBuffer allocateOne(const vk::raii::Device& device, const vk::raii::CommandPool& pool) {
    vk::CommandBufferAllocateInfo info(*pool, vk::CommandBufferLevel::ePrimary, 1);
    return std::move(vk::raii::CommandBuffers(device, info).front());
}

}  // namespace

CommandRunner::CommandRunner(const Context& context)
    : context_(context),
      pool_(context.device(), vk::CommandPoolCreateInfo(vk::CommandPoolCreateFlagBits::eResetCommandBuffer, context.queueFamily())),
      commands_(allocateOne(context.device(), pool_)),
      fence_(context.device(), vk::FenceCreateInfo()) {
    if (context.info().timestampValidBits > 0)
        timestamps_ = vk::raii::QueryPool(context.device(), vk::QueryPoolCreateInfo({}, vk::QueryType::eTimestamp, 2));
}

double CommandRunner::run(const std::function<void(const vk::raii::CommandBuffer&)>& record,
                          std::chrono::milliseconds timeout) {
    commands_.reset();
    commands_.begin(vk::CommandBufferBeginInfo(vk::CommandBufferUsageFlagBits::eOneTimeSubmit));
    if (*timestamps_) {
        commands_.resetQueryPool(*timestamps_, 0, 2);
        commands_.writeTimestamp(vk::PipelineStageFlagBits::eTopOfPipe, *timestamps_, 0);
    }
    record(commands_);
    if (*timestamps_) commands_.writeTimestamp(vk::PipelineStageFlagBits::eBottomOfPipe, *timestamps_, 1);
    commands_.end();

    context_.device().resetFences(*fence_);
    vk::SubmitInfo submit;
    submit.setCommandBuffers(*commands_);
    const auto start = std::chrono::steady_clock::now();
    context_.queue().submit(submit, *fence_);
    const auto nanoseconds = std::chrono::duration_cast<std::chrono::nanoseconds>(timeout).count();
    const vk::Result result = context_.device().waitForFences(*fence_, VK_TRUE, static_cast<std::uint64_t>(nanoseconds));
    if (result == vk::Result::eTimeout)
        throw std::runtime_error("a GPU submission did not finish within " + std::to_string(timeout.count() / 1000.0) +
                                 " s on " + context_.info().name + "; the device is probably hung");
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    lastDeviceSeconds_ = -1.0;
    if (*timestamps_) {
        std::uint64_t ticks[2] = {0, 0};
        const vk::Result got = (*context_.device()).getQueryPoolResults(*timestamps_, 0, 2, sizeof ticks, ticks, sizeof ticks[0],
                                                                         vk::QueryResultFlagBits::e64);
        const unsigned bits = context_.info().timestampValidBits;
        const std::uint64_t mask = bits >= 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << bits) - 1;
        if (got == vk::Result::eSuccess)
            lastDeviceSeconds_ = static_cast<double>((ticks[1] - ticks[0]) & mask) * context_.info().timestampPeriodNs * 1e-9;
    }
    return wall;
}

void computeToComputeBarrier(const vk::raii::CommandBuffer& commands) {
    vk::MemoryBarrier barrier(vk::AccessFlagBits::eShaderWrite, vk::AccessFlagBits::eShaderRead | vk::AccessFlagBits::eShaderWrite);
    commands.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader, vk::PipelineStageFlagBits::eComputeShader, {}, barrier, {}, {});
}

void computeToIndirectBarrier(const vk::raii::CommandBuffer& commands) {
    vk::MemoryBarrier barrier(vk::AccessFlagBits::eShaderWrite,
                              vk::AccessFlagBits::eShaderRead | vk::AccessFlagBits::eShaderWrite | vk::AccessFlagBits::eIndirectCommandRead);
    commands.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader,
                             vk::PipelineStageFlagBits::eComputeShader | vk::PipelineStageFlagBits::eDrawIndirect, {}, barrier, {}, {});
}

void computeToHostBarrier(const vk::raii::CommandBuffer& commands) {
    vk::MemoryBarrier barrier(vk::AccessFlagBits::eShaderWrite, vk::AccessFlagBits::eHostRead);
    commands.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader, vk::PipelineStageFlagBits::eHost, {}, barrier, {}, {});
}

}  // namespace vkrt
