#include "kernel_modules.h"

#include "compute_pipeline.h"

namespace vkrt {

std::string stageKernelName(std::uint32_t stage, const std::string& render) {
    static const char* const names[] = {nullptr, "generate", "extend", "shade_record", "shadow", "shade_resolve", "accumulate"};
    return stage == gpu::WAVEFRONT_OFF ? render : "wavefront_" + std::string(names[stage]);
}

KernelModules::KernelModules(const Context& context, const KernelSource& source, const std::vector<std::uint32_t>& renderSpirv)
    : context_(context), source_(source) {
    modules_[gpu::WAVEFRONT_OFF].emplace(makeShaderModule(context, renderSpirv));
}

const vk::raii::ShaderModule& KernelModules::module(std::uint32_t stage) {
    std::optional<vk::raii::ShaderModule>& m = modules_.at(stage);
    if (!m) {
        KernelSource stageSource;
        stageSource.name = stageKernelName(stage);
        stageSource.shaderDir = source_.shaderDir;
        m.emplace(makeShaderModule(context_, loadKernel(stageSource)));
    }
    return *m;
}

}  // namespace vkrt
