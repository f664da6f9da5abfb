// The kernels' VkPipelineCache kept on disk between processes, so a driver that caches compiled
// pipelines (NVIDIA's, AMD's) compiles a kernel variant once per machine, not once per run. One
// file per device and driver (vendor, device, driver version and pipelineCacheUUID in its name);
// the data's own header is checked against the device before the driver sees it, so a corrupt,
// truncated or foreign file is ignored with a note, never handed over. lavapipe (Mesa 22.3) keeps
// nothing in a pipeline cache (its data is the 32-byte header alone): there the file saves nothing
// (docs/STARTUP.md).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "device_list.h"

namespace vkrt {

struct PipelineCacheFile {
    std::filesystem::path path;              // empty: no cache directory (nothing is read or written)
    std::vector<std::uint8_t> data;          // the accepted contents, or empty
    std::vector<std::string> notes;          // why a file was ignored or could not be written
};

// $VKRT_PIPELINE_CACHE_DIR, else $XDG_CACHE_HOME/vkrt/pipelines, else ~/.cache/vkrt/pipelines;
// VKRT_PIPELINE_CACHE=off disables the file (empty path).
std::filesystem::path pipelineCacheDirectory();

// Reads the device's file, if there is one, and keeps its data when its header matches `device`.
PipelineCacheFile openPipelineCacheFile(const DeviceInfo& device);

// Why `data` cannot be a VkPipelineCache's initial data for `device`, or "" when it can.
std::string pipelineCacheDataProblem(const DeviceInfo& device, const std::vector<std::uint8_t>& data);

// Writes `data` when it differs from what was read, through a temporary name and a rename (two
// processes never see half a file); a failure becomes a note.
void savePipelineCacheFile(PipelineCacheFile& file, const std::vector<std::uint8_t>& data);

}  // namespace vkrt
