// --device auto (issue 39): on a machine whose only Vulkan devices run on the CPU (Mesa's lavapipe)
// vkrt renders on the CPU reference, which is faster there; with a GPU beside them it takes Vulkan.
// The lists are made up, so each case runs on any machine.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "device_choice.h"

namespace vkrt {
namespace {

DeviceInfo device(int index, const std::string& name, const std::string& type, bool usable = true) {
    DeviceInfo d;
    d.index = index;
    d.name = name;
    d.type = type;
    d.usable = usable;
    d.unusableReason = usable ? "" : "needs Vulkan 1.2";
    return d;
}

const DeviceInfo kLavapipe = device(0, "llvmpipe (LLVM 15.0.6, 256 bits)", "cpu");

TEST(AutoDevice, OnlyLavapipeRendersOnTheCpuReferenceNamingIt) {
    const AutoDevice choice = chooseAutoDevice({kLavapipe});
    EXPECT_TRUE(choice.cpuReference);
    EXPECT_NE(choice.reason.find("the only Vulkan device, llvmpipe (LLVM 15.0.6, 256 bits), runs on the CPU"), std::string::npos)
        << choice.reason;
    EXPECT_NE(choice.reason.find("--device gpu"), std::string::npos) << choice.reason;
}

TEST(AutoDevice, AGpuOfAnyKindBesideLavapipeTakesVulkan) {
    for (const char* type : {"discrete", "integrated", "virtual", "other"}) {
        EXPECT_FALSE(chooseAutoDevice({kLavapipe, device(1, "GPU", type)}).cpuReference) << type;
        EXPECT_FALSE(chooseAutoDevice({device(0, "GPU", type), kLavapipe}).cpuReference) << type;
    }
}

TEST(AutoDevice, AnUnusableGpuDoesNotCount) {
    EXPECT_TRUE(chooseAutoDevice({device(0, "old GPU", "discrete", false), kLavapipe}).cpuReference);
}

TEST(AutoDevice, TwoCpuDevicesAreNamedTogether) {
    const AutoDevice choice = chooseAutoDevice({kLavapipe, device(1, "SwiftShader Device", "cpu")});
    EXPECT_TRUE(choice.cpuReference);
    EXPECT_NE(choice.reason.find("the only Vulkan devices, llvmpipe (LLVM 15.0.6, 256 bits), SwiftShader Device, run on the CPU"),
              std::string::npos)
        << choice.reason;
}

// Nothing usable: Vulkan is tried, and its failure says why (the fallback's own note).
TEST(AutoDevice, NoUsableDeviceLeavesTheReasonToOpeningVulkan) {
    EXPECT_FALSE(chooseAutoDevice({}).cpuReference);
    EXPECT_FALSE(chooseAutoDevice({device(0, "llvmpipe", "cpu", false)}).cpuReference);
}

}  // namespace
}  // namespace vkrt
