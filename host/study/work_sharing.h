// How a study's renders are shared among the processes of an MPI job (`mpirun -np N vkrt sweep ...`):
// rank 0 leads (reads the cache, writes every file), and the ranks exchange bytes through this
// interface, which the application implements over MPI (host/app/mpi_work_sharing.h). The study code
// needs no MPI: a single process passes none.
#pragma once

#include <cstddef>
#include <vector>

namespace vkrt::study {

class WorkSharing {
public:
    virtual ~WorkSharing() = default;
    virtual int rank() const = 0;
    virtual int size() const = 0;
    // Rank 0's `bytes` to every rank (resized there). Every rank must call it.
    virtual void broadcast(std::vector<std::byte>& bytes) = 0;
    // Every rank's bytes on rank 0, in rank order (empty on the other ranks). Every rank must call it.
    virtual std::vector<std::vector<std::byte>> gather(const std::vector<std::byte>& mine) = 0;
};

}  // namespace vkrt::study
