// Where tests find their inputs.
#pragma once
#include <string>

namespace vkrt::test {
// ../shared beside the repository, or $VKRT_SHARED when set.
std::string sharedDir();
// ../shared/scenes/upstream
std::string upstreamDir();
// The repository root (for scenes/ and shaders/).
std::string sourceDir();
// A scratch directory for test outputs (created on demand; kept after a failure as an artefact).
std::string artifactDir();
}  // namespace vkrt::test
