#include "file_watcher.h"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include <poll.h>
#include <sys/eventfd.h>
#include <sys/inotify.h>
#include <unistd.h>

#include "output_file.h"  // linkTargets

namespace vkrt {

namespace {

// What a save looks like, whatever the editor: a write closed (in place), a file moved onto the
// name (write-and-rename), a deletion (the scene is gone: the next render says so).
// IN_CREATE: a symbolic link made onto the name (ln -sf), and a folder appearing (a deleted
// folder made again); IN_IGNORED, which inotify sends unasked, says a watched folder is gone.
constexpr std::uint32_t kEvents = IN_CLOSE_WRITE | IN_MOVED_TO | IN_DELETE | IN_MOVED_FROM | IN_CREATE;


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
    for (const std::filesystem::path& file : files) {
        files_.insert(watchedPath(file));
        wanted_.insert(watchedPath(file).parent_path());
        for (const std::filesystem::path& target : linkTargets(watchedPath(file))) {
            files_.insert(watchedPath(target));
            wanted_.insert(watchedPath(target).parent_path());
        }
    }
    for (const std::filesystem::path& tree : trees) {
        trees_.push_back(watchedPath(tree));
        wanted_.insert(watchedPath(tree));
        std::error_code ec;
        for (auto it = std::filesystem::recursive_directory_iterator(tree, ec); !ec && it != std::filesystem::recursive_directory_iterator();
             it.increment(ec))
            if (it->is_directory(ec)) wanted_.insert(watchedPath(it->path()));
    }
    rearm(nullptr);  // what the caller reads now is current: nothing counts as changed yet
}

bool FileWatcher::rearm(FileChanges* changes) {
    std::set<std::filesystem::path> watched;
    for (const auto& [wd, folder] : folders_) watched.insert(folder);
    // Ancestor watches are made again below for the folders still missing.
    for (const auto& [wd, folder] : ancestors_)
        if (!folders_.count(wd)) ::inotify_rm_watch(fd_, wd);
    ancestors_.clear();
    bool counted = false;
    for (const std::filesystem::path& folder : wanted_) {
        if (watched.count(folder)) continue;
        // inotify returns the same descriptor for a folder watched twice.
        const int wd = ::inotify_add_watch(fd_, folder.c_str(), kEvents | IN_ONLYDIR);
        if (wd >= 0) {
            folders_[wd] = folder;
            std::error_code ec;
            if (changes)
                for (const std::filesystem::path& file : files_)
                    if (file.parent_path() == folder && std::filesystem::exists(file, ec)) {
                        changes->files.insert(file);
                        counted = true;
                    }
            continue;
        }
        // Missing (or not a folder): wait for it at the nearest ancestor that exists.
        for (std::filesystem::path up = folder.parent_path(); !up.empty(); up = up.parent_path()) {
            const int ancestor = ::inotify_add_watch(fd_, up.c_str(), kEvents | IN_ONLYDIR);
            if (ancestor >= 0) {
                ancestors_[ancestor] = up;
                break;
            }
            if (up == up.root_path()) break;
        }
    }
    return counted;
}

bool FileWatcher::drain(FileChanges& changes, bool othersCount) {
    bool counted = false, rearmNeeded = false;
    alignas(inotify_event) char buffer[16384];
    for (;;) {
        const ssize_t n = ::read(fd_, buffer, sizeof buffer);
        if (n <= 0) break;  // EAGAIN: nothing more queued
        for (ssize_t at = 0; at < n;) {
            const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
            at += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
            if (event->mask & IN_IGNORED) {  // the folder is gone (deleted, or its file system unmounted)
                folders_.erase(event->wd);
                ancestors_.erase(event->wd);
                rearmNeeded = true;
                continue;
            }
            // A folder appearing may be a wanted one, or on the way to one.
            if ((event->mask & IN_ISDIR) && (event->mask & (IN_CREATE | IN_MOVED_TO))) rearmNeeded = true;
            const auto folder = folders_.find(event->wd);
            if (folder == folders_.end() || event->len == 0) continue;
            // A file created is reported by its IN_CLOSE_WRITE; a symbolic link has only IN_CREATE.
            if ((event->mask & IN_CREATE) && !(event->mask & IN_ISDIR)) {
                std::error_code ec;
                if (!std::filesystem::is_symlink(folder->second / event->name, ec)) continue;
            }
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
    if (rearmNeeded && rearm(&changes)) counted = true;
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
