#include "submission_recorder.h"

#include "commands.h"

namespace vkrt {

void recordWarmUp(const vk::raii::CommandBuffer& commands, vk::Pipeline pipeline, vk::PipelineLayout layout,
                  vk::DescriptorSet set) {
    gpu::PassParams params{};
    params.pass = glm::uvec4(0u, 1u, 1u, 1u);  // sample 0, stride 1, one workgroup, one sample; tile 0x0 at (0, 0)
    computeToComputeBarrier(commands);
    commands.bindPipeline(vk::PipelineBindPoint::eCompute, pipeline);
    commands.bindDescriptorSets(vk::PipelineBindPoint::eCompute, layout, 0, set, {});
    commands.pushConstants<gpu::PassParams>(layout, vk::ShaderStageFlagBits::eCompute, 0, params);
    commands.dispatch(1, 1, 1);  // z = 1: see recordSubmission
    computeToHostBarrier(commands);
}

void recordSubmission(const vk::raii::CommandBuffer& commands, vk::Pipeline pipeline, vk::PipelineLayout layout,
                      vk::DescriptorSet set, const Submission& submission, const SampleBatching& batching) {
    // The previous submission's additions to the accumulation buffer come first (in-order
    // sample sums), and the host's writes (status reset, uploads) are covered by the submit.
    computeToComputeBarrier(commands);
    commands.bindPipeline(vk::PipelineBindPoint::eCompute, pipeline);
    commands.bindDescriptorSets(vk::PipelineBindPoint::eCompute, layout, 0, set, {});
    for (std::uint32_t s = 0; s < submission.sampleCount; ++s) {
        const std::uint32_t pass = submission.firstSample + s;  // the planner counts passes, not samples
        const gpu::PassParams params = passParams(submission.tile, batching.first(pass), batching.count(pass));
        if (s > 0) computeToComputeBarrier(commands);  // pass s adds to the sums pass s-1 wrote
        commands.pushConstants<gpu::PassParams>(layout, vk::ShaderStageFlagBits::eCompute, 0, params);
        // The base offsets gl_WorkGroupID, so render.comp's block mapping sees workgroups
        // [first, first + count) of the pass without knowing about partial dispatches. Height and
        // depth stay 1: the kernels read their uniforms at gl_NumWorkGroups.z - 1 (bindings.glsl).
        commands.dispatchBase(submission.firstWorkgroup, 0, 0, submission.workgroupCount, 1, 1);
    }
    computeToHostBarrier(commands);  // status (every submission) and accumulation (at the end)
}

void recordAdaptivePass(const vk::raii::CommandBuffer& commands, vk::Pipeline pipeline, vk::PipelineLayout layout,
                        vk::DescriptorSet set, std::uint32_t firstEntry, std::uint32_t entries, std::uint32_t samplesDone,
                        std::uint32_t k) {
    const std::uint32_t groups = (entries + 63u) / 64u;
    gpu::PassParams params{};
    params.tile = glm::uvec4(firstEntry, 0u, entries, 1u);
    params.pass = glm::uvec4(samplesDone, 1u, groups, k);
    computeToComputeBarrier(commands);  // the previous pass's sums (and the host's uploads) first
    commands.bindPipeline(vk::PipelineBindPoint::eCompute, pipeline);
    commands.bindDescriptorSets(vk::PipelineBindPoint::eCompute, layout, 0, set, {});
    commands.pushConstants<gpu::PassParams>(layout, vk::ShaderStageFlagBits::eCompute, 0, params);
    commands.dispatch(groups, 1, 1);  // z = 1: the kernels read their uniforms at gl_NumWorkGroups.z - 1
    computeToHostBarrier(commands);
}

}  // namespace vkrt
