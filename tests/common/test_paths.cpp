#include "test_paths.h"

#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace vkrt::test {

namespace {

// The folder holding shaders/render.comp and scenes/, found from the test binary's own place:
// build/tests/<area>/ in a build tree, bin/ in a bundle (tools/bundle.sh copies both folders
// there). Never a path compiled into the binary, which is wrong once the binary is moved.
std::string findSourceDir() {
    if (const char* env = std::getenv("VKRT_SOURCE_DIR"); env && *env) return env;
    std::error_code ec;
    std::filesystem::path dir = std::filesystem::read_symlink("/proc/self/exe", ec).parent_path();
    for (; !ec && !dir.empty(); dir = dir.parent_path()) {
        if (std::filesystem::exists(dir / "shaders" / "render.comp", ec) && std::filesystem::is_directory(dir / "scenes", ec))
            return dir.string();
        if (dir == dir.root_path()) break;
    }
    throw std::runtime_error("no folder above the test binary holds shaders/render.comp and scenes/ (set VKRT_SOURCE_DIR)");
}

}  // namespace

std::string sharedDir() {
    if (const char* env = std::getenv("VKRT_SHARED"); env && *env) return env;
    return sourceDir() + "/../shared";
}

std::string upstreamDir() { return sharedDir() + "/scenes/upstream"; }

std::string jsonSceneDir() { return sharedDir() + "/scenes/json"; }

std::string sourceDir() {
    static const std::string dir = findSourceDir();
    return dir;
}

std::string artifactDir() {
    std::string dir = std::filesystem::current_path().string() + "/test_artifacts";
    std::filesystem::create_directories(dir);
    return dir;
}

std::filesystem::path freshArtifactDir(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::path(artifactDir()) / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace vkrt::test
