// Where the render kernel's SPIR-V comes from: embedded at build time (the default), compiled at
// run time from a shader directory (--shader-dir), or handed over directly (tests' own kernels).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace vkrt {

struct KernelSource {
    std::string name = "render";                     // <name>.comp
    std::optional<std::filesystem::path> shaderDir;  // compile DIR/<name>.comp, includes from DIR and DIR/shared
    std::vector<std::uint32_t> spirv;                // non-empty: use exactly this module
};

// Throws ShaderCompileError (run-time compile) or std::runtime_error (no such embedded kernel).
std::vector<std::uint32_t> loadKernel(const KernelSource& source);

}  // namespace vkrt
