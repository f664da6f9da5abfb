// Whether this process is one rank of an MPI job, and the MPI module when it is (mpi_api.h).
#pragma once

#include "mpi_api.h"

namespace vkrt {

// The environment mpirun (OpenMPI, or a PMI/PMIx launcher such as srun) gives its ranks.
bool launchedAsMpiRank();

// libvkrt_mpi.so's table, loaded with RTLD_GLOBAL (OpenMPI's own plugins resolve libmpi's symbols
// from the global scope). Looked for at $VKRT_MPI_MODULE when set (only there), else beside the
// executable, then the folders above it (module_loader.h); throws std::runtime_error naming what was tried.
const mpi::Api& mpiApi();

}  // namespace vkrt
