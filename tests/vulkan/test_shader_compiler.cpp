// Run-time GLSL compilation (--shader-dir): the same SPIR-V as the build, includes from the
// directory and DIR/shared, and errors that name file:line, also inside included files.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "kernel_source.h"
#include "shader_compiler.h"
#include "test_paths.h"
#include "vulkan_errors.h"
#include "vulkan_test_support.h"

namespace vkrt {
namespace {

namespace fs = std::filesystem;
using test::VulkanTest;

const fs::path kKernels = fs::path(test::sourceDir()) / "tests" / "vulkan" / "kernels";
const fs::path kShaders = fs::path(test::sourceDir()) / "shaders";

// A scratch shader directory, removed afterwards.
class ShaderDir {
public:
    explicit ShaderDir(const std::string& name) : path_(fs::temp_directory_path() / ("vkrt_" + name + "_" + std::to_string(::getpid()))) {
        fs::remove_all(path_);
        fs::create_directories(path_ / "shared");
    }
    ~ShaderDir() { fs::remove_all(path_); }
    void write(const std::string& file, const std::string& text) const { std::ofstream(path_ / file) << text; }
    void copy(const fs::path& from, const std::string& to) const { fs::copy_file(from, path_ / to, fs::copy_options::overwrite_existing); }
    const fs::path& path() const { return path_; }

private:
    fs::path path_;
};

std::string compileError(const fs::path& file, const std::vector<fs::path>& includes) {
    try {
        compileComputeShader(file, includes);
    } catch (const ShaderCompileError& e) {
        return e.what();
    }
    return "";
}

TEST(ShaderCompiler, RunTimeSpirvEqualsTheBuildsForTheSameSource) {
    const std::vector<std::uint32_t> runtime = compileComputeShader(kKernels / "camera_rays.comp", {kKernels, kShaders / "shared"});
    ASSERT_FALSE(runtime.empty());
    EXPECT_EQ(runtime[0], 0x07230203u);  // SPIR-V magic
    EXPECT_EQ(runtime, test::testKernel("camera_rays"));
}

TEST(ShaderCompiler, TheRenderKernelCompilesFromTheSourceTree) {
    // What `--shader-dir shaders` does: the repository's kernel with includes from shaders/ and
    // shaders/shared, as the build compiles it.
    const std::vector<std::uint32_t> spirv = compileComputeShader(kShaders / "render.comp", {kShaders, kShaders / "shared"});
    EXPECT_EQ(spirv.at(0), 0x07230203u);
    EXPECT_EQ(spirv, loadKernel({}));  // the embedded kernel
}

TEST(ShaderCompiler, ErrorNamesFileAndLine) {
    ShaderDir dir("broken");
    dir.write("broken.comp",
              "#version 460\n"
              "layout(local_size_x = 64) in;\n"
              "void main() {\n"
              "    uint x = 1u;\n"
              "    x = undefinedThing + 2u;\n"
              "}\n");
    const std::string message = compileError(dir.path() / "broken.comp", {dir.path()});
    EXPECT_NE(message.find("broken.comp:5:"), std::string::npos) << message;
    EXPECT_NE(message.find("undefinedThing"), std::string::npos) << message;
}

TEST(ShaderCompiler, ErrorInAnIncludeNamesTheIncludedFile) {
    ShaderDir dir("broken_include");
    dir.write("main.comp",
              "#version 460\n"
              "#extension GL_GOOGLE_include_directive : require\n"
              "#include \"helper.glsl\"\n"
              "layout(local_size_x = 64) in;\n"
              "void main() { helper(); }\n");
    dir.write("shared/helper.glsl",
              "// helper, found through DIR/shared\n"
              "void helper() {\n"
              "    float f = vec3(1.0);\n"
              "}\n");
    const std::string message = compileError(dir.path() / "main.comp", {dir.path(), dir.path() / "shared"});
    EXPECT_NE(message.find("helper.glsl:3:"), std::string::npos) << message;
}

TEST(ShaderCompiler, MissingIncludeIsReportedAtTheDirective) {
    ShaderDir dir("missing_include");
    dir.write("main.comp",
              "#version 460\n"
              "#extension GL_GOOGLE_include_directive : require\n"
              "#include \"nowhere.glsl\"\n"
              "layout(local_size_x = 64) in;\n"
              "void main() {}\n");
    const std::string message = compileError(dir.path() / "main.comp", {dir.path()});
    EXPECT_NE(message.find("main.comp:3:"), std::string::npos) << message;
    EXPECT_NE(message.find("nowhere.glsl"), std::string::npos) << message;
}

TEST(ShaderCompiler, MissingFileIsACompileError) {
    const std::string message = compileError("/nonexistent/vkrt/render.comp", {});
    EXPECT_NE(message.find("/nonexistent/vkrt/render.comp"), std::string::npos) << message;
}

TEST(KernelSource, UnknownEmbeddedKernelSaysWhatExists) {
    KernelSource source;
    source.name = "no_such_kernel";
    try {
        loadKernel(source);
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("no_such_kernel"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("render"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("--shader-dir"), std::string::npos);
    }
}

// A shader directory laid out like shaders/: render.comp at the top, device_host.h and
// sampling.h in shared/. The renderer compiles it at construction and renders the same image
// as the build-time SPIR-V of the same source.
TEST_F(VulkanTest, ShaderDirKernelRendersLikeTheEmbeddedOne) {
    ShaderDir dir("shader_dir");
    dir.copy(kKernels / "camera_rays.comp", "render.comp");
    dir.copy(kKernels / "test_bindings.glsl", "test_bindings.glsl");
    dir.copy(kShaders / "shared" / "device_host.h", "shared/device_host.h");
    dir.copy(kShaders / "shared" / "sampling.h", "shared/sampling.h");
    test::TinyScene tiny;
    const RenderOptions options = test::smallRender(20, 12, 2);
    const Image fromDir = renderer({.shaderDir = dir.path()}).render(tiny.gpu(), options);
    const Image embedded = renderer({}, {.kernelSpirv = test::testKernel("camera_rays")}).render(tiny.gpu(), options);
    EXPECT_EQ(fromDir.pixels, embedded.pixels);
    EXPECT_NE(fromDir.pixels[0], fromDir.pixels[1]);
}

TEST(GpuRenderer, BrokenShaderDirFailsAtConstructionWithFileAndLine) {
    ShaderDir dir("renderer_broken");
    dir.write("render.comp", "#version 460\nlayout(local_size_x = 64) in;\nvoid main() { syntax error }\n");
    try {
        GpuRenderer gpu({.shaderDir = dir.path()});
        FAIL() << "a broken kernel was accepted";
    } catch (const ShaderCompileError& e) {
        EXPECT_NE(std::string(e.what()).find("render.comp:3:"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace vkrt
