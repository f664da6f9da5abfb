#include "test_paths.h"

#include <cstdlib>
#include <filesystem>

namespace vkrt::test {

std::string sharedDir() {
    if (const char* env = std::getenv("VKRT_SHARED"); env && *env) return env;
    return VKRT_DEFAULT_SHARED_DIR;
}

std::string upstreamDir() { return sharedDir() + "/scenes/upstream"; }

std::string jsonSceneDir() { return sharedDir() + "/scenes/json"; }

std::string sourceDir() { return VKRT_SOURCE_DIR; }

std::string artifactDir() {
    std::string dir = std::filesystem::current_path().string() + "/test_artifacts";
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace vkrt::test
