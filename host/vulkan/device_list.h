// The Vulkan devices of this machine, for `vkrt --list-devices` and for choosing one (`--gpu N`).
// No Vulkan types here, so the command line can include it cheaply.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace vkrt {

struct DeviceInfo {
    int index = 0;                 // position in the loader's list: the N of --gpu N
    std::string name;
    std::string type;              // "discrete", "integrated", "virtual", "cpu", "other"
    std::string driver;            // driver name and version string
    std::uint32_t apiVersion = 0;  // VK_MAKE_API_VERSION packed
    std::uint64_t maxStorageBufferRange = 0;
    std::uint64_t maxTexelBufferElements = 0;
    std::uint64_t maxUniformBufferRange = 0;
    std::uint64_t maxMemoryAllocationSize = 0;
    std::uint64_t deviceLocalHeapBytes = 0;  // the largest device-local memory heap
    std::uint32_t maxWorkGroupCountX = 0;
    std::uint32_t subgroupSize = 0;
    // What a VkPipelineCache's data belongs to (its header): pipeline_cache_file.h keys files by them.
    std::uint32_t vendorId = 0, deviceId = 0, driverVersion = 0;
    std::array<std::uint8_t, 16> pipelineCacheUuid{};
    bool lavapipe = false;         // Mesa's llvmpipe driver (VkDriverId): its workarounds key on this
    bool loopLimiter = false;      // lavapipe before Mesa 25: loops end silently after 65,535 passes
    std::uint32_t queueFamily = 0; // the family vkrt submits to (computeQueueFamily)
    bool computeOnlyQueue = false; // that family has no graphics
    std::uint32_t timestampValidBits = 0;  // 0: the family cannot write timestamps
    float timestampPeriodNs = 0.0f;        // nanoseconds per timestamp tick
    // No device-local memory at all: a device that compiles pipelines and cannot run them (RADV's
    // null device, RADV_FORCE_FAMILY=navi21 without AMD hardware). Not usable for renders (RADV
    // crashes on the first command pool there); `vkrt-bench gpu kernels` opens it for its
    // compiler's statistics (ContextOptions::compileOnly).
    bool compileOnly = false;
    bool pipelineStatistics = false;  // offers VK_KHR_pipeline_executable_properties (registers, spills)
    bool usable = false;           // Vulkan 1.2 with a compute queue and device memory
    std::string unusableReason;    // why not, when !usable
};

// Enumerates every device; throws VulkanUnavailable when the Vulkan loader cannot be used.
std::vector<DeviceInfo> listDevices();

// One block per device: index, name, type, driver, API version, the limits vkrt checks.
std::string formatDeviceList(const std::vector<DeviceInfo>& devices);

// "1.3.230"
std::string apiVersionString(std::uint32_t version);

// The device to use: `requested` (>= 0, from --gpu) if it exists and is usable, else the first
// usable device in the order discrete > integrated > virtual > cpu > other. Throws
// VulkanUnavailable when nothing is usable, std::invalid_argument for a bad `requested`.
int chooseDevice(const std::vector<DeviceInfo>& devices, int requested);

// Every usable device in that order of preference (only `requested` when it is >= 0): the
// candidates to try when creating a device fails on the first choice.
std::vector<int> deviceCandidates(const std::vector<DeviceInfo>& devices, int requested);

// The device of MPI rank `localRank` on its node: round robin over the usable devices of the best
// type present (discrete > integrated > virtual > cpu), so a node with one GPU and Mesa's lavapipe
// puts every rank on the GPU, never one on the CPU. -1 when no device is usable.
int deviceForLocalRank(const std::vector<DeviceInfo>& devices, int localRank);

}  // namespace vkrt
