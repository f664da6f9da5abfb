// lavapipe's loop limiter (../shared/LAVAPIPE.md): Mesa before 25 ends loops silently after
// 65,535 loop passes. loop_counter.comp counts the iterations loops really run, and the test
// compares them with a model of the limiter as gallivm builds it (lp_exec_endloop): one counter
// per SIMD group of 8 lanes, shared by every loop of the kernel, decremented once per pass of any
// loop - including the last pass that only finds the loop condition false - and every loop stops
// once it reaches zero. Lanes run in lockstep with masks, so even a loop in a branch no lane takes
// makes one (empty) pass. The test accepts either world - no limiter, or exactly this one - and
// prints which; anything else fails.
#include <array>

#include <gtest/gtest.h>

#include "buffer.h"
#include "commands.h"
#include "compute_pipeline.h"
#include "vulkan_test_support.h"

namespace vkrt {
namespace {

using test::VulkanTest;

constexpr std::uint32_t kMesaLoopLimit = 65535;  // LP_MAX_TGSI_LOOP_ITERATIONS in gallivm
constexpr std::uint32_t kLanes = 8;

struct Counts {
    std::uint32_t step[4];
    std::array<std::uint32_t, kLanes> first;
    std::array<std::uint32_t, kLanes> second;
};

// The model. `limit` = 0 means no limiter. Returns what loop_counter.comp writes.
Counts model(std::uint32_t n, std::uint32_t mode, std::uint32_t limit) {
    Counts c{};
    std::int64_t budget = limit ? limit : INT64_MAX;
    // One loop pass: the body when `more`, then the limiter's decrement; false: the loop ends.
    auto pass = [&](bool more) {
        --budget;
        return more && budget > 0;
    };
    if (mode == 2) {
        for (std::uint32_t i = 0;; ++i) {
            const bool more = i < n;
            if (more) {
                for (auto& f : c.first) ++f;
                for (std::uint32_t k = 0;; ++k) {  // the inner loop of lane i % 8
                    const bool innerMore = k < 7;
                    if (innerMore) ++c.second[i % kLanes];
                    if (!pass(innerMore)) break;
                }
            }
            if (!pass(more)) break;
        }
        return c;
    }
    // The mode-2 branch comes first in the kernel: no lane takes it, yet its outer loop makes one
    // empty pass, and inside it so does its inner loop.
    budget -= 2;
    for (std::uint32_t i = 0;; ++i) {
        if (i < n) for (auto& f : c.first) ++f;
        if (!pass(i < n)) break;
    }
    if (mode == 1) {
        for (std::uint32_t i = 0;; ++i) {
            if (i < n) for (auto& s : c.second) ++s;
            if (!pass(i < n)) break;
        }
    }
    return c;
}

class LoopCounter {
public:
    explicit LoopCounter(const Context& context)
        : setLayout_(context.device(), vk::DescriptorSetLayoutCreateInfo({}, binding_)),
          layout_(context.device(), vk::PipelineLayoutCreateInfo({}, *setLayout_, push_)),
          module_(makeShaderModule(context, test::testKernel("loop_counter"))),
          pipeline_(makeComputePipeline(context, nullptr, *layout_, *module_, {})),
          runner_(context),
          transfers_(context, runner_),
          buffer_(context, "counts", sizeof(Counts),
                  vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eTransferDst | vk::BufferUsageFlagBits::eTransferSrc,
                  MemoryUse::Device),
          pool_(context.device(), vk::DescriptorPoolCreateInfo(vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, 1, poolSize_)),
          set_(std::move(vk::raii::DescriptorSets(context.device(), vk::DescriptorSetAllocateInfo(*pool_, *setLayout_)).front())) {
        const vk::DescriptorBufferInfo info(buffer_.handle(), 0, VK_WHOLE_SIZE);
        context.device().updateDescriptorSets(vk::WriteDescriptorSet(*set_, 0, 0, vk::DescriptorType::eStorageBuffer, {}, info), {});
    }

    Counts run(std::uint32_t n, std::uint32_t mode) {
        Counts initial{{1, 1, 1, 1}, {}, {}};
        initial.first.fill(0xdeadbeefu);
        initial.second.fill(0xdeadbeefu);
        transfers_.upload(buffer_, std::as_bytes(std::span(&initial, 1)));
        const std::uint32_t push[2] = {n, mode};
        runner_.run([&](const vk::raii::CommandBuffer& commands) {
            computeToComputeBarrier(commands);
            commands.bindPipeline(vk::PipelineBindPoint::eCompute, *pipeline_);
            commands.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *layout_, 0, *set_, {});
            commands.pushConstants<std::uint32_t>(*layout_, vk::ShaderStageFlagBits::eCompute, 0, push);
            commands.dispatch(1, 1, 1);
            computeToHostBarrier(commands);
        });
        Counts result{};
        transfers_.download(buffer_, std::as_writable_bytes(std::span(&result, 1)));
        return result;
    }

private:
    static constexpr vk::DescriptorSetLayoutBinding binding_{0, vk::DescriptorType::eStorageBuffer, 1, vk::ShaderStageFlagBits::eCompute};
    static constexpr vk::PushConstantRange push_{vk::ShaderStageFlagBits::eCompute, 0, 8};
    static constexpr vk::DescriptorPoolSize poolSize_{vk::DescriptorType::eStorageBuffer, 1};
    vk::raii::DescriptorSetLayout setLayout_;
    vk::raii::PipelineLayout layout_;
    vk::raii::ShaderModule module_;
    vk::raii::Pipeline pipeline_;
    CommandRunner runner_;
    Transfers transfers_;
    Buffer buffer_;
    vk::raii::DescriptorPool pool_;
    vk::raii::DescriptorSet set_;
};

void expectModel(const Counts& measured, const Counts& expected, const std::string& what) {
    EXPECT_EQ(measured.first, expected.first) << what;
    EXPECT_EQ(measured.second, expected.second) << what;
}

TEST_F(VulkanTest, LoopLimiterIsAbsentOrExactlyMesasSharedPassCounter) {
    const Context& c = context();
    LoopCounter counter(c);
    const std::uint32_t big = 200000;
    const std::uint32_t ran = counter.run(big, 0).first[0];
    const std::uint32_t limit = ran == big ? 0 : kMesaLoopLimit;
    std::cout << c.info().name << " / " << c.info().driver << ": loop limiter "
              << (limit ? "PRESENT: a loop of " + std::to_string(big) + " iterations stopped after " + std::to_string(ran)
                        : std::string("absent"))
              << "\n";
    expectModel(counter.run(big, 0), model(big, 0, limit), "one loop of 200000");
    for (std::uint32_t n : {1u, 1000u, kMesaLoopLimit - 1, kMesaLoopLimit, kMesaLoopLimit + 1, 1000000u})
        expectModel(counter.run(n, 0), model(n, 0, limit), "one loop of " + std::to_string(n));

    // Shared by all loops, and the pass that ends a loop counts: 2 + 40000 + 1 passes leave 25532.
    const Counts two = counter.run(40000, 1);
    expectModel(two, model(40000, 1, limit), "two loops of 40000");
    std::cout << "two loops of 40000 in a row: " << two.first[0] << " + " << two.second[0] << " iterations ran\n";

    // Divergence: the counter belongs to the SIMD group, not to a lane. Every outer iteration
    // costs the group 1 + 8 passes although each lane runs an inner loop only every 8th time.
    const Counts divergent = counter.run(20000, 2);
    expectModel(divergent, model(20000, 2, limit), "divergent inner loops");
    const std::uint32_t ownIterations = divergent.first[0] + divergent.second[0];
    std::cout << "divergent loops: the outer loop stopped after " << divergent.first[0] << " of 20000 iterations, when lane 0 "
              << "had run only " << ownIterations << " iterations of its own\n";
    if (limit) {
        // What the render kernel must design around: a per-invocation count of its own loop
        // iterations (LOOP_BUDGET = 60000 in device_host.h) does not bound the group's counter.
        EXPECT_LT(divergent.first[0], 20000u);
        EXPECT_LT(ownIterations, gpu::LOOP_BUDGET);
    }
}

}  // namespace
}  // namespace vkrt
