#include "mpi_work_sharing.h"

#include <numeric>
#include <stdexcept>
#include <string>

namespace vkrt {

void MpiWorkSharing::broadcast(std::vector<std::byte>& bytes) {
    std::string error;
    long long size = static_cast<long long>(bytes.size());  // first the size, so the others can make room
    if (!api_.broadcast(&size, sizeof size, error)) throw std::runtime_error(error);
    bytes.resize(static_cast<std::size_t>(size));
    if (size > 0 && !api_.broadcast(bytes.data(), size, error)) throw std::runtime_error(error);
}

std::vector<std::vector<std::byte>> MpiWorkSharing::gather(const std::vector<std::byte>& mine) {
    std::string error;
    std::vector<long long> counts(static_cast<std::size_t>(size_));
    if (!api_.allCounts(static_cast<long long>(mine.size()), counts.data(), error)) throw std::runtime_error(error);
    std::vector<std::byte> all(rank_ == 0 ? static_cast<std::size_t>(std::accumulate(counts.begin(), counts.end(), 0LL)) : 0);
    if (!api_.gatherBytes(mine.data(), static_cast<long long>(mine.size()), all.data(), counts.data(), error))
        throw std::runtime_error(error);
    std::vector<std::vector<std::byte>> parts;
    if (rank_ != 0) return parts;
    std::size_t at = 0;
    for (const long long count : counts) {
        parts.emplace_back(all.begin() + static_cast<std::ptrdiff_t>(at), all.begin() + static_cast<std::ptrdiff_t>(at + count));
        at += static_cast<std::size_t>(count);
    }
    return parts;
}

}  // namespace vkrt
