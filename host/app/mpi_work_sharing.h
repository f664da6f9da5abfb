// study::WorkSharing over the ranks of an MPI job (mpi_api.h), for `mpirun -np N vkrt sweep ...`.
#pragma once

#include "mpi_api.h"
#include "work_sharing.h"

namespace vkrt {

class MpiWorkSharing : public study::WorkSharing {
public:
    MpiWorkSharing(const mpi::Api& api, int rank, int size) : api_(api), rank_(rank), size_(size) {}
    int rank() const override { return rank_; }
    int size() const override { return size_; }
    // Throw std::runtime_error naming the MPI call when it fails.
    void broadcast(std::vector<std::byte>& bytes) override;
    std::vector<std::vector<std::byte>> gather(const std::vector<std::byte>& mine) override;

private:
    const mpi::Api& api_;
    int rank_, size_;
};

}  // namespace vkrt
