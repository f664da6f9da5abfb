#include "output_file.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include <unistd.h>

namespace vkrt {

namespace fs = std::filesystem;

std::string lowerExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

void checkOutputFolder(const std::string& path, const char* what) {
    const fs::path parent = fs::path(path).parent_path();
    const fs::path dir = parent.empty() ? fs::path(".") : parent;
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) throw std::runtime_error(path + ": the folder '" + dir.string() + "' does not exist");
    if (::access(dir.c_str(), W_OK) != 0) throw std::runtime_error(path + ": the folder '" + dir.string() + "' is not writable");
    if (fs::is_directory(path, ec)) throw std::runtime_error(path + ": is a folder, not " + what);
}

void checkNotTheInput(const std::string& output, const std::string& input) {
    std::error_code ec;
    if (fs::equivalent(output, input, ec))
        throw std::runtime_error(output + ": is the scene file itself; choose another output name (-o)");
}

void writeAtomically(const std::string& path, const std::function<void(const std::string& temporary)>& write) {
    // Same folder, so the rename is atomic (and relative paths inside resolve as in the result).
    const fs::path target(path);
    const fs::path temp = target.parent_path() / ("." + target.filename().string() + ".partial-" + std::to_string(::getpid()));
    try {
        write(temp.string());
        fs::rename(temp, target);
    } catch (...) {
        std::error_code ignored;
        fs::remove(temp, ignored);
        throw;
    }
}

}  // namespace vkrt
