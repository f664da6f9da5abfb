#include "mpi_ranks.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <vector>

#include <dlfcn.h>

namespace vkrt {

bool launchedAsMpiRank() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"})
        if (const char* v = std::getenv(name); v && *v) return true;
    return false;
}

namespace {

const mpi::Api* load() {
    std::vector<std::string> candidates;
    std::error_code ec;
    if (const char* env = std::getenv("VKRT_MPI_MODULE"); env && *env) {
        candidates.push_back(env);
    } else {
        const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
        if (!ec) candidates.push_back((exe.parent_path() / "libvkrt_mpi.so").string());
#ifdef VKRT_MPI_MODULE_PATH
        candidates.push_back(VKRT_MPI_MODULE_PATH);
#endif
    }
    std::string tried;
    for (std::size_t k = 0; k < candidates.size(); ++k) {
        const std::string& path = candidates[k];
        if (std::find(candidates.begin(), candidates.begin() + static_cast<std::ptrdiff_t>(k), path) != candidates.begin() + static_cast<std::ptrdiff_t>(k))
            continue;  // the build tree is also the executable's folder
        if (!std::filesystem::exists(path, ec)) {
            tried += "\n  " + path + ": no such file";
            continue;
        }
        void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
        if (!handle) {
            tried += "\n  " + path + ": " + dlerror();
            continue;
        }
        using Entry = const mpi::Api* (*)();
        const auto entry = reinterpret_cast<Entry>(dlsym(handle, "vkrt_mpi_api"));
        const mpi::Api* api = entry ? entry() : nullptr;
        if (api && api->version == mpi::kApiVersion) return api;
        tried += "\n  " + path + ": not vkrt's MPI module of version " + std::to_string(mpi::kApiVersion);
        dlclose(handle);
    }
    throw std::runtime_error("started by mpirun, but cannot load libvkrt_mpi.so; tried:" + tried);
}

}  // namespace

const mpi::Api& mpiApi() {
    static std::once_flag once;
    static const mpi::Api* api = nullptr;
    static std::string failure;
    std::call_once(once, [] {
        try {
            api = load();
        } catch (const std::exception& e) {
            failure = e.what();
        }
    });
    if (!api) throw std::runtime_error(failure);
    return *api;
}

}  // namespace vkrt
