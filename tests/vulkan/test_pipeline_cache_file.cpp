// The kernels' pipeline cache on disk (host/vulkan/pipeline_cache_file.h), without a device: a file
// is only handed to the driver when its header names this device and driver; a corrupt, truncated
// or foreign file is ignored with a note; a save goes through a rename and reads back the same.
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "pipeline_cache_file.h"
#include "test_paths.h"

namespace vkrt::test {
namespace {

DeviceInfo someDevice() {
    DeviceInfo d;
    d.vendorId = 0x10de;
    d.deviceId = 0x2335;
    d.driverVersion = 0x12345678;
    for (std::size_t i = 0; i < d.pipelineCacheUuid.size(); ++i) d.pipelineCacheUuid[i] = static_cast<std::uint8_t>(i * 7 + 1);
    return d;
}

// A header for `d` (VkPipelineCacheHeaderVersionOne) and `extra` bytes of payload.
std::vector<std::uint8_t> cacheData(const DeviceInfo& d, std::size_t extra) {
    std::vector<std::uint8_t> data(32 + extra, 0xab);
    const std::uint32_t words[4] = {32u, 1u, d.vendorId, d.deviceId};
    std::memcpy(data.data(), words, sizeof words);
    std::memcpy(data.data() + 16, d.pipelineCacheUuid.data(), 16);
    return data;
}

void writeBytes(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

class PipelineCacheFiles : public ::testing::Test {
protected:
    void SetUp() override {
        dir = std::filesystem::path(artifactDir()) / "pipeline_cache";
        std::filesystem::remove_all(dir);
        setenv("VKRT_PIPELINE_CACHE_DIR", dir.c_str(), 1);
    }
    void TearDown() override { unsetenv("VKRT_PIPELINE_CACHE_DIR"); }
    std::filesystem::path dir;
};

TEST_F(PipelineCacheFiles, TheHeaderMustNameThisDeviceAndDriver) {
    const DeviceInfo d = someDevice();
    EXPECT_EQ(pipelineCacheDataProblem(d, cacheData(d, 100)), "");
    EXPECT_NE(pipelineCacheDataProblem(d, std::vector<std::uint8_t>(20, 0)).find("shorter than"), std::string::npos);
    DeviceInfo other = d;
    other.deviceId = 1;
    EXPECT_EQ(pipelineCacheDataProblem(d, cacheData(other, 0)), "written for another device");
    other = d;
    other.pipelineCacheUuid[5] ^= 1;
    EXPECT_EQ(pipelineCacheDataProblem(d, cacheData(other, 0)), "written by another driver build");
    std::vector<std::uint8_t> version = cacheData(d, 0);
    version[4] = 2;
    EXPECT_EQ(pipelineCacheDataProblem(d, version), "header version 2, not 1");
    std::vector<std::uint8_t> length = cacheData(d, 0);
    length[0] = 200;
    EXPECT_NE(pipelineCacheDataProblem(d, length).find("does not fit"), std::string::npos);
}

TEST_F(PipelineCacheFiles, ASavedCacheReadsBackAndABadOneIsIgnoredWithANote) {
    const DeviceInfo d = someDevice();
    PipelineCacheFile first = openPipelineCacheFile(d);
    ASSERT_EQ(first.path.parent_path(), dir);
    EXPECT_TRUE(first.data.empty());
    EXPECT_TRUE(first.notes.empty()) << "no file yet is not worth a note";
    const std::vector<std::uint8_t> data = cacheData(d, 1000);
    savePipelineCacheFile(first, data);
    EXPECT_TRUE(first.notes.empty()) << first.notes.front();
    EXPECT_EQ(openPipelineCacheFile(d).data, data);
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        EXPECT_EQ(entry.path(), first.path) << "a temporary was left behind";

    // Garbage, a truncated file and another device's file: ignored, each with a note naming the file.
    DeviceInfo other = d;
    other.vendorId = 0x1002;
    for (const std::vector<std::uint8_t>& bad : {std::vector<std::uint8_t>(5000, 0x5a), std::vector<std::uint8_t>(data.begin(), data.begin() + 12),
                                                 cacheData(other, 64)}) {
        writeBytes(first.path, bad);
        const PipelineCacheFile reopened = openPipelineCacheFile(d);
        EXPECT_TRUE(reopened.data.empty());
        ASSERT_EQ(reopened.notes.size(), 1u);
        EXPECT_NE(reopened.notes[0].find(first.path.string() + " ignored"), std::string::npos) << reopened.notes[0];
    }

    // An unwritable place is a note too, not an exception.
    setenv("VKRT_PIPELINE_CACHE_DIR", "/proc/vkrt-cannot-write-here", 1);
    PipelineCacheFile nowhere = openPipelineCacheFile(d);
    savePipelineCacheFile(nowhere, data);
    ASSERT_EQ(nowhere.notes.size(), 1u);
    EXPECT_NE(nowhere.notes[0].find("not written"), std::string::npos) << nowhere.notes[0];
    setenv("VKRT_PIPELINE_CACHE", "off", 1);
    EXPECT_TRUE(openPipelineCacheFile(d).path.empty());
    unsetenv("VKRT_PIPELINE_CACHE");
}

}  // namespace
}  // namespace vkrt::test
