// Image output (issue 22): the path is checked before a render starts, and the file appears under
// its name only when complete (written beside it and renamed), so a viewer or a kill during the
// write never leaves a truncated image under the name asked for.
#include <filesystem>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "image.h"

namespace vkrt {
namespace {

namespace fs = std::filesystem;

fs::path freshDir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("vkrt_image_output_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string refusal(const std::string& path) {
    try {
        checkImageOutputPath(path);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

TEST(ImageOutput, BadPathsAreRefusedNamingTheProblem) {
    const fs::path dir = freshDir("bad");
    EXPECT_NE(refusal((dir / "missing" / "x.png").string()).find("does not exist"), std::string::npos);
    EXPECT_NE(refusal((dir / "x.bmp").string()).find("unsupported output format '.bmp'"), std::string::npos);
    EXPECT_NE(refusal("").find("empty"), std::string::npos);
    fs::create_directories(dir / "folder.png");
    EXPECT_NE(refusal((dir / "folder.png").string()).find("is a folder"), std::string::npos);
    EXPECT_EQ(refusal((dir / "ok.PNG").string()), "");
    EXPECT_EQ(refusal("relative_name.exr"), "");  // the current folder
}

TEST(ImageOutput, TheWrittenFileIsCompleteAndNoPartialFileIsLeft) {
    const fs::path dir = freshDir("atomic");
    Image image(3, 2);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = glm::vec3(0.1f * i, 0.5f, 1.0f);
    const fs::path target = dir / "out.exr";
    writeImage(image, target.string());
    writeImage(image, target.string());  // replacing an existing file goes the same way
    const Image back = readImage(target.string());
    ASSERT_EQ(back.width, 3);
    ASSERT_EQ(back.height, 2);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) EXPECT_EQ(back.pixels[i], image.pixels[i]) << i;
    int entries = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
    EXPECT_EQ(entries, 1) << "a temporary file was left beside " << target;
}

TEST(ImageOutput, AFailedWriteLeavesNothingBehind) {
    const fs::path dir = freshDir("failed");
    EXPECT_THROW(writeImage(Image(2, 2), (dir / "missing" / "x.png").string()), std::runtime_error);
    EXPECT_TRUE(fs::is_empty(dir));
}

}  // namespace
}  // namespace vkrt
