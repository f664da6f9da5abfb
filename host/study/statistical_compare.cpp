#include "statistical_compare.h"

#include <algorithm>

namespace vkrt::study {

StatisticalComparison compareDevicesStatistically(StudyRenderer& renderer, const PreparedScene& scene,
                                                  const RenderOptions& options, const ZTestOptions& test) {
    StatisticalComparison out;
    out.cpuSeed = options.seed;
    out.gpuSeed = options.seed + 1u;

    out.gpuRpp = options.samplesPerPixel;
    out.cpuRpp = std::max(kMinReferenceRpp, kReferenceRppFactor * options.samplesPerPixel);
    RenderOptions cpuOptions = options;
    cpuOptions.seed = out.cpuSeed;
    cpuOptions.samplesPerPixel = out.cpuRpp;
    Image sampleVariance;
    const TimedRender cpu = renderer.render(Device::Cpu, scene, cpuOptions, &sampleVariance);

    RenderOptions gpuOptions = options;
    gpuOptions.seed = out.gpuSeed;
    const TimedRender gpu = renderer.render(Device::Gpu, scene, gpuOptions);

    out.test = zTest(gpu.image, cpu.image,
                     sumImages(varianceOfMean(sampleVariance, out.gpuRpp), varianceOfMean(sampleVariance, out.cpuRpp)), test);
    out.cpuSeconds = cpu.seconds;
    out.gpuSeconds = gpu.seconds;
    return out;
}

}  // namespace vkrt::study
