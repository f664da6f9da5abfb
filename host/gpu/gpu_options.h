// How the GPU side opens its device and finds its kernels: the product's options (the command
// line's --gpu, --validate, --shader-dir) and, apart, the hooks only tests set. GpuRenderer and
// GpuRayTracer both take these and turn them into the plumbing's options here, in one place.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "context.h"
#include "kernel_source.h"

namespace vkrt {

struct GpuRendererOptions {
    int gpu = -1;             // --gpu N (index of listDevices()); -1 chooses discrete > integrated > cpu
    bool validation = false;  // --validate: Khronos validation layers, messages in validationLog()
    bool fallBack = true;     // --device auto: a device that fails to open gives way to the next
                              // (with a note); --device gpu: it is an error
    std::optional<std::filesystem::path> shaderDir;  // --shader-dir: compile DIR/<kernel>.comp at run time
};

// Test hooks, never set by the product (VKRT_MAX_BUFFER_BYTES, read by Context, is the
// environment's form of maxBufferBytes for tests that run the vkrt binary).
struct GpuTestHooks {
    std::vector<std::uint32_t> kernelSpirv;       // this SPIR-V instead of the kernel
    std::optional<std::uint64_t> maxBufferBytes;  // cap the per-buffer device limits
    bool forceStaging = false;                    // staging copies even on a CPU device
};

ContextOptions contextOptions(const GpuRendererOptions& options, const GpuTestHooks& hooks);
// kernel: "render" or "trace_rays" (shaders/<kernel>.comp).
KernelSource kernelSource(const std::string& kernel, const GpuRendererOptions& options, const GpuTestHooks& hooks);

}  // namespace vkrt
