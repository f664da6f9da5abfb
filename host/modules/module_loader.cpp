#include "module_loader.h"

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include <dlfcn.h>

namespace vkrt {

const void* loadModule(const ModuleSearch& search, const std::function<std::string(void* entry, const void*& table)>& open,
                       const std::string& what) {
    std::vector<std::string> candidates;
    std::error_code ec;
    if (const char* env = std::getenv(search.envVariable.c_str()); env && *env) {
        candidates.push_back(env);  // the user's choice, and only it
    } else {
        const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
        if (!ec) {
            std::filesystem::path dir = exe.parent_path();
            for (int level = 0; level <= kModuleSearchLevels && !dir.empty(); ++level, dir = dir.parent_path()) {
                candidates.push_back((dir / search.file).string());
                if (dir == dir.root_path()) break;
            }
        }
    }
    std::string tried;
    for (const std::string& path : candidates) {
        if (!std::filesystem::exists(path, ec)) {
            tried += "\n  " + path + ": no such file";
            continue;
        }
        void* handle = dlopen(path.c_str(), RTLD_NOW | search.dlopenFlags);
        if (!handle) {
            tried += "\n  " + path + ": " + dlerror();
            continue;
        }
        void* entry = dlsym(handle, search.entry.c_str());
        const void* table = nullptr;
        const std::string refusal = entry ? open(entry, table) : "no " + search.entry + " entry point";
        if (refusal.empty() && table) return table;  // kept loaded for the process
        tried += "\n  " + path + ": " + refusal;
        dlclose(handle);
    }
    throw std::runtime_error("cannot load " + search.file + " (" + what + "); tried:" + tried);
}

}  // namespace vkrt
