// The MPI side of vkrt (`mpirun -np N vkrt scene.xml ...`), built as a module of its own
// (libvkrt_mpi.so) and loaded only when the process was started by mpirun (mpi_ranks.h): OpenMPI's
// libraries stay out of every other run's start-up (docs/STARTUP.md).
//
// A table of functions behind one extern "C" entry point, as host/image/oiio_codec.h.
#pragma once

#include <string>

namespace vkrt::mpi {

inline constexpr int kApiVersion = 2;

struct Api {
    int version;
    // MPI_Init; this process's rank, the world's size and the rank among those on this machine
    // (OpenMPI's local rank). false with `error` when MPI cannot start.
    bool (*init)(int* rank, int* size, int* localRank, std::string& error);
    // Rank 0 receives every rank's floats in rank order (MPI_Gatherv); `all` is read on rank 0 only.
    bool (*gather)(const float* mine, long long count, float* all, const long long* counts, std::string& error);
    // Every rank's count of floats, on every rank (MPI_Allgather).
    bool (*allCounts)(long long mine, long long* counts, std::string& error);
    // Rank 0's `bytes` bytes at `data` to every rank (MPI_Bcast).
    bool (*broadcast)(void* data, long long bytes, std::string& error);
    // Rank 0 receives every rank's bytes in rank order (MPI_Gatherv); `all` is read on rank 0 only.
    bool (*gatherBytes)(const void* mine, long long bytes, void* all, const long long* counts, std::string& error);
    // Ends every rank of the job with this exit code (MPI_Abort): one rank's error never leaves
    // the others waiting.
    void (*abortAll)(int code);
    void (*finalize)();
};

}  // namespace vkrt::mpi

extern "C" const vkrt::mpi::Api* vkrt_mpi_api();
