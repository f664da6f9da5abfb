// Where tests find their inputs.
#pragma once
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

// In a test body: skips the test, naming what is missing, when `path` (an input under ../shared) does
// not exist. With VKRT_REQUIRE_SHARED=1 (the README's and CI's test command, where nothing may be
// missing) the same message is a failure instead.
#define VKRT_SKIP_WITHOUT(path)                                                                         \
    do {                                                                                                \
        const std::string vkrt_needed_ = (path);                                                        \
        if (!std::filesystem::exists(vkrt_needed_)) {                                                   \
            if (vkrt::test::sharedRequired()) FAIL() << "missing " << vkrt_needed_ << vkrt::test::kSharedHint; \
            GTEST_SKIP() << "missing " << vkrt_needed_ << vkrt::test::kSharedHint;                     \
        }                                                                                               \
    } while (0)

namespace vkrt::test {
inline constexpr const char* kSharedHint =
    " (the shared scenes: put shared/ beside the repository or set VKRT_SHARED)";
// VKRT_REQUIRE_SHARED=1: a missing input fails the test instead of skipping it.
inline bool sharedRequired() {
    const char* v = std::getenv("VKRT_REQUIRE_SHARED");
    return v != nullptr && std::string(v) == "1";
}
// $VKRT_SHARED when set, else ../shared beside sourceDir().
std::string sharedDir();
// ../shared/scenes/upstream
std::string upstreamDir();
// ../shared/scenes/json: the course's JSON scenes (SOURCES.md there)
std::string jsonSceneDir();
// The repository root, or a bundle's root (for scenes/ and shaders/): $VKRT_SOURCE_DIR when set,
// else the nearest folder above the test binary that holds shaders/render.comp and scenes/.
std::string sourceDir();
// A scratch directory for test outputs (created on demand; kept after a failure as an artefact).
std::string artifactDir();
// artifactDir()/name, emptied of an earlier run's files and made.
std::filesystem::path freshArtifactDir(const std::string& name);
}  // namespace vkrt::test
