// The vkrt program: parses the command line and runs the command.
#pragma once

namespace vkrt {

// Returns the process exit code: 0 success, 1 bad scene or failed render, 2 usage error,
// 3 `compare` or `check` found the images different, 130 interrupted by Ctrl-C.
int runVkrt(int argc, const char* const* argv);

}  // namespace vkrt
