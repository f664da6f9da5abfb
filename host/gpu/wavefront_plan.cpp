#include "wavefront_plan.h"

#include <algorithm>
#include <stdexcept>

namespace vkrt {

WavefrontPathLayout wavefrontPathLayout(const SceneTables& tables, const FeatureSet& features, const gpu::FrameParams& frame) {
    const std::uint32_t k = frame.sampling.z;  // light samples (bindings.glsl frameLightSamples)
    WavefrontPathLayout layout;
    for (const gpu::Light& light : tables.lights) layout.shadowsPerPath += gpu::lightType(light) == gpu::LIGHT_AREA ? k : 1u;
    if (features.emitters && frame.lighting.x > 0) layout.shadowsPerPath += k;
    if (features.environment && frame.lighting.z > 0) layout.shadowsPerPath += k;
    layout.stackEntries = features.pathStackSize;
    return layout;
}

WavePlan planWaves(std::uint32_t width, std::uint32_t rowBegin, std::uint32_t rowEnd, std::uint32_t samples,
                   std::uint64_t pathsPerWave, const std::vector<std::uint32_t>& roundBreaks) {
    if (width == 0 || rowEnd <= rowBegin || samples == 0) return {};
    if (pathsPerWave < width) throw std::invalid_argument("wavefront: a wave must hold at least one row of paths");
    const std::uint32_t rows = rowEnd - rowBegin;
    const auto bandRows = static_cast<std::uint32_t>(std::min<std::uint64_t>(rows, pathsPerWave / width));
    const std::uint64_t bandPixels = static_cast<std::uint64_t>(bandRows) * width;
    const auto perWave =
        static_cast<std::uint32_t>(std::clamp<std::uint64_t>(pathsPerWave / bandPixels, 1, std::min(samples, kMaxWaveSamples)));
    WavePlan plan;
    for (std::uint32_t first = 0, count = 0; first < samples; first += count) {
        count = std::min(perWave, samples - first);
        for (const std::uint32_t end : roundBreaks)
            if (end > first && end < first + count) count = end - first;
        for (std::uint32_t y = rowBegin; y < rowEnd; y += bandRows) {
            Wave wave;
            wave.band = TileRect{0, y, width, std::min(bandRows, rowEnd - y)};
            wave.firstSample = first;
            wave.samples = count;
            plan.maxPaths = std::max(plan.maxPaths, wave.paths());
            plan.waves.push_back(wave);
        }
        plan.roundEnds.push_back(plan.waves.size());
    }
    return plan;
}

std::uint64_t wavePathsFor(const BufferLimits& limits, std::uint64_t pixels, const WavefrontPathLayout& layout,
                           std::uint32_t maxWorkgroups, std::uint64_t target) {
    // A quarter of the heap at most: the scene's tables share it. The kernels index texels with a
    // signed int, and the buffer's size is rounded up a little (stableTexelBufferBytes): margins.
    const std::uint64_t cap = std::min({limits.maxTexelBufferElements, limits.maxMemoryAllocationSize / 16, limits.heapBytes / 64,
                                        std::uint64_t{0x7fffffff}});
    const std::uint64_t texelLimit = cap > 64 ? cap - 64 : 0;
    const std::uint64_t free = texelLimit > pixels ? texelLimit - pixels : 0;
    std::uint64_t paths = std::min(target, free / layout.texelsPerPath());
    const std::uint64_t lanes = static_cast<std::uint64_t>(maxWorkgroups) * 64;
    paths = std::min(paths, lanes / std::max<std::uint32_t>(1, layout.shadowsPerPath));
    return paths;
}

}  // namespace vkrt
