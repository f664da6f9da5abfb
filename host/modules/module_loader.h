// vkrt's optional parts that pull in many libraries (OpenImageIO's image I/O, OpenMPI) are shared
// modules loaded at run time, so a run that does not need them never maps them (docs/STARTUP.md).
// This finds and opens one.
#pragma once

#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>

namespace vkrt {

inline constexpr int kModuleSearchLevels = 3;

struct ModuleSearch {
    std::string file;          // "libvkrt_oiio.so"
    std::string envVariable;   // names the module's path; when set, only that path is tried
    std::string entry;         // the extern "C" function returning the module's table
    int dlopenFlags = 0;       // RTLD_LOCAL or RTLD_GLOBAL, or-ed with RTLD_NOW
};

// The first loadable candidate's table: $envVariable when set, else beside the running
// executable, then in the folders above it, up to kModuleSearchLevels (a test binary in
// build/tests/<area>/ finds the build's modules in build/). Never a path compiled into the
// binary: a bundle moved to another machine must not load, or silently miss, a build tree's. `open` gets the entry point's address, calls it as the module's own
// function type (a call through another type is undefined: UBSan's -fsanitize=function says so)
// and returns "" with `table` set, or why it refuses the module. Throws std::runtime_error with
// `what` and every candidate tried, each with its reason.
const void* loadModule(const ModuleSearch& search, const std::function<std::string(void* entry, const void*& table)>& open,
                       const std::string& what);

// The module's table, loaded on the first call and kept for the process: its entry has the type
// `const Table* (*)()` and the table's `version` must be `version`. Every call after a failure
// throws the same std::runtime_error.
template <class Table>
const Table& moduleTable(const ModuleSearch& search, int version, const std::string& what) {
    static std::once_flag once;
    static const Table* table = nullptr;
    static std::string failure;
    std::call_once(once, [&] {
        try {
            table = static_cast<const Table*>(loadModule(
                search,
                [version](void* entry, const void*& out) {
                    const Table* found = reinterpret_cast<const Table* (*)()>(entry)();
                    if (!found) return std::string("its entry returned no table");
                    if (found->version != version)
                        return "version " + std::to_string(found->version) + ", expected " + std::to_string(version);
                    out = found;
                    return std::string();
                },
                what));
        } catch (const std::exception& e) {
            failure = e.what();
        }
    });
    if (!table) throw std::runtime_error(failure);
    return *table;
}

}  // namespace vkrt
