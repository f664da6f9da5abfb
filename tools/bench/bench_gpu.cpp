// `vkrt-bench gpu rays|scenes ...`: the GPU path's benchmark; each mode lives in its own file.
#include <stdexcept>

#include "bench_command.h"
#include "bench_gpu.h"

namespace vkrt::bench {

int runGpuBench(const std::vector<std::string>& args) {
    if (!args.empty() && args[0] == "rays") return runGpuRaysBench({args.begin() + 1, args.end()});
    if (!args.empty() && args[0] == "scenes") return runGpuScenesBench({args.begin() + 1, args.end()});
    if (!args.empty() && args[0] == "kernels") return runGpuKernelsBench({args.begin() + 1, args.end()});
    throw std::runtime_error("usage: vkrt-bench gpu rays MESH.obj|sphere:N [W H SPP] ... | vkrt-bench gpu scenes [DIR] ... | "
                             "vkrt-bench gpu kernels [SCENES|DIRS...] ...");
}

}  // namespace vkrt::bench
