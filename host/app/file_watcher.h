// Waits for files to change, through Linux inotify. It watches the folders that hold the files, not
// the files: an editor that saves by writing a new file and renaming it over the old one replaces
// the file's inode, and a watch on the old inode would never fire again. For the same reason a
// folder that is deleted (or does not exist yet) is waited for through its nearest existing
// ancestor and watched again when it appears, its files then counting as changed; and a file that
// is a symbolic link is watched at its target too (an edit there changes what the link reads).
#pragma once

#include <chrono>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace vkrt {

struct FileChanges {
    std::set<std::filesystem::path> files;  // the watched files that changed
    std::set<std::filesystem::path> trees;  // the files in watched trees that changed
    std::set<std::filesystem::path> others; // other files in the watched files' folders
};

// An absolute, normalised spelling (no symlinks resolved: the names the user gave are watched).
std::filesystem::path watchedPath(const std::filesystem::path& path);

class FileWatcher {
public:
    FileWatcher();  // throws std::runtime_error when inotify is unavailable
    ~FileWatcher();
    FileWatcher(const FileWatcher&) = delete;
    FileWatcher& operator=(const FileWatcher&) = delete;

    // Adds these files to what is watched (a change is a write closed, a file renamed or moved onto
    // the name, or deleted) and every file under these folders whose extension is in
    // `treeExtensions`. Nothing already queued is lost: a change made while the caller was
    // reading the files is still reported by the next wait().
    void watch(const std::vector<std::filesystem::path>& files, const std::vector<std::filesystem::path>& trees = {},
               const std::set<std::string>& treeExtensions = {});
    // Changes to this file and to the temporaries written beside it (output_file.h) are ignored.
    void ignore(const std::filesystem::path& file) { ignored_.push_back(watchedPath(file)); }

    // Blocks until something watched changes (or, with `othersCount`, any file in a watched
    // file's folder), then goes on collecting until nothing has changed for `quiet` (a save is
    // often several events: write, rename, attributes), and returns what changed. As soon as stop()
    // is true (asked every 100 ms, and at once after wake()) returns what it has seen so far, or
    // nullopt when nothing; later events stay queued for the next wait().
    std::optional<FileChanges> wait(const std::function<bool()>& stop, std::chrono::milliseconds quiet, bool othersCount);
    // From another thread: makes a wait() ask stop() now.
    void wake();

    std::size_t folderCount() const { return folders_.size(); }

private:
    // Reads what inotify has queued into `changes`; true when something counted.
    bool drain(FileChanges& changes, bool othersCount);
    // Watches every wanted folder that exists and is not watched (its existing watched files count
    // as changed: they may have come back with it), and for each that does not exist its nearest
    // existing ancestor, to hear of its creation. True when a file was counted.
    bool rearm(FileChanges* changes);

    int fd_ = -1;
    int wakeFd_ = -1;  // an eventfd: wake() writes it
    std::set<std::filesystem::path> wanted_;        // the folders whose files count
    std::map<int, std::filesystem::path> folders_;  // watch descriptor -> wanted folder
    std::map<int, std::filesystem::path> ancestors_;  // watch descriptor -> ancestor of a missing wanted folder
    std::set<std::filesystem::path> files_;
    std::vector<std::filesystem::path> trees_;
    std::set<std::string> treeExtensions_;
    std::vector<std::filesystem::path> ignored_;
};

}  // namespace vkrt
