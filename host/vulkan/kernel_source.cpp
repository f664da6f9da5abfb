#include "kernel_source.h"

#include <stdexcept>

#include "embedded_spirv.h"
#include "shader_compiler.h"

namespace vkrt {

std::vector<std::uint32_t> loadKernel(const KernelSource& source) {
    if (!source.spirv.empty()) return source.spirv;
    if (source.shaderDir) {
        const std::filesystem::path& dir = *source.shaderDir;
        return compileComputeShader(dir / (source.name + ".comp"), {dir, dir / "shared"});
    }
    for (const EmbeddedSpirv& kernel : embeddedKernels())
        if (kernel.name == source.name) return {kernel.words.begin(), kernel.words.end()};
    std::string known;
    for (const EmbeddedSpirv& kernel : embeddedKernels()) known += (known.empty() ? "" : ", ") + std::string(kernel.name);
    throw std::runtime_error("no embedded kernel '" + source.name + "' (built from shaders/" + source.name +
                             ".comp; embedded: " + (known.empty() ? "none" : known) + "); pass --shader-dir DIR to compile it at run time");
}

}  // namespace vkrt
