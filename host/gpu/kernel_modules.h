// The render kernels' shader modules: render.comp (the megakernel) made at once, and each
// wavefront stage's (shaders/wavefront_<stage>.comp) on first use, from the same place: embedded,
// or compiled from --shader-dir. FeatureSet::wavefrontStage picks one.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan_raii.hpp>

#include "context.h"
#include "device_host.h"
#include "kernel_source.h"

namespace vkrt {

// "wavefront_generate", ... for gpu::WAVEFRONT_*; `render` for WAVEFRONT_OFF.
std::string stageKernelName(std::uint32_t stage, const std::string& render = "render");

class KernelModules {
public:
    // `source` says where render.comp comes from (its SPIR-V handed over, embedded or compiled);
    // the stages come from the same shader directory, or are embedded.
    KernelModules(const Context& context, const KernelSource& source, const std::vector<std::uint32_t>& renderSpirv);
    // Throws as loadKernel does (a stage's GLSL that does not compile) on a stage's first use.
    const vk::raii::ShaderModule& module(std::uint32_t stage);

private:
    const Context& context_;
    KernelSource source_;
    std::array<std::optional<vk::raii::ShaderModule>, gpu::WAVEFRONT_STAGE_COUNT> modules_;
};

}  // namespace vkrt
