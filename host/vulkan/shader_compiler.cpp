#include "shader_compiler.h"

#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include "vulkan_errors.h"

namespace vkrt {

namespace {

namespace fs = std::filesystem;

// glslang keeps process-wide tables; InitializeProcess/FinalizeProcess are reference-counted, so
// one guard per compilation is safe alongside any other glslang user in the process.
struct GlslangProcess {
    GlslangProcess() { glslang::InitializeProcess(); }
    ~GlslangProcess() { glslang::FinalizeProcess(); }
    GlslangProcess(const GlslangProcess&) = delete;
    GlslangProcess& operator=(const GlslangProcess&) = delete;
};

bool readFile(const fs::path& path, std::string& text) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::ostringstream contents;
    contents << in.rdbuf();
    text = contents.str();
    return true;
}

// Resolves includes from files on disk. Header names handed back to glslang are full paths, so
// glslang's messages for an included file name that file.
class DirectoryIncluder : public glslang::TShader::Includer {
public:
    explicit DirectoryIncluder(std::vector<fs::path> dirs) : dirs_(std::move(dirs)) {}

    IncludeResult* includeLocal(const char* header, const char* includer, size_t) override {
        return tryOpen(fs::path(includer).parent_path() / header);
    }
    IncludeResult* includeSystem(const char* header, const char*, size_t) override {
        for (const fs::path& dir : dirs_)
            if (IncludeResult* found = tryOpen(dir / header)) return found;
        return nullptr;  // glslang reports "cannot find include file" at the directive's file:line
    }
    void releaseInclude(IncludeResult* result) override {
        if (!result) return;
        delete static_cast<std::string*>(result->userData);
        delete result;
    }

private:
    IncludeResult* tryOpen(const fs::path& path) {
        auto text = std::make_unique<std::string>();
        if (!readFile(path, *text)) return nullptr;
        const std::string name = path.lexically_normal().string();
        const char* data = text->data();
        const size_t size = text->size();
        return new IncludeResult(name, data, size, text.release());
    }

    std::vector<fs::path> dirs_;
};

}  // namespace

std::vector<std::uint32_t> compileComputeShader(const fs::path& file, const std::vector<fs::path>& includeDirs) {
    std::string source;
    if (!readFile(file, source)) throw ShaderCompileError(file.string() + ":0: error: cannot read the shader file");

    GlslangProcess process;
    glslang::TShader shader(EShLangCompute);
    const std::string name = file.lexically_normal().string();
    const char* text = source.c_str();
    const int length = static_cast<int>(source.size());
    const char* names = name.c_str();
    shader.setStringsWithLengthsAndNames(&text, &length, &names, 1);
    shader.setEnvInput(glslang::EShSourceGlsl, EShLangCompute, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_2);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_5);  // what --target-env vulkan1.2 uses

    const auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
    DirectoryIncluder includer(includeDirs);
    if (!shader.parse(GetDefaultResources(), 460, false, messages, includer))
        throw ShaderCompileError("GLSL compile of " + name + " failed:\n" + shader.getInfoLog());

    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(messages)) throw ShaderCompileError("GLSL link of " + name + " failed:\n" + program.getInfoLog());

    std::vector<std::uint32_t> spirv;
    spv::SpvBuildLogger logger;
    glslang::GlslangToSpv(*program.getIntermediate(EShLangCompute), spirv, &logger);
    const std::string problems = logger.getAllMessages();
    if (spirv.empty()) throw ShaderCompileError("SPIR-V generation for " + name + " failed:\n" + problems);
    return spirv;
}

}  // namespace vkrt
