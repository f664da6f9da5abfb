// SPIR-V compiled at build time and linked into the binary (shaders/CMakeLists.txt,
// vkrt_embed_spirv), so the program needs no shader files at run time.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace vkrt {

struct EmbeddedSpirv {
    std::string_view name;                 // the source file name without .comp
    std::span<const std::uint32_t> words;  // the SPIR-V module
};

// The product kernels, every shaders/*.comp (library vkrt_kernels).
std::span<const EmbeddedSpirv> embeddedKernels();

}  // namespace vkrt
