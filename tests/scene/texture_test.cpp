// <texture> definitions, their bindings, and image decoding (checked against OpenImageIO read
// independently in the test).
#include <cstdint>
#include <vector>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imageio.h>

#include "scene_test_files.h"
#include "test_paths.h"
#include "texture_loading.h"

namespace vkrt::test {
namespace {

using TextureParsing = SceneFiles;

std::uint32_t packed(int r, int g, int b, int a) {
    return static_cast<std::uint32_t>(r) | static_cast<std::uint32_t>(g) << 8 | static_cast<std::uint32_t>(b) << 16 |
           static_cast<std::uint32_t>(a) << 24;
}

// Writes a 2x2 PNG with `channels` channels; texel (x, y) channel c holds 10*(2y+x) + 50*c + 5.
std::string writePng(const std::string& path, int channels) {
    std::vector<std::uint8_t> pixels;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x)
            for (int c = 0; c < channels; ++c) pixels.push_back(static_cast<std::uint8_t>(10 * (2 * y + x) + 50 * c + 5));
    std::filesystem::create_directories(std::filesystem::path(path).parent_path());
    auto out = OIIO::ImageOutput::create(path);
    EXPECT_TRUE(out);
    OIIO::ImageSpec spec(2, 2, channels, OIIO::TypeDesc::UINT8);
    if (channels == 2 || channels == 4) spec.alpha_channel = channels - 1;
    spec.attribute("oiio:UnassociatedAlpha", 1);  // store the values as given, not divided by alpha
    if (!out || !out->open(path, spec)) {
        ADD_FAILURE() << "cannot write " << path;
        return path;
    }
    EXPECT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels.data()));
    out->close();
    return path;
}

TEST_F(TextureParsing, GreyGreyAlphaRgbAndRgbaSourcesAllBecomeRgba8TopRowFirst) {
    struct Case {
        int channels;
        std::uint32_t texel10;  // texel (x=1, y=0): base value 15
        std::uint32_t texel01;  // texel (x=0, y=1): base value 25
    };
    const Case cases[] = {
        {1, packed(15, 15, 15, 255), packed(25, 25, 25, 255)},
        {2, packed(15, 15, 15, 65), packed(25, 25, 25, 75)},
        {3, packed(15, 65, 115, 255), packed(25, 75, 125, 255)},
        {4, packed(15, 65, 115, 165), packed(25, 75, 125, 175)},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.channels);
        const std::string path = writePng((dir / ("t" + std::to_string(c.channels) + ".png")).string(), c.channels);
        std::string error;
        const auto texture = loadTextureImage(path, error);
        ASSERT_TRUE(texture) << error;
        EXPECT_EQ(texture->width, 2);
        EXPECT_EQ(texture->height, 2);
        ASSERT_EQ(texture->rgba8.size(), 4u);
        EXPECT_EQ(texture->rgba8[1], c.texel10);
        EXPECT_EQ(texture->rgba8[2], c.texel01);
    }
}

TEST_F(TextureParsing, MissingOrUndecodableFileReportsWhy) {
    std::string error;
    EXPECT_FALSE(loadTextureImage((dir / "nope.png").string(), error));
    EXPECT_NE(error.find("not found"), std::string::npos) << error;
    const std::string garbage = write("garbage.png", "this is not a png");
    EXPECT_FALSE(loadTextureImage(garbage, error));
    EXPECT_FALSE(error.empty());
}

TEST_F(TextureParsing, TexAttributeOnDiffuseAndSpecularAndLegacyDiffusetex) {
    writePng((dir / "images/a.png").string(), 3);
    writePng((dir / "images/b.png").string(), 1);
    const Scene scene = loadClean(sceneWith(
        "<texture name=\"A\" type=\"image\"><sourcefile>images/a.png</sourcefile></texture>\n"
        "<texture name=\"B\" type=\"image\"><sourcefile> images/b.png </sourcefile></texture>\n"
        "<shader name=\"earth\" type=\"BlinnPhong\"><diffuse tex=\"A\">1 1 1</diffuse><specular tex=\"B\">0.5 0.5 0.5</specular></shader>\n"
        "<shader name=\"moon\" type=\"Lambertian\"><diffuse>1.0 1.0 1.0</diffuse><diffusetex>B</diffusetex></shader>\n"
        "<shader name=\"plain\" type=\"Lambertian\"><diffusetex> A </diffusetex></shader>"));
    ASSERT_EQ(scene.textures.size(), 2u);
    EXPECT_EQ(scene.textures[0].name, "A");
    EXPECT_EQ(scene.textures[0].where.line, 4);
    EXPECT_EQ(scene.textures[0].rgba8[1], packed(15, 65, 115, 255));
    EXPECT_EQ(scene.textures[1].rgba8[1], packed(15, 15, 15, 255));
    EXPECT_EQ(scene.shaders[0].diffuseTexture, 0);
    EXPECT_EQ(scene.shaders[0].specularTexture, 1);
    EXPECT_EQ(scene.shaders[0].specular, glm::vec3(0.5f));  // the tint is kept
    EXPECT_EQ(scene.shaders[1].diffuseTexture, 1);
    EXPECT_EQ(scene.shaders[2].diffuseTexture, 0);
    EXPECT_EQ(scene.shaders[2].diffuse, glm::vec3(1.0f));  // white under a texture without a tint
}

TEST_F(TextureParsing, TextureDefinedAfterTheShaderStillResolves) {
    writePng((dir / "a.png").string(), 3);
    const Scene scene = loadClean(sceneWith(
        "<shader name=\"s\" type=\"Lambertian\"><diffuse tex=\"late\">1 1 1</diffuse></shader>\n"
        "<texture name=\"late\" type=\"image\"><sourcefile>a.png</sourcefile></texture>"));
    EXPECT_EQ(scene.shaders[0].diffuseTexture, 0);
}

TEST_F(TextureParsing, MissingFileWarnsAndTheShaderUsesItsTint) {
    const std::string xml = sceneWith(
        "<texture name=\"spaceTex\" type=\"image\">\n<sourcefile>images/stars.png</sourcefile>\n</texture>\n"
        "<shader name=\"skyMap\" type=\"Lambertian\"><diffuse>0.5 0.6 0.7</diffuse><diffusetex>spaceTex</diffusetex></shader>");
    Diagnostics diagnostics;
    const Scene scene = load(xml, diagnostics);
    EXPECT_TRUE(scene.textures.empty());
    EXPECT_EQ(scene.shaders[0].diffuseTexture, kNoTexture);
    EXPECT_EQ(scene.shaders[0].diffuse, glm::vec3(0.5f, 0.6f, 0.7f));
    ASSERT_EQ(diagnostics.warnings().size(), 1u);
    expectIssue(diagnostics.warnings()[0], lineOf(xml, "<sourcefile>"), "sourcefile", (dir / "images/stars.png").string());
    EXPECT_THROW(load(xml, diagnostics, /*strict=*/true), SceneError);
}

TEST_F(TextureParsing, UndefinedTextureNameIsAnError) {
    const std::string xml = sceneWith("<shader name=\"s\" type=\"Lambertian\"><diffuse tex=\"nothere\">1 1 1</diffuse></shader>");
    const Issue issue = errorOf(xml);
    expectIssue(issue, 4, "diffuse", "nothere");
    EXPECT_NE(issue.problem.find("unresolved texture"), std::string::npos);
}

TEST(UpstreamTexture, CalibrationImageMatchesOpenImageIO) {
    VKRT_SKIP_WITHOUT(vkrt::test::upstreamDir());
    // Loaded through a real scene (dielectric_Test00.xml binds it with tex=), compared with
    // OpenImageIO's own reading of the same file, texel by texel over a sparse grid.
    const std::string image = upstreamDir() + "/images/textureMapCalibration.png";
    Diagnostics diagnostics;
    const Scene scene = loadScene(upstreamDir() + "/dielectric_Test00.xml", {}, diagnostics);
    ASSERT_EQ(scene.textures.size(), 1u);
    const Texture& texture = scene.textures[0];
    EXPECT_EQ(texture.name, "calibrationTex");

    OIIO::ImageBuf reference(image);
    ASSERT_TRUE(reference.read(0, 0, true, OIIO::TypeDesc::UINT8)) << reference.geterror();
    const OIIO::ImageSpec& spec = reference.spec();
    ASSERT_EQ(texture.width, spec.width);
    ASSERT_EQ(texture.height, spec.height);
    ASSERT_GE(spec.nchannels, 3);
    int compared = 0;
    int distinct = 0;
    std::uint32_t first = texture.rgba8[0];
    for (int y = 0; y < spec.height; y += 17) {
        for (int x = 0; x < spec.width; x += 13) {
            float rgb[4] = {0, 0, 0, 1};
            reference.getpixel(x, y, rgb, 4);
            const std::uint32_t expected = packed(static_cast<int>(std::lround(rgb[0] * 255)), static_cast<int>(std::lround(rgb[1] * 255)),
                                                  static_cast<int>(std::lround(rgb[2] * 255)),
                                                  spec.nchannels >= 4 ? static_cast<int>(std::lround(rgb[3] * 255)) : 255);
            const std::uint32_t got = texture.rgba8[static_cast<std::size_t>(y) * spec.width + x];
            ASSERT_EQ(got, expected) << "texel " << x << "," << y;
            ++compared;
            distinct += got != first;
        }
    }
    EXPECT_GT(compared, 100);
    EXPECT_GT(distinct, 10);  // the image is not uniform, so row/column mix-ups would show
}

}  // namespace
}  // namespace vkrt::test
