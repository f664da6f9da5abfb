// Files vkrt writes (images, converted scenes): checked before the work that makes them, so a long
// render or load is not thrown away for a typo in -o, and written beside their name and renamed into
// place, so a reader (or a kill during the write) never sees a partial file.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace vkrt {

// The extension with its dot, lower case (".png" for "X.PNG").
std::string lowerExtension(const std::string& path);

// Throws std::runtime_error naming `path` when its folder does not exist or cannot be written, or
// when `path` is a folder; `what` names what it should be ("an image file", "a scene file").
void checkOutputFolder(const std::string& path, const char* what);

// Throws std::runtime_error when `output` is the file `input` under any spelling.
void checkNotTheInput(const std::string& output, const std::string& input);

// Calls write(temporary) for a temporary name in `path`'s folder (the pid keeps two processes apart),
// then renames it to `path`; on any exception the temporary is removed and the exception goes on.
// When `path` is a symbolic link, the file it points to is written and the link stays. SIGTERM and
// SIGHUP during the write remove the temporary before they end the process (when their handling
// is the default one).
void writeAtomically(const std::string& path, const std::function<void(const std::string& temporary)>& write);

// The files a chain of symbolic links at `path` leads through, in order (not `path` itself; empty
// when it is no link), up to 40 hops: where a write through it lands, and what a watch follows.
std::vector<std::filesystem::path> linkTargets(const std::filesystem::path& path);

// Removes the temporary a writeAtomically is writing, if any: async-signal-safe (unlink), for the
// handlers of signals that end the process (interrupt.cpp's second Ctrl-C).
void removeTemporaryBeingWritten() noexcept;

}  // namespace vkrt
