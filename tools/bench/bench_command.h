// vkrt-bench subcommands. Each lives in its own file and is listed in main.cpp's table; to add
// one (e.g. `gpu`), write `int runGpuBench(const std::vector<std::string>& args)` in bench_gpu.cpp,
// declare it here, add a row to the table in main.cpp and the file to tools/CMakeLists.txt.
#pragma once

#include <string>
#include <vector>

namespace vkrt::bench {

// args: everything after the subcommand name. Returns the process exit code.
int runBvhBench(const std::vector<std::string>& args);

}  // namespace vkrt::bench
