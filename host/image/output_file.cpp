#include "output_file.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <mutex>
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

namespace {

// The temporary being written, for a signal handler to remove: a fixed buffer (a handler may not
// allocate) published by an atomic flag. One write at a time per process is what vkrt does; a
// second concurrent writer simply is not registered.
char g_temporary[4096];
std::atomic<bool> g_temporarySet{false};

extern "C" void removeTemporaryAndDie(int signal) {
    removeTemporaryBeingWritten();
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

// SIGTERM and SIGHUP (a batch scheduler's kill, a closed terminal) end the process by default;
// they first remove the temporary. A disposition someone else set (ignore, a handler) is kept.
void installTerminationCleanup() {
    static std::once_flag once;
    std::call_once(once, [] {
        for (int signal : {SIGTERM, SIGHUP}) {
            struct sigaction current {};
            if (::sigaction(signal, nullptr, &current) == 0 && current.sa_handler == SIG_DFL)
                std::signal(signal, removeTemporaryAndDie);
        }
    });
}

class RegisteredTemporary {
public:
    explicit RegisteredTemporary(const fs::path& temp) {
        const std::string& text = temp.native();
        if (text.size() < sizeof g_temporary && !g_temporarySet.load()) {
            std::memcpy(g_temporary, text.c_str(), text.size() + 1);
            g_temporarySet.store(true);
            registered_ = true;
        }
    }
    ~RegisteredTemporary() {
        if (registered_) g_temporarySet.store(false);
    }
    RegisteredTemporary(const RegisteredTemporary&) = delete;
    RegisteredTemporary& operator=(const RegisteredTemporary&) = delete;

private:
    bool registered_ = false;
};

}  // namespace

std::vector<fs::path> linkTargets(const fs::path& path) {
    std::vector<fs::path> targets;
    fs::path at = path;
    std::error_code ec;
    for (int hops = 0; hops < 40 && fs::is_symlink(at, ec); ++hops) {
        const fs::path next = fs::read_symlink(at, ec);
        if (ec) break;
        at = (next.is_absolute() ? next : at.parent_path() / next).lexically_normal();
        targets.push_back(at);
    }
    return targets;
}

void removeTemporaryBeingWritten() noexcept {
    if (g_temporarySet.load()) ::unlink(g_temporary);
}

void writeAtomically(const std::string& path, const std::function<void(const std::string& temporary)>& write) {
    installTerminationCleanup();
    // Same folder, so the rename is atomic (and relative paths inside resolve as in the result).
    // Where the write lands: the end of a chain of links, so that -o through a link updates the
    // file it points to instead of replacing the link by a file.
    const std::vector<fs::path> links = linkTargets(path);
    const fs::path target = links.empty() ? fs::path(path) : links.back();
    // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on "." + string.
    std::string name = ".";
    name += target.filename().string();
    name += ".partial-" + std::to_string(::getpid());
    const fs::path temp = target.parent_path() / name;
    const RegisteredTemporary registered(temp);
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
