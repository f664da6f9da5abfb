// What every fuzz target shares: the bytes as a file where a loader wants a path, and the one rule
// of what counts as a finding. A loader must answer any input with a result or with the error it
// documents (SceneError for scenes, std::runtime_error for OBJ and images); a crash, a sanitizer
// report, a hang (libFuzzer's -timeout) or any other exception is a finding.
#pragma once

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#include <unistd.h>

namespace vkrt::fuzz {

// A file of this process's own (the pid keeps parallel fuzzers apart), rewritten per input.
inline std::string writeInput(const std::uint8_t* data, std::size_t size, const char* extension) {
    const std::string path = "/tmp/vkrt_fuzz_" + std::to_string(::getpid()) + extension;
    std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    return path;
}

// Scenes name their meshes and textures relative to themselves: an empty folder, so that a fuzzed
// scene does not load the corpus's 100K-triangle meshes on every run (OBJ and images have targets).
inline const char* kSceneDirectory = "/nonexistent/vkrt-fuzz/";

}  // namespace vkrt::fuzz
