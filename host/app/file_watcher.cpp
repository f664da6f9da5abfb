#include "file_watcher.h"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include <poll.h>
#include <sys/eventfd.h>
#include <sys/inotify.h>
#include <unistd.h>

namespace vkrt {

namespace {

// What a save looks like, whatever the editor: a write closed (in place), a file moved onto the
// name (write-and-rename), a deletion (the scene is gone: the next render says so).
constexpr std::uint32_t kEvents = IN_CLOSE_WRITE | IN_MOVED_TO | IN_DELETE | IN_MOVED_FROM;

bool isUnder(const std::filesystem::path& file, const std::filesystem::path& folder) {
    auto f = file.begin();
    for (auto d = folder.begin(); d != folder.end(); ++d, ++f) {
        if (d->empty()) continue;  // a trailing separator
        if (f == file.end() || *f != *d) return false;
    }
    return true;
}

}  // namespace

std::filesystem::path watchedPath(const std::filesystem::path& path) {
    return std::filesystem::absolute(path).lexically_normal();
}

FileWatcher::FileWatcher()
    : fd_(::inotify_init1(IN_NONBLOCK | IN_CLOEXEC)), wakeFd_(::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC)) {
    if (fd_ < 0 || wakeFd_ < 0) {
        const std::string why = std::strerror(errno);
        if (fd_ >= 0) ::close(fd_);
        if (wakeFd_ >= 0) ::close(wakeFd_);
        throw std::runtime_error("cannot watch files (inotify: " + why + ")");
    }
}

FileWatcher::~FileWatcher() {
    ::close(fd_);
    ::close(wakeFd_);
}

void FileWatcher::wake() {
    const std::uint64_t one = 1;
    [[maybe_unused]] const ssize_t n = ::write(wakeFd_, &one, sizeof one);  // the counter cannot overflow here
}

void FileWatcher::watch(const std::vector<std::filesystem::path>& files, const std::vector<std::filesystem::path>& trees,
                        const std::set<std::string>& treeExtensions) {
    treeExtensions_.insert(treeExtensions.begin(), treeExtensions.end());
    std::set<std::filesystem::path> folders;
    for (const std::filesystem::path& file : files) {
        files_.insert(watchedPath(file));
        folders.insert(watchedPath(file).parent_path());
    }
    for (const std::filesystem::path& tree : trees) {
        trees_.push_back(watchedPath(tree));
        folders.insert(watchedPath(tree));
        std::error_code ec;
        for (auto it = std::filesystem::recursive_directory_iterator(tree, ec); !ec && it != std::filesystem::recursive_directory_iterator();
             it.increment(ec))
            if (it->is_directory(ec)) folders.insert(watchedPath(it->path()));
    }
    for (const std::filesystem::path& folder : folders) {
        // inotify returns the same descriptor for a folder watched twice.
        const int wd = ::inotify_add_watch(fd_, folder.c_str(), kEvents);
        // A folder that does not exist (yet) is not watched; its file's absence is the render's error.
        if (wd >= 0) folders_[wd] = folder;
    }
}

bool FileWatcher::drain(FileChanges& changes, bool othersCount) {
    bool counted = false;
    alignas(inotify_event) char buffer[16384];
    for (;;) {
        const ssize_t n = ::read(fd_, buffer, sizeof buffer);
        if (n <= 0) break;  // EAGAIN: nothing more queued
        for (ssize_t at = 0; at < n;) {
            const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
            at += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
            const auto folder = folders_.find(event->wd);
            if (folder == folders_.end() || event->len == 0) continue;
            const std::filesystem::path path = folder->second / event->name;
            bool ignored = false;
            for (const std::filesystem::path& name : ignored_) {
                const std::string f = path.filename().string(), n = name.filename().string();
                // The file, or the temporaries writeAtomically makes beside it (".NAME.partial-PID").
                if (path.parent_path() == name.parent_path() && (f == n || f.rfind("." + n, 0) == 0)) ignored = true;
            }
            if (ignored) continue;
            if (files_.count(path)) {
                changes.files.insert(path);
                counted = true;
                continue;
            }
            bool inTree = false;
            for (const std::filesystem::path& tree : trees_)
                if (isUnder(path, tree) && treeExtensions_.count(path.extension().string())) inTree = true;
            if (inTree) {
                changes.trees.insert(path);
                counted = true;
            } else if (!(event->mask & IN_ISDIR)) {
                changes.others.insert(path);
                counted = counted || othersCount;
            }
        }
    }
    return counted;
}

std::optional<FileChanges> FileWatcher::wait(const std::function<bool()>& stop, std::chrono::milliseconds quiet, bool othersCount) {
    FileChanges changes;
    bool seen = false;
    for (;;) {
        // Stopped half-way through a save's events: what was seen is returned (the rest stays queued).
        if (stop && stop()) return seen ? std::optional<FileChanges>(changes) : std::nullopt;
        pollfd p[2] = {{fd_, POLLIN, 0}, {wakeFd_, POLLIN, 0}};
        const int timeout = seen ? static_cast<int>(quiet.count()) : 100;
        const int ready = ::poll(p, 2, timeout);
        if (ready < 0 && errno != EINTR) throw std::runtime_error(std::string("cannot watch files (poll: ") + std::strerror(errno) + ")");
        if (ready > 0 && (p[1].revents & POLLIN)) {
            std::uint64_t count = 0;
            [[maybe_unused]] const ssize_t n = ::read(wakeFd_, &count, sizeof count);
        }
        if (ready > 0 && (p[0].revents & POLLIN)) {
            if (drain(changes, othersCount)) seen = true;
        } else if (ready == 0 && seen) {
            return changes;  // quiet for `quiet`: the save is complete
        }
    }
}

}  // namespace vkrt
