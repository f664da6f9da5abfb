// How the wavefront renderer (wavefront_renderer.h) cuts a render into waves and lays out a
// wave's paths in the accumulation buffer (shaders/wavefront_state.glsl). No device needed.
#pragma once

#include <cstdint>
#include <vector>

#include "device_host.h"
#include "device_limits.h"
#include "feature_set.h"
#include "scene_tables.h"
#include "tile_planner.h"

namespace vkrt {

// One path's texels (shaders/wavefront_state.glsl): six fields, two per shadow ray of a hit, three
// per pending ray of its stack; then its entries in the queues: one in each of the two path queues,
// one per shadow ray in the shadow queue.
struct WavefrontPathLayout {
    std::uint32_t shadowsPerPath = 0;  // the most shadow rays one hit can ask for
    std::uint32_t stackEntries = 0;    // FeatureSet::pathStackSize
    std::uint32_t texelsPerPath() const { return 6 + 2 * shadowsPerPath + 3 * stackEntries + 2 + shadowsPerPath; }
};

// The most shadow rays shadeRay (shaders/integrator.glsl) asks for at one hit: one per point light,
// k per area light, k for the shape emitters together, k for the environment map.
WavefrontPathLayout wavefrontPathLayout(const SceneTables& tables, const FeatureSet& features, const gpu::FrameParams& frame);

// A wave: the band's pixels times samples [firstSample, firstSample + samples).
struct Wave {
    TileRect band;
    std::uint32_t firstSample = 0;
    std::uint32_t samples = 0;
    std::uint64_t paths() const { return band.pixels() * samples; }
};

struct WavePlan {
    std::vector<Wave> waves;           // in order: every band of a run of samples, then the next run
    std::vector<std::size_t> roundEnds;  // after waves[0 .. end) every pixel has the same samples
    std::uint64_t maxPaths = 0;        // the largest wave's paths (the state's size)
};

// Waves of at most `pathsPerWave` paths over rows [rowBegin, rowEnd) of a `width`-wide image at
// `samples` per pixel: whole rows, as many samples of them as fit, in sample order per pixel. A
// round of waves also ends at each sample count in `roundBreaks` (progressive checkpoints).
WavePlan planWaves(std::uint32_t width, std::uint32_t rowBegin, std::uint32_t rowEnd, std::uint32_t samples,
                   std::uint64_t pathsPerWave, const std::vector<std::uint32_t>& roundBreaks = {});

// The most samples of one pixel a wave holds: ACCUMULATE sums them in one loop, which must stay
// far below LOOP_BUDGET with lavapipe's lockstep factor (sample_batching.h).
inline constexpr std::uint32_t kMaxWaveSamples = 4096;

// Paths per wave on a device: `target` (enough to fill it), fewer where one path's texels after
// the image's sums would not fit the accumulation buffer's limits or the SHADOW stage's dispatch
// (maxWorkgroups of 64 lanes) could not cover its rays.
std::uint64_t wavePathsFor(const BufferLimits& limits, std::uint64_t pixels, const WavefrontPathLayout& layout,
                           std::uint32_t maxWorkgroups, std::uint64_t target);

}  // namespace vkrt
