#include "kernel_layouts.h"

#include <array>

#include "device_host.h"

namespace vkrt {

KernelLayout renderLayout(const Context& context) {
    using T = vk::DescriptorType;
    const std::array bindings = {
        computeBinding(gpu::BINDING_NODES, T::eStorageTexelBuffer),
        computeBinding(gpu::BINDING_PRIMS, T::eStorageTexelBuffer),
        computeBinding(gpu::BINDING_PRIM_INFO, T::eStorageTexelBuffer),
        computeBinding(gpu::BINDING_VERTEX_ATTRIBS, T::eStorageTexelBuffer),
        computeBinding(gpu::BINDING_INSTANCES, T::eStorageTexelBuffer),
        computeBinding(gpu::BINDING_SHADERS, T::eStorageTexelBuffer),
        computeBinding(gpu::BINDING_LIGHTS, T::eStorageTexelBuffer),
        computeBinding(gpu::BINDING_TEXTURES, T::eStorageTexelBuffer),
        computeBinding(gpu::BINDING_TEXELS, T::eStorageTexelBuffer),
        computeBinding(gpu::BINDING_FRAME, T::eUniformBuffer),
        computeBinding(gpu::BINDING_ACCUM, T::eStorageTexelBuffer),
        computeBinding(gpu::BINDING_STATUS, T::eStorageBuffer),
        computeBinding(gpu::BINDING_EMITTERS, T::eStorageTexelBuffer),
        computeBinding(gpu::BINDING_EMITTER_TRIANGLES, T::eStorageTexelBuffer),
        computeBinding(gpu::BINDING_ENVIRONMENT, T::eStorageTexelBuffer),
        computeBinding(gpu::BINDING_ENVIRONMENT_CDF, T::eStorageTexelBuffer),
    };
    return KernelLayout(context, bindings, sizeof(gpu::PassParams));
}

KernelLayout traceLayout(const Context& context) {
    using T = vk::DescriptorType;
    const std::array bindings = {
        computeBinding(gpu::BINDING_NODES, T::eStorageTexelBuffer),
        computeBinding(gpu::BINDING_PRIMS, T::eStorageTexelBuffer),
        computeBinding(gpu::BINDING_INSTANCES, T::eStorageTexelBuffer),
        computeBinding(gpu::BINDING_FRAME, T::eUniformBuffer),
        computeBinding(gpu::BINDING_STATUS, T::eStorageBuffer),
        computeBinding(gpu::BINDING_RAYS, T::eStorageTexelBuffer),
        computeBinding(gpu::BINDING_HITS, T::eStorageTexelBuffer),
    };
    return KernelLayout(context, bindings, sizeof(gpu::TraceParams));
}

}  // namespace vkrt
