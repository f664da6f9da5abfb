#include "wavefront_renderer.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <string>

#include "float_range.h"
#include "pixel_sums.h"
#include "progress.h"
#include "render_status.h"
#include "wavefront_plan.h"

namespace vkrt {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Extend-shade-shadow-resolve steps a wave may take before the render stops with an error: a
// path's rays (a dielectric's tree of them) are bounded by the depth, so only a runaway reaches it.
constexpr std::uint32_t kMaxSteps = 1u << 16;

std::uint32_t groupsFor(std::uint64_t invocations) { return static_cast<std::uint32_t>((invocations + 63) / 64); }

class StageRecorder {
public:
    StageRecorder(const vk::raii::CommandBuffer& commands, const GpuRenderDevice& device, const SceneUpload& scene,
                  const std::array<const vk::raii::Pipeline*, gpu::WAVEFRONT_STAGE_COUNT>& pipelines, const gpu::PassParams& wave)
        : commands_(commands), layout_(device.layout.pipelineLayout()), status_(scene.statusBuffer()), pipelines_(pipelines),
          wave_(wave) {
        const vk::DescriptorSet set = scene.descriptorSet();
        commands.bindDescriptorSets(vk::PipelineBindPoint::eCompute, layout_, 0, set, {});
        commands.pushConstants<gpu::PassParams>(layout_, vk::ShaderStageFlagBits::eCompute, 0, wave);
    }

    // Rounds [first, first + count): pass.z carries each one's parity (the path queue it reads,
    // wavefront_state.glsl); each stage covers its queue by an indirect dispatch.
    void rounds(std::uint32_t first, std::uint32_t count, std::uint32_t shadowsPerPath) {
        for (std::uint32_t round = first; round < first + count; ++round) {
            const std::uint32_t q = round & 1u;
            wave_.pass.z = q;
            commands_.pushConstants<gpu::PassParams>(layout_, vk::ShaderStageFlagBits::eCompute, 0, wave_);
            queueStage(gpu::WAVEFRONT_EXTEND, q);
            if (shadowsPerPath > 0) {
                queueStage(gpu::WAVEFRONT_SHADE_RECORD, q);
                queueStage(gpu::WAVEFRONT_SHADOW, 2);
            }
            queueStage(gpu::WAVEFRONT_SHADE_RESOLVE, q);
        }
    }

    // One stage over `invocations` lanes, after everything recorded before it.
    void stage(std::uint32_t which, std::uint64_t invocations) {
        if (invocations == 0) return;
        computeToIndirectBarrier(commands_);
        commands_.bindPipeline(vk::PipelineBindPoint::eCompute, **pipelines_[which]);
        // Height and depth 1: the kernels read their uniforms at gl_NumWorkGroups.z - 1 (bindings.glsl).
        commands_.dispatch(groupsFor(invocations), 1, 1);
    }

    // One stage over queue q's entries: as many workgroups as the stages that appended to it counted
    // (RenderStatus::queueGroups[q], written on the device), so ended paths cost nothing.
    void queueStage(std::uint32_t which, std::uint32_t q) {
        computeToIndirectBarrier(commands_);
        commands_.bindPipeline(vk::PipelineBindPoint::eCompute, **pipelines_[which]);
        commands_.dispatchIndirect(status_, offsetof(gpu::RenderStatus, queueGroups) + q * sizeof(glm::uvec4));
    }

private:
    const vk::raii::CommandBuffer& commands_;
    vk::PipelineLayout layout_;
    vk::Buffer status_;
    const std::array<const vk::raii::Pipeline*, gpu::WAVEFRONT_STAGE_COUNT>& pipelines_;
    gpu::PassParams wave_;
};

}  // namespace

std::uint64_t targetWavePaths(const DeviceInfo& device) { return device.lavapipe ? (1u << 16) : (1u << 20); }

void renderWavefront(const GpuRenderDevice& device, SceneUpload& gpuScene, const GpuSceneData& data, const KernelInputs& in,
                     const RenderOptions& options, std::uint64_t wavePaths, GpuRenderStats& stats, std::vector<glm::vec4>& sums) {
    const WavefrontPathLayout pathLayout = wavefrontPathLayout(data.tables, in.features, in.frame);
    const std::uint64_t pixels = static_cast<std::uint64_t>(options.width) * options.height;
    const std::uint64_t pathsPerWave = wavePathsFor(device.context.limits(), pixels, pathLayout,
                                                    device.context.info().maxWorkGroupCountX,
                                                    wavePaths > 0 ? wavePaths : targetWavePaths(device.context.info()));
    const glm::ivec2 rows = rowsOf(options);
    std::vector<std::uint32_t> breaks;
    const std::vector<int> checkpoints = checkpointEnds(options.samplesPerPixel, options.checkpoints);
    if (options.onCheckpoint)
        for (const int end : checkpoints) breaks.push_back(static_cast<std::uint32_t>(end));
    // A wave holds a row at least (an image wider than the device's wave: the memory check refuses
    // what does not fit).
    const WavePlan plan = planWaves(static_cast<std::uint32_t>(options.width), static_cast<std::uint32_t>(rows.x),
                                    static_cast<std::uint32_t>(rows.y), static_cast<std::uint32_t>(options.samplesPerPixel),
                                    std::max<std::uint64_t>(pathsPerWave, static_cast<std::uint64_t>(options.width)), breaks);

    std::array<const vk::raii::Pipeline*, gpu::WAVEFRONT_STAGE_COUNT> pipelines{};
    for (std::uint32_t stage = gpu::WAVEFRONT_GENERATE; stage < gpu::WAVEFRONT_STAGE_COUNT; ++stage) {
        FeatureSet features = in.features;
        features.wavefrontStage = stage;
        double seconds = 0.0;
        pipelines[stage] = &device.kernels.pipeline(features, 1, &seconds);
        stats.pipelineSeconds += seconds;
    }

    auto start = Clock::now();
    gpuScene.beginWavefront(device.context, device.transfers, in.frame, plan.maxPaths * pathLayout.texelsPerPath());
    stats.uploadSeconds += secondsSince(start);
    stats.sceneBytes = gpuScene.bytes();

    // Steps per submission: a path without a stack has at most one ray per depth.
    const std::uint32_t depth = std::min(in.features.maxDepth, static_cast<std::uint32_t>(std::max(options.maxDepth, 0)));
    const std::uint32_t stepsPerSubmission = depth + 1;
    const bool branches = in.features.pathStackSize > 0;
    const auto width = static_cast<std::uint32_t>(options.width);
    sums.assign(pixels, glm::vec4(0.0f));
    Progress progress("GPU render", options.quiet);
    std::uint32_t ended = 0;  // paths ended so far, as the kernels count them (modulo 2^32)
    std::size_t round = 0;
    start = Clock::now();
    for (std::size_t w = 0; w < plan.waves.size(); ++w) {
        if (options.cancel && options.cancel->load()) {
            device.context.device().waitIdle();
            throw RenderCancelled{};
        }
        const Wave& wave = plan.waves[w];
        const gpu::PassParams params = passParams(wave.band, wave.firstSample, wave.samples);
        gpu::PassParams waveParams = params;
        waveParams.pass.y = pathLayout.shadowsPerPath;
        waveParams.pass.z = 0;  // the round's parity (StageRecorder::rounds)
        const std::uint64_t paths = wave.paths();
        ended += static_cast<std::uint32_t>(paths);
        std::uint32_t steps = 0;
        auto submit = [&](const std::function<void(StageRecorder&)>& record) {
            const double seconds = device.runner.run([&](const vk::raii::CommandBuffer& commands) {
                StageRecorder recorder(commands, device, gpuScene, pipelines, waveParams);
                record(recorder);
                computeToHostBarrier(commands);
            });
            if (device.runner.lastDeviceSeconds() >= 0.0)
                stats.kernelSeconds = std::max(stats.kernelSeconds, 0.0) + device.runner.lastDeviceSeconds();
            stats.maxSubmissionSeconds = std::max(stats.maxSubmissionSeconds, seconds);
            ++stats.submissions;
            throwIfKernelFailed(gpuScene.status(), width, device.context.info().loopLimiter);
        };
        submit([&](StageRecorder& r) {
            r.stage(gpu::WAVEFRONT_GENERATE, paths);
            r.rounds(0, stepsPerSubmission, pathLayout.shadowsPerPath);
            if (!branches) r.stage(gpu::WAVEFRONT_ACCUMULATE, wave.band.pixels());
        });
        steps += stepsPerSubmission;
        stats.dispatches += 1 + stepsPerSubmission * (pathLayout.shadowsPerPath > 0 ? 4 : 2) + (branches ? 0 : 1);
        // A path that branches (a dielectric, gloss samples) may need more steps than its depth.
        while (gpuScene.status().paths.x != ended) {
            if (!branches || steps >= kMaxSteps)
                throw GpuKernelError("the wavefront kernels left " + std::to_string(ended - gpuScene.status().paths.x) +
                                     " paths unfinished after " + std::to_string(steps) + " steps");
            submit([&](StageRecorder& r) { r.rounds(steps, stepsPerSubmission, pathLayout.shadowsPerPath); });
            steps += stepsPerSubmission;
        }
        if (branches) submit([&](StageRecorder& r) { r.stage(gpu::WAVEFRONT_ACCUMULATE, wave.band.pixels()); });
        progress.update(static_cast<double>(w + 1) / plan.waves.size());

        if (round < plan.roundEnds.size() && w + 1 == plan.roundEnds[round]) {
            const auto samplesDone = static_cast<int>(wave.firstSample + wave.samples);
            ++round;
            const bool last = w + 1 == plan.waves.size();
            if (options.onCheckpoint && !last && std::find(checkpoints.begin(), checkpoints.end(), samplesDone) != checkpoints.end()) {
                device.transfers.download(gpuScene.accum(), std::as_writable_bytes(std::span(sums)));
                const std::vector<TileRect> band = {TileRect{0, 0, width, static_cast<std::uint32_t>(rows.y - rows.x)}};
                Image soFar = resolveSoFar(sums, options.width, options.height, band, 0, samplesDone, samplesDone, rows.x);
                clampOverflowedPixels(soFar);
                options.onCheckpoint->checkpoint(soFar, samplesDone);
            }
        }
    }
    stats.renderSeconds = secondsSince(start);
    stats.nonFiniteSamples = gpu::statusNonFiniteSamples(gpuScene.status());

    device.transfers.download(gpuScene.accum(), std::as_writable_bytes(std::span(sums)));
}

}  // namespace vkrt
