#include "mpi_ranks.h"

#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <string>

#include <dlfcn.h>

#include "module_loader.h"

namespace vkrt {

bool launchedAsMpiRank() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"})
        if (const char* v = std::getenv(name); v && *v) return true;
    return false;
}

const mpi::Api& mpiApi() {
    static std::once_flag once;
    static const mpi::Api* api = nullptr;
    static std::string failure;
    std::call_once(once, [] {
        try {
            // RTLD_GLOBAL: OpenMPI's own plugins resolve libmpi's symbols from the global scope.
            ModuleSearch search{"libvkrt_mpi.so", "VKRT_MPI_MODULE", VKRT_MPI_MODULE_PATH, "vkrt_mpi_api", RTLD_GLOBAL};
            api = static_cast<const mpi::Api*>(loadModule(
                search,
                [](void* entry, const void*& table) {
                    const mpi::Api* found = reinterpret_cast<decltype(&vkrt_mpi_api)>(entry)();
                    if (!found) return std::string("no API table");
                    if (found->version != mpi::kApiVersion)
                        return "API version " + std::to_string(found->version) + ", expected " + std::to_string(mpi::kApiVersion);
                    table = found;
                    return std::string();
                },
                "started by mpirun: the MPI ranks' module"));
        } catch (const std::exception& e) {
            failure = e.what();
        }
    });
    if (!api) throw std::runtime_error(failure);
    return *api;
}

}  // namespace vkrt
