// Device creation, listing and choice, and that the validation layer really reports misuse (so
// "zero messages" in every other test means something).
#include <stdexcept>

#include <gtest/gtest.h>

#include "context.h"
#include "device_list.h"
#include "vulkan_errors.h"
#include "vulkan_test_support.h"

namespace vkrt {
namespace {

using test::VulkanTest;

DeviceInfo fakeDevice(int index, const std::string& type, bool usable) {
    DeviceInfo d;
    d.index = index;
    d.name = "device" + std::to_string(index);
    d.type = type;
    d.usable = usable;
    d.unusableReason = usable ? "" : "has no compute queue";
    return d;
}

TEST(DeviceChoice, PrefersDiscreteThenIntegratedThenCpu) {
    const std::vector<DeviceInfo> devices = {fakeDevice(0, "cpu", true), fakeDevice(1, "integrated", true),
                                             fakeDevice(2, "discrete", false), fakeDevice(3, "discrete", true)};
    EXPECT_EQ(chooseDevice(devices, -1), 3);
    EXPECT_EQ(chooseDevice({devices[0], devices[1]}, -1), 1);
    EXPECT_EQ(chooseDevice({devices[0]}, -1), 0);
}

TEST(DeviceChoice, OverrideWinsWhenUsable) {
    const std::vector<DeviceInfo> devices = {fakeDevice(0, "cpu", true), fakeDevice(1, "discrete", true),
                                             fakeDevice(2, "discrete", false)};
    EXPECT_EQ(chooseDevice(devices, 0), 0);
    EXPECT_THROW(chooseDevice(devices, 2), std::invalid_argument);
    try {
        chooseDevice(devices, 7);
        FAIL() << "--gpu 7 accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("--gpu 7"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("device1"), std::string::npos) << e.what();
    }
}

TEST(DeviceChoice, CandidatesInOrderOfPreference) {
    const std::vector<DeviceInfo> devices = {fakeDevice(0, "cpu", true), fakeDevice(1, "integrated", true),
                                             fakeDevice(2, "discrete", false), fakeDevice(3, "discrete", true),
                                             fakeDevice(4, "cpu", true)};
    EXPECT_EQ(deviceCandidates(devices, -1), (std::vector<int>{3, 1, 0, 4}));
    EXPECT_EQ(deviceCandidates(devices, 4), (std::vector<int>{4}));  // --gpu: that one or nothing
    EXPECT_THROW(deviceCandidates(devices, 2), std::invalid_argument);
}

// MPI ranks on a node (app.cpp's pickGpuByLocalRank): round robin over the devices of the best
// type present, never Mesa's lavapipe beside a discrete GPU.
TEST(DeviceChoice, MpiRanksGoToDevicesOfTheBestTypePresent) {
    const std::vector<DeviceInfo> nvidiaAndLavapipe = {fakeDevice(0, "discrete", true), fakeDevice(1, "cpu", true)};
    EXPECT_EQ(deviceForLocalRank(nvidiaAndLavapipe, 0), 0);
    EXPECT_EQ(deviceForLocalRank(nvidiaAndLavapipe, 1), 0);
    const std::vector<DeviceInfo> lavapipeFirst = {fakeDevice(0, "cpu", true), fakeDevice(1, "discrete", true)};
    EXPECT_EQ(deviceForLocalRank(lavapipeFirst, 0), 1);
    EXPECT_EQ(deviceForLocalRank(lavapipeFirst, 1), 1);
    const std::vector<DeviceInfo> twoGpus = {fakeDevice(0, "cpu", true), fakeDevice(1, "discrete", true),
                                             fakeDevice(2, "integrated", true), fakeDevice(3, "discrete", true),
                                             fakeDevice(4, "discrete", false)};
    EXPECT_EQ(deviceForLocalRank(twoGpus, 0), 1);
    EXPECT_EQ(deviceForLocalRank(twoGpus, 1), 3);
    EXPECT_EQ(deviceForLocalRank(twoGpus, 2), 1);
    EXPECT_EQ(deviceForLocalRank({fakeDevice(0, "cpu", true)}, 3), 0);  // lavapipe alone: every rank on it
    EXPECT_EQ(deviceForLocalRank({fakeDevice(0, "discrete", false)}, 0), -1);
}

// What the CLI falls back to the CPU on: a loader that finds no driver.
TEST(Context, NoDriverIsVulkanUnavailable) {
    ::setenv("VK_DRIVER_FILES", "/nonexistent/vkrt_icd.json", 1);
    ::setenv("VK_ICD_FILENAMES", "/nonexistent/vkrt_icd.json", 1);
    try {
        Context c;
        ADD_FAILURE() << "a device without a driver: " << c.info().name;
    } catch (const VulkanUnavailable& e) {
        std::cout << "VulkanUnavailable: " << e.what() << "\n";
    }
    ::unsetenv("VK_DRIVER_FILES");
    ::unsetenv("VK_ICD_FILENAMES");
    EXPECT_NO_THROW(Context());  // and the driver is found again
}

TEST(DeviceChoice, NothingUsableIsVulkanUnavailable) {
    EXPECT_THROW(chooseDevice({}, -1), VulkanUnavailable);
    EXPECT_THROW(chooseDevice({fakeDevice(0, "discrete", false)}, -1), VulkanUnavailable);
}

TEST(DeviceList, DescribesEveryDeviceWithItsLimits) {
    const std::vector<DeviceInfo> devices = listDevices();
    ASSERT_FALSE(devices.empty()) << "this machine has lavapipe";
    for (std::size_t i = 0; i < devices.size(); ++i) EXPECT_EQ(devices[i].index, static_cast<int>(i));
    const std::string text = formatDeviceList(devices);
    std::cout << text;
    for (const DeviceInfo& d : devices) {
        EXPECT_NE(text.find(d.name), std::string::npos);
        if (!d.usable) continue;
        EXPECT_GE(d.apiVersion, VK_API_VERSION_1_2);
        EXPECT_GT(d.maxStorageBufferRange, 0u);
        EXPECT_GT(d.maxTexelBufferElements, 0u);
        EXPECT_GT(d.maxMemoryAllocationSize, 0u);
        EXPECT_GT(d.deviceLocalHeapBytes, 0u);
        EXPECT_GE(d.maxWorkGroupCountX, 65535u);  // the Vulkan minimum
    }
    EXPECT_NE(text.find("maxStorageBufferRange"), std::string::npos);
    EXPECT_NE(text.find("driver:"), std::string::npos);
}

TEST_F(VulkanTest, CreatesTheBestUsableDevice) {
    const Context& c = context();
    const std::vector<DeviceInfo> devices = listDevices();
    EXPECT_EQ(c.info().index, chooseDevice(devices, -1));
    EXPECT_TRUE(c.info().usable);
    EXPECT_EQ(c.info().name, devices[c.info().index].name);
    EXPECT_TRUE(*c.device());
    EXPECT_TRUE(*c.queue());
    EXPECT_EQ(c.limits().maxStorageBufferRange, c.info().maxStorageBufferRange);
    std::cout << "device: " << c.info().name << " (" << c.info().type << "), maps device memory: " << c.mapsDeviceMemory() << "\n";
}

TEST_F(VulkanTest, GpuIndexSelectsThatDevice) {
    const Context& c = context({.gpu = 0});
    EXPECT_EQ(c.info().index, 0);
}

TEST(Context, BadGpuIndexIsRefused) {
    EXPECT_THROW(Context({.gpu = 99}), std::invalid_argument);
}

// A zero-size buffer with no usage breaks two "valid usage" rules; the layer must say so,
// and the log must catch it, or the silence asserted everywhere else would prove nothing.
TEST(Validation, RecordsMessagesForMisuse) {
    std::shared_ptr<const ValidationLog> log;
    {
        Context c({.validation = true});
        log = c.validationLog();
        ASSERT_NE(log, nullptr);
        EXPECT_EQ(log->count(), 0u) << log->joined();
        VkBufferCreateInfo info{};
        info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
        info.size = 0;
        info.usage = 0;
        VkBuffer buffer = VK_NULL_HANDLE;
        const VkResult result = c.device().getDispatcher()->vkCreateBuffer(*c.device(), &info, nullptr, &buffer);
        if (result == VK_SUCCESS) c.device().getDispatcher()->vkDestroyBuffer(*c.device(), buffer, nullptr);
    }
    EXPECT_GE(log->count(), 1u);
    EXPECT_NE(log->joined().find("VUID-VkBufferCreateInfo"), std::string::npos) << log->joined();
}

TEST(Validation, OffMeansNoLog) {
    Context c;
    EXPECT_EQ(c.validationLog(), nullptr);
}

}  // namespace
}  // namespace vkrt
