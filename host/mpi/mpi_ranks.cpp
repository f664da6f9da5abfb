#include "mpi_ranks.h"

#include <cstdlib>

#include <dlfcn.h>

#include "module_loader.h"

namespace vkrt {

bool launchedAsMpiRank() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"})
        if (const char* v = std::getenv(name); v && *v) return true;
    return false;
}

const mpi::Api& mpiApi() {
    // RTLD_GLOBAL: OpenMPI's own plugins resolve libmpi's symbols from the global scope.
    return moduleTable<mpi::Api>({"libvkrt_mpi.so", "VKRT_MPI_MODULE", "vkrt_mpi_api", RTLD_GLOBAL},
                                 mpi::kApiVersion, "started by mpirun: the MPI ranks' module");
}

}  // namespace vkrt
