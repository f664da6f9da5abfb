// Run-time GLSL -> SPIR-V through the glslang library, for `--shader-dir DIR`: shader developers
// edit GLSL and re-run without rebuilding the program. The same compiler (glslang, Vulkan 1.2
// target) compiles the embedded kernels at build time, so both paths accept the same GLSL.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace vkrt {

// Compiles one compute shader. `#include "x"` (GL_GOOGLE_include_directive) is resolved in the
// including file's directory first, then in `includeDirs` in order.
// Throws ShaderCompileError with glslang's messages, each as "file:line: error"; a missing file
// or include is reported the same way.
std::vector<std::uint32_t> compileComputeShader(const std::filesystem::path& file,
                                                const std::vector<std::filesystem::path>& includeDirs);

}  // namespace vkrt
