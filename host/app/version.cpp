#include "version.h"

namespace vkrt {

// Both come from host/app/CMakeLists.txt, as compile definitions of this file only.
std::string versionLine() {
    const std::string commit = VKRT_GIT_COMMIT;
    return std::string("vkrt ") + VKRT_VERSION + (commit.empty() ? "" : " (git " + commit + ")");
}

}  // namespace vkrt
