// Where tests find their inputs.
#pragma once
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

// In a test body: skips the test, naming what is missing, when `path` (an input under ../shared) does
// not exist. tools/run_tests.sh, the README's and CI's test command, fails on any skip.
#define VKRT_SKIP_WITHOUT(path)                                                                         \
    do {                                                                                                \
        const std::string vkrt_needed_ = (path);                                                        \
        if (!std::filesystem::exists(vkrt_needed_))                                                     \
            GTEST_SKIP() << "missing " << vkrt_needed_                                                  \
                         << " (the shared scenes: put shared/ beside the repository or set VKRT_SHARED)"; \
    } while (0)

namespace vkrt::test {
// ../shared beside the repository, or $VKRT_SHARED when set.
std::string sharedDir();
// ../shared/scenes/upstream
std::string upstreamDir();
// ../shared/scenes/json: the course's JSON scenes (SOURCES.md there)
std::string jsonSceneDir();
// The repository root (for scenes/ and shaders/).
std::string sourceDir();
// A scratch directory for test outputs (created on demand; kept after a failure as an artefact).
std::string artifactDir();
}  // namespace vkrt::test
