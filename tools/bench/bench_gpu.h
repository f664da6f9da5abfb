// The two modes of `vkrt-bench gpu` (bench_gpu.cpp dispatches): ray throughput of trace_rays.comp
// against the CPU traversal and Embree, and whole renders of the course scenes.
#pragma once

#include <string>
#include <vector>

namespace vkrt::bench {

// `vkrt-bench gpu rays MESH.obj|sphere:N [W H SPP] [options]` (bench_gpu_rays.cpp).
int runGpuRaysBench(const std::vector<std::string>& args);
// `vkrt-bench gpu scenes [DIR] [-w W -h H -r RPP] [options]` (bench_gpu_scenes.cpp).
int runGpuScenesBench(const std::vector<std::string>& args);
// `vkrt-bench gpu kernels [SCENES|DIRS...] [options]` (bench_gpu_kernels.cpp).
int runGpuKernelsBench(const std::vector<std::string>& args);

}  // namespace vkrt::bench
