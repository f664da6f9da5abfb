// vkrt-bench subcommands. Each lives in its own file and is listed in main.cpp's table; to add
// one (say `foo`), write `int runFooBench(const std::vector<std::string>& args)` in bench_foo.cpp,
// declare it here, add a row to the table in main.cpp and the file to tools/CMakeLists.txt.
#pragma once

#include <string>
#include <vector>

namespace vkrt::bench {

// args: everything after the subcommand name. Returns the process exit code.
int runBvhBench(const std::vector<std::string>& args);
int runGpuBench(const std::vector<std::string>& args);
int runAdaptiveBench(const std::vector<std::string>& args);

}  // namespace vkrt::bench
