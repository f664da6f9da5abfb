#include "pipeline_cache_file.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <system_error>

#include <unistd.h>

namespace vkrt {

namespace {

std::uint32_t word(const std::vector<std::uint8_t>& data, std::size_t offset) {
    std::uint32_t w = 0;
    std::memcpy(&w, data.data() + offset, sizeof w);
    return w;
}

std::string fileName(const DeviceInfo& d) {
    char head[64];
    std::snprintf(head, sizeof head, "%04x-%04x-%08x-", d.vendorId, d.deviceId, d.driverVersion);
    std::string name = head;
    for (const std::uint8_t b : d.pipelineCacheUuid) {
        char hex[3];
        std::snprintf(hex, sizeof hex, "%02x", b);
        name += hex;
    }
    return name + ".bin";
}

}  // namespace

std::filesystem::path pipelineCacheDirectory() {
    if (const char* off = std::getenv("VKRT_PIPELINE_CACHE"); off && std::string(off) == "off") return {};
    if (const char* dir = std::getenv("VKRT_PIPELINE_CACHE_DIR"); dir && *dir) return dir;
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "vkrt" / "pipelines";
    if (const char* home = std::getenv("HOME"); home && *home) return std::filesystem::path(home) / ".cache" / "vkrt" / "pipelines";
    return {};
}

std::string pipelineCacheDataProblem(const DeviceInfo& device, const std::vector<std::uint8_t>& data) {
    // VkPipelineCacheHeaderVersionOne: length, version, vendorID, deviceID, pipelineCacheUUID.
    constexpr std::size_t kHeader = 16 + 16;
    if (data.size() < kHeader) return "shorter than a pipeline cache header (" + std::to_string(data.size()) + " bytes)";
    const std::uint32_t length = word(data, 0);
    if (length < kHeader || length > data.size()) return "its header length " + std::to_string(length) + " does not fit the file";
    if (word(data, 4) != 1u) return "header version " + std::to_string(word(data, 4)) + ", not 1";
    if (word(data, 8) != device.vendorId || word(data, 12) != device.deviceId) return "written for another device";
    if (std::memcmp(data.data() + 16, device.pipelineCacheUuid.data(), 16) != 0) return "written by another driver build";
    return "";
}

PipelineCacheFile openPipelineCacheFile(const DeviceInfo& device) {
    PipelineCacheFile file;
    const std::filesystem::path dir = pipelineCacheDirectory();
    if (dir.empty()) return file;
    file.path = dir / fileName(device);
    std::ifstream in(file.path, std::ios::binary);
    if (!in) return file;  // not written yet
    std::vector<std::uint8_t> data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (const std::string problem = pipelineCacheDataProblem(device, data); !problem.empty()) {
        file.notes.push_back("pipeline cache " + file.path.string() + " ignored: " + problem);
        return file;
    }
    file.data = std::move(data);
    return file;
}

void savePipelineCacheFile(PipelineCacheFile& file, const std::vector<std::uint8_t>& data) {
    if (file.path.empty() || data == file.data) return;
    std::error_code ec;
    std::filesystem::create_directories(file.path.parent_path(), ec);
    std::filesystem::path temporary = file.path;
    temporary += ".tmp" + std::to_string(::getpid());
    {
        std::ofstream out(temporary, std::ios::binary);
        out.write(reinterpret_cast<const char*>(data.data()), static_cast<std::streamsize>(data.size()));
        if (!out) {
            file.notes.push_back("pipeline cache " + file.path.string() + " not written (" +
                                 (ec ? ec.message() : std::string("cannot write ") + temporary.string()) + ")");
            std::filesystem::remove(temporary, ec);
            return;
        }
    }
    std::filesystem::rename(temporary, file.path, ec);
    if (ec) {
        file.notes.push_back("pipeline cache " + file.path.string() + " not written (" + ec.message() + ")");
        std::filesystem::remove(temporary, ec);
        return;
    }
    file.data = data;
}

}  // namespace vkrt
