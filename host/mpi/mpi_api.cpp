// libvkrt_mpi.so: mpi_api.h's table, implemented with OpenMPI's C API.
#include "mpi_api.h"

#include <cstdlib>
#include <vector>

#include <mpi.h>

namespace vkrt::mpi {
namespace {

std::string errorText(int code) {
    char text[MPI_MAX_ERROR_STRING];
    int length = 0;
    MPI_Error_string(code, text, &length);
    return std::string(text, static_cast<std::size_t>(length));
}

bool init(int* rank, int* size, int* localRank, std::string& error) {
    int initialised = 0;
    MPI_Initialized(&initialised);
    if (!initialised) {
        if (const int code = MPI_Init(nullptr, nullptr); code != MPI_SUCCESS) {
            error = "MPI_Init: " + errorText(code);
            return false;
        }
    }
    MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
    MPI_Comm_rank(MPI_COMM_WORLD, rank);
    MPI_Comm_size(MPI_COMM_WORLD, size);
    MPI_Comm local;
    MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, *rank, MPI_INFO_NULL, &local);
    MPI_Comm_rank(local, localRank);
    MPI_Comm_free(&local);
    return true;
}

// Counts travel as MPI_LONG_LONG; chunks below 2^31 (MPI's int counts) are not needed at these
// image sizes, so one Gatherv with int counts, checked.
bool gatherOf(MPI_Datatype type, const void* mine, long long count, void* all, const long long* counts, std::string& error) {
    int size = 0;
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    std::vector<int> sizes(static_cast<std::size_t>(size)), offsets(static_cast<std::size_t>(size));
    long long offset = 0;
    for (int r = 0; r < size; ++r) {
        if (counts[r] > 0x7fffffffLL || offset > 0x7fffffffLL) {
            error = "a gather of more than 2^31 values (MPI's int counts)";
            return false;
        }
        sizes[static_cast<std::size_t>(r)] = static_cast<int>(counts[r]);
        offsets[static_cast<std::size_t>(r)] = static_cast<int>(offset);
        offset += counts[r];
    }
    const int code = MPI_Gatherv(mine, static_cast<int>(count), type, all, sizes.data(), offsets.data(), type, 0,
                                 MPI_COMM_WORLD);
    if (code != MPI_SUCCESS) error = "MPI_Gatherv: " + errorText(code);
    return code == MPI_SUCCESS;
}

bool gather(const float* mine, long long count, float* all, const long long* counts, std::string& error) {
    return gatherOf(MPI_FLOAT, mine, count, all, counts, error);
}

bool gatherBytes(const void* mine, long long bytes, void* all, const long long* counts, std::string& error) {
    return gatherOf(MPI_BYTE, mine, bytes, all, counts, error);
}

bool broadcast(void* data, long long bytes, std::string& error) {
    if (bytes > 0x7fffffffLL) {
        error = "a broadcast of more than 2^31 bytes (MPI's int counts)";
        return false;
    }
    const int code = MPI_Bcast(data, static_cast<int>(bytes), MPI_BYTE, 0, MPI_COMM_WORLD);
    if (code != MPI_SUCCESS) error = "MPI_Bcast: " + errorText(code);
    return code == MPI_SUCCESS;
}

bool allCounts(long long mine, long long* counts, std::string& error) {
    const int code = MPI_Allgather(&mine, 1, MPI_LONG_LONG, counts, 1, MPI_LONG_LONG, MPI_COMM_WORLD);
    if (code != MPI_SUCCESS) error = "MPI_Allgather: " + errorText(code);
    return code == MPI_SUCCESS;
}

void abortAll(int code) { MPI_Abort(MPI_COMM_WORLD, code); }

void finalize() {
    int finalised = 0;
    MPI_Finalized(&finalised);
    if (!finalised) MPI_Finalize();
}

constexpr Api kApi{kApiVersion, init, gather, allCounts, broadcast, gatherBytes, abortAll, finalize};

}  // namespace
}  // namespace vkrt::mpi

extern "C" const vkrt::mpi::Api* vkrt_mpi_api() { return &vkrt::mpi::kApi; }
