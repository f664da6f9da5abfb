#include "wavefront_renderer.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <functional>
#include <span>
#include <string>

#include "float_range.h"
#include "pixel_sums.h"
#include "progress.h"
#include "render_cancel.h"
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

    // The queues' lengths and dispatch sizes at a wave's start, written on the device's timeline:
    // round 0's queue holds `firstQueue` entries (GENERATE writes every slot in order), or none
    // when GENERATE appends them (adaptive rounds: only the slots with a sample); the others none.
    void resetQueues(std::uint32_t firstQueue) {
        struct Counters {
            glm::uvec3 lengths;  // RenderStatus::paths y, z, w
            glm::uvec4 groups[3];
        };
        static_assert(offsetof(gpu::RenderStatus, queueGroups) == offsetof(gpu::RenderStatus, paths) + 16);
        static_assert(sizeof(Counters) == 12 + 3 * 16);  // no padding: written over paths.y .. queueGroups[2]
        // A path queue keeps one workgroup when empty: its first invocation empties the next queue.
        const Counters counters{glm::uvec3(firstQueue, 0u, 0u),
                                {glm::uvec4(std::max(groupsFor(firstQueue), 1u), 1u, 1u, 0u), glm::uvec4(1u, 1u, 1u, 0u),
                                 glm::uvec4(0u, 1u, 1u, 0u)}};
        commands_.updateBuffer<Counters>(status_, offsetof(gpu::RenderStatus, paths) + 4, counters);
        vk::MemoryBarrier barrier(vk::AccessFlagBits::eTransferWrite,
                                  vk::AccessFlagBits::eShaderRead | vk::AccessFlagBits::eShaderWrite | vk::AccessFlagBits::eIndirectCommandRead);
        commands_.pipelineBarrier(vk::PipelineStageFlagBits::eTransfer,
                                  vk::PipelineStageFlagBits::eComputeShader | vk::PipelineStageFlagBits::eDrawIndirect, {}, barrier, {}, {});
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

// One wave at a time through the stages (the pipelines of `in`'s feature set, made once).
class WaveRunner {
public:
    WaveRunner(const GpuRenderDevice& device, SceneUpload& scene, const GpuSceneData& data, const KernelInputs& in,
               const RenderOptions& options, GpuRenderStats& stats)
        : device_(device), scene_(scene), stats_(stats), layout_(wavefrontPathLayout(data.tables, in.features, in.frame)),
          branches_(in.features.pathStackSize > 0), appends_(in.features.adaptive),
          width_(static_cast<std::uint32_t>(options.width)) {
        for (std::uint32_t stage = gpu::WAVEFRONT_GENERATE; stage < gpu::WAVEFRONT_STAGE_COUNT; ++stage) {
            FeatureSet features = in.features;
            features.wavefrontStage = stage;
            double seconds = 0.0;
            pipelines_[stage] = &device.kernels.pipeline(features, 1, &seconds);
            stats.pipelineSeconds += seconds;
        }
        // Rounds per submission: a path without a stack has at most one ray per depth.
        const std::uint32_t depth = std::min(in.features.maxDepth, static_cast<std::uint32_t>(std::max(options.maxDepth, 0)));
        roundsPerSubmission_ = depth + 1;
    }

    const WavefrontPathLayout& layout() const { return layout_; }

    // Paths per wave on this device (`wanted`: 0 for its default) for an accumulation buffer that
    // holds `texelsBefore` texels before the paths.
    std::uint64_t pathsPerWave(std::uint64_t texelsBefore, std::uint64_t wanted) const {
        return wavePathsFor(device_.context.limits(), texelsBefore, layout_, device_.context.info().maxWorkGroupCountX,
                            wanted > 0 ? wanted : targetWavePaths(device_.context.info()));
    }

    // One wave to its end: GENERATE over `paths` slots, rounds until every path has ended, then
    // ACCUMULATE over `accumulators` lanes. `wave` is its push constants but the shadow rays per path
    // and the round parity, set here.
    void run(gpu::PassParams wave, std::uint64_t paths, std::uint64_t accumulators) {
        wave.pass.y = layout_.shadowsPerPath;
        wave.pass.z = 0;  // the round's parity (StageRecorder::rounds)
        ended_ += static_cast<std::uint32_t>(paths);
        std::uint32_t rounds = 0;
        const std::uint32_t shadows = layout_.shadowsPerPath;
        submit(wave, [&](StageRecorder& r) {
            r.resetQueues(appends_ ? 0u : static_cast<std::uint32_t>(paths));
            r.stage(gpu::WAVEFRONT_GENERATE, paths);
            r.rounds(0, roundsPerSubmission_, shadows);
            if (!branches_) r.stage(gpu::WAVEFRONT_ACCUMULATE, accumulators);
        });
        rounds += roundsPerSubmission_;
        stats_.dispatches += 1 + roundsPerSubmission_ * (shadows > 0 ? 4 : 2) + (branches_ ? 0 : 1);
        // A path that branches (a dielectric where nothing is Diffuse, gloss samples) may need more
        // rounds than its depth.
        while (scene_.status().paths.x != ended_) {
            if (!branches_ || rounds >= kMaxSteps)
                throw GpuKernelError("the wavefront kernels left " + std::to_string(ended_ - scene_.status().paths.x) +
                                     " paths unfinished after " + std::to_string(rounds) + " rounds");
            submit(wave, [&](StageRecorder& r) { r.rounds(rounds, roundsPerSubmission_, shadows); });
            rounds += roundsPerSubmission_;
            stats_.dispatches += roundsPerSubmission_ * (shadows > 0 ? 4 : 2);
        }
        if (branches_) {
            submit(wave, [&](StageRecorder& r) { r.stage(gpu::WAVEFRONT_ACCUMULATE, accumulators); });
            ++stats_.dispatches;
        }
    }

private:
    void submit(const gpu::PassParams& wave, const std::function<void(StageRecorder&)>& record) {
        const double seconds = device_.runner.run([&](const vk::raii::CommandBuffer& commands) {
            StageRecorder recorder(commands, device_, scene_, pipelines_, wave);
            record(recorder);
            computeToHostBarrier(commands);
        });
        countSubmission(stats_, seconds, device_.runner.lastDeviceSeconds());
        throwIfKernelFailed(scene_.status(), width_, device_.context.info().loopLimiter);
    }

    const GpuRenderDevice& device_;
    SceneUpload& scene_;
    GpuRenderStats& stats_;
    WavefrontPathLayout layout_;
    bool branches_;
    bool appends_;  // GENERATE appends round 0's queue (adaptive) instead of writing every slot
    std::uint32_t width_;
    std::uint32_t roundsPerSubmission_ = 1;
    std::uint32_t ended_ = 0;  // paths ended so far, as the kernels count them (modulo 2^32)
    std::array<const vk::raii::Pipeline*, gpu::WAVEFRONT_STAGE_COUNT> pipelines_{};
};

}  // namespace

std::uint64_t targetWavePaths(const DeviceInfo& device) { return device.lavapipe ? (1u << 16) : (1u << 20); }

void renderWavefront(const GpuRenderDevice& device, SceneUpload& gpuScene, const GpuSceneData& data, const KernelInputs& in,
                     const RenderOptions& options, std::uint64_t wavePaths, GpuRenderStats& stats, std::vector<glm::vec4>& sums) {
    WaveRunner runner(device, gpuScene, data, in, options, stats);
    const std::uint64_t pixels = static_cast<std::uint64_t>(options.width) * options.height;
    const glm::ivec2 rows = rowsOf(options);
    std::vector<std::uint32_t> breaks;
    const std::vector<int> checkpoints = checkpointEnds(options.samplesPerPixel, options.checkpoints);
    if (options.onCheckpoint)
        for (const int end : checkpoints) breaks.push_back(static_cast<std::uint32_t>(end));
    // A wave holds a row at least (an image wider than the device's wave: the memory check refuses
    // what does not fit).
    const WavePlan plan = planWaves(static_cast<std::uint32_t>(options.width), static_cast<std::uint32_t>(rows.x),
                                    static_cast<std::uint32_t>(rows.y), static_cast<std::uint32_t>(options.samplesPerPixel),
                                    std::max<std::uint64_t>(runner.pathsPerWave(pixels, wavePaths), static_cast<std::uint64_t>(options.width)),
                                    breaks);

    auto start = Clock::now();
    gpuScene.beginWavefront(device.context, device.transfers, in.frame, plan.maxPaths * runner.layout().texelsPerPath());
    stats.uploadSeconds += secondsSince(start);
    stats.sceneBytes = gpuScene.bytes();

    const auto width = static_cast<std::uint32_t>(options.width);
    sums.assign(pixels, glm::vec4(0.0f));
    Progress progress("GPU render", options.quiet);
    std::size_t round = 0;
    start = Clock::now();
    for (std::size_t w = 0; w < plan.waves.size(); ++w) {
        throwIfCancelled(device.context, options);
        const Wave& wave = plan.waves[w];
        runner.run(passParams(wave.band, wave.firstSample, wave.samples), wave.paths(), wave.band.pixels());
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

void addSampleRangesWavefront(const GpuRenderDevice& device, SceneUpload& gpuScene, const GpuSceneData& data, const KernelInputs& in,
                              const RenderOptions& options, std::span<const glm::uvec4> contents, std::size_t pixels,
                              GpuRenderStats& stats) {
    WaveRunner runner(device, gpuScene, data, in, options, stats);
    const std::span<const glm::uvec4> work = contents.subspan(2 * pixels);
    const std::uint64_t pathsPerWave = std::max<std::uint64_t>(runner.pathsPerWave(contents.size(), 0), 1);
    auto start = Clock::now();
    gpuScene.beginAdaptiveRound(device.context, device.transfers, in.frame, contents, pathsPerWave * runner.layout().texelsPerPath());
    stats.uploadSeconds += secondsSince(start);

    // Sample offsets in runs: entries are sorted by samples to add, so those with more than `offset`
    // left are a prefix; each run takes as many offsets as fill a wave of that prefix.
    const std::uint32_t most = work.empty() ? 0u : work.front().z - work.front().y;
    Progress progress("GPU round", options.quiet);
    start = Clock::now();
    std::size_t active = work.size();
    for (std::uint32_t offset = 0; offset < most;) {
        while (active > 0 && work[active - 1].z - work[active - 1].y <= offset) --active;
        const auto samples = static_cast<std::uint32_t>(
            std::clamp<std::uint64_t>(pathsPerWave / active, 1, std::min(most - offset, kMaxWaveSamples)));
        const std::uint64_t entriesPerWave = std::max<std::uint64_t>(1, pathsPerWave / samples);
        for (std::size_t first = 0; first < active; first += entriesPerWave) {
            throwIfCancelled(device.context, options);
            const auto entries = static_cast<std::uint32_t>(std::min<std::uint64_t>(entriesPerWave, active - first));
            gpu::PassParams wave{};
            wave.tile = glm::uvec4(static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(work.size()), entries, 1u);
            wave.pass = glm::uvec4(offset, 0u, 0u, samples);
            runner.run(wave, static_cast<std::uint64_t>(entries) * samples, entries);
        }
        offset += samples;
        progress.update(static_cast<double>(offset) / most);
    }
    stats.renderSeconds = secondsSince(start);
    stats.nonFiniteSamples = gpu::statusNonFiniteSamples(gpuScene.status());
}

}  // namespace vkrt
