// vkrt-bench SUBCOMMAND ...: measurement tools (not tests). See bench_command.h to add a subcommand.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "bench_command.h"

namespace {

struct Subcommand {
    const char* name;
    const char* usage;
    int (*run)(const std::vector<std::string>&);
};

constexpr Subcommand kSubcommands[] = {
    {"bvh", "bvh MESH.obj|sphere:N [W H SPP THREADS] [--peer PATH] [--build-peer] [--rounds R]\n"
            "               [--ctrav C] [--cisect C] [--max-leaf N] [--bins B]",
     vkrt::bench::runBvhBench},
    {"gpu", "gpu rays MESH.obj|sphere:N [W H SPP] [--rounds R] [--threads T] [--peer PATH | --build-peer | --no-peer]\n"
            "               [--max-mismatch-fraction F] [--shader-dir DIR]\n"
            "  vkrt-bench gpu scenes [DIR] [-w W] [-h H] [-r RPP] [--repeat N]\n"
            "  vkrt-bench gpu kernels [SCENES|DIRS...] [--general] [--adaptive] [--wavefront] [--gpu N] [--shader-dir DIR] [-k DEPTH]",
     vkrt::bench::runGpuBench},
    {"adaptive", "adaptive SCENE... [-w W] [--target E] [--reference-rpp R] [--min-rpp M]\n"
                 "               [--max-rpp M] [-k DEPTH] [--map-radius R] [--repeat N]",
     vkrt::bench::runAdaptiveBench},
};

void usage() {
    std::fprintf(stderr, "usage: vkrt-bench SUBCOMMAND ...\n");
    for (const Subcommand& s : kSubcommands) std::fprintf(stderr, "  vkrt-bench %s\n", s.usage);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        usage();
        return 2;
    }
    const std::string name = argv[1];
    for (const Subcommand& s : kSubcommands) {
        if (name != s.name) continue;
        try {
            return s.run(std::vector<std::string>(argv + 2, argv + argc));
        } catch (const std::exception& e) {
            std::fprintf(stderr, "vkrt-bench %s: %s\n", s.name, e.what());
            return 1;
        }
    }
    std::fprintf(stderr, "vkrt-bench: unknown subcommand '%s'\n", name.c_str());
    usage();
    return 2;
}
