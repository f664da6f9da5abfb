#include "gpu_options.h"

namespace vkrt {

ContextOptions contextOptions(const GpuRendererOptions& options, const GpuTestHooks& hooks) {
    ContextOptions c;
    c.gpu = options.gpu;
    c.validation = options.validation;
    c.fallBack = options.fallBack;
    c.maxBufferBytes = hooks.maxBufferBytes;
    c.forceStaging = hooks.forceStaging;
    return c;
}

KernelSource kernelSource(const std::string& kernel, const GpuRendererOptions& options, const GpuTestHooks& hooks) {
    KernelSource k;
    k.name = kernel;
    k.shaderDir = options.shaderDir;
    k.spirv = hooks.kernelSpirv;
    return k;
}

}  // namespace vkrt
