// --input-limit's grammar (input_limits.h): names, suffixes, and the values it refuses.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "input_limits.h"

namespace vkrt {
namespace {

struct InputLimitsTest : ::testing::Test {
    void TearDown() override { resetInputLimits(); }
};

std::string errorOf(const std::string& assignment) {
    try {
        setInputLimit(assignment);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

TEST_F(InputLimitsTest, DefaultsAreTheDocumentedOnes) {
    EXPECT_EQ(inputLimits().sceneFileBytes, 64u << 20);
    EXPECT_EQ(inputLimits().meshFileBytes, 1u << 30);
    EXPECT_EQ(inputLimits().imageTexels, 1u << 25);
    EXPECT_EQ(inputLimits().sceneTexels, 1u << 26);
    EXPECT_EQ(inputLimits().readPixels, 1u << 28);
}

TEST_F(InputLimitsTest, SuffixesArePowersOf1024) {
    setInputLimit("scene-bytes=3K");
    setInputLimit("mesh-bytes=5m");
    setInputLimit("image-texels=2G");
    setInputLimit("scene-texels=7");
    setInputLimit("read-pixels=12345678901");
    EXPECT_EQ(inputLimits().sceneFileBytes, 3u * 1024);
    EXPECT_EQ(inputLimits().meshFileBytes, 5u << 20);
    EXPECT_EQ(inputLimits().imageTexels, std::uint64_t(2) << 30);
    EXPECT_EQ(inputLimits().sceneTexels, 7u);
    EXPECT_EQ(inputLimits().readPixels, 12345678901u);
    resetInputLimits();
    EXPECT_EQ(inputLimits().sceneFileBytes, 64u << 20);
}

TEST_F(InputLimitsTest, BadAssignmentsSayWhatIsWrongAndChangeNothing) {
    EXPECT_NE(errorOf("texels=5").find("no input limit 'texels' (there are scene-bytes, mesh-bytes, image-texels, "
                                       "scene-texels, read-pixels)"),
              std::string::npos);
    EXPECT_NE(errorOf("scene-bytes").find("expected NAME=VALUE"), std::string::npos);
    EXPECT_NE(errorOf("scene-bytes=").find("no number"), std::string::npos);
    EXPECT_NE(errorOf("scene-bytes=-5").find("no number"), std::string::npos);
    EXPECT_NE(errorOf("scene-bytes=0").find("would refuse every file"), std::string::npos);
    EXPECT_NE(errorOf("scene-bytes=5T").find("unknown suffix"), std::string::npos);
    EXPECT_NE(errorOf("scene-bytes=5MB").find("unexpected text"), std::string::npos);
    EXPECT_NE(errorOf("scene-bytes=1.5G").find("unexpected text"), std::string::npos);
    EXPECT_NE(errorOf("scene-bytes=99999999999999999999").find("too large"), std::string::npos);
    EXPECT_NE(errorOf("scene-bytes=17179869184G").find("too large"), std::string::npos);  // 2^34 << 30 = 2^64
    EXPECT_EQ(inputLimits().sceneFileBytes, 64u << 20);
}

}  // namespace
}  // namespace vkrt
