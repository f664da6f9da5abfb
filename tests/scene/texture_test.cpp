// <texture> definitions, their bindings, and image decoding (checked against OpenImageIO read
// independently in the test).
#include <chrono>
#include <cstdint>
#include <fstream>
#include <iterator>
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

// One file named by many <texture> elements (or by different spellings of its path) is decoded
// once and shared: 100 names give one Texture, so a scene cannot multiply a 2K image's decode
// time and memory by repeating its name.
TEST_F(TextureParsing, OneFileNamedByManyTexturesIsDecodedOnceAndShared) {
    writePng((dir / "images/a.png").string(), 3);
    writePng((dir / "images/b.png").string(), 1);
    std::string body;
    for (int i = 0; i < 100; ++i)
        body += "<texture name=\"t" + std::to_string(i) + "\" type=\"image\"><sourcefile>" +
                (i % 2 ? "images/a.png" : "images/../images/./a.png") + "</sourcefile></texture>\n";
    body += "<texture name=\"other\" type=\"image\"><sourcefile>images/b.png</sourcefile></texture>\n";
    body += "<shader name=\"first\" type=\"Lambertian\"><diffuse tex=\"t0\">1 1 1</diffuse></shader>\n";
    body += "<shader name=\"last\" type=\"Lambertian\"><diffuse tex=\"t99\">1 1 1</diffuse></shader>\n";
    body += "<shader name=\"b\" type=\"Lambertian\"><diffuse tex=\"other\">1 1 1</diffuse></shader>";
    const Scene scene = loadClean(sceneWith(body));
    ASSERT_EQ(scene.textures.size(), 2u);
    EXPECT_EQ(scene.textures[0].name, "t0");
    EXPECT_EQ(scene.shaders[0].diffuseTexture, 0);
    EXPECT_EQ(scene.shaders[1].diffuseTexture, 0);
    EXPECT_EQ(scene.shaders[2].diffuseTexture, 1);
    EXPECT_EQ(scene.textures[1].rgba8[1], packed(15, 15, 15, 255));
}

// The PNG CRC (ISO 3309), so the test can write a header libpng accepts.
std::uint32_t pngCrc(const std::vector<std::uint8_t>& bytes, std::size_t begin, std::size_t end) {
    std::uint32_t crc = 0xffffffffu;
    for (std::size_t i = begin; i < end; ++i) {
        crc ^= bytes[i];
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return crc ^ 0xffffffffu;
}

// A real 2x2 PNG whose IHDR is rewritten to claim width x height (the CRC recomputed).
std::string writePngClaiming(const std::string& path, std::uint32_t width, std::uint32_t height) {
    writePng(path, 3);
    std::ifstream in(path, std::ios::binary);
    std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    in.close();
    // 8-byte signature, then the IHDR chunk: length (4), "IHDR" (4), width (4), height (4), 5 more, CRC.
    const auto put = [&](std::size_t at, std::uint32_t v) {
        for (int k = 0; k < 4; ++k) bytes[at + k] = static_cast<std::uint8_t>(v >> (24 - 8 * k));
    };
    put(16, width);
    put(20, height);
    put(29, pngCrc(bytes, 12, 29));
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    return path;
}

// A header that claims 40000 x 40000 (1.6e9 texels) is refused from the header, before any texel
// is allocated: with the decode attempted it zero-filled 4.8 GB and took 34 s. The bound of 5 s
// is generous (the refusal reads one header); the warning names the size and the texture.
TEST_F(TextureParsing, AHeaderClaimingHugeDimensionsIsRefusedBeforeAllocating) {
    const std::string path = writePngClaiming((dir / "huge.png").string(), 40000, 40000);
    std::string error;
    const auto start = std::chrono::steady_clock::now();
    EXPECT_FALSE(loadTextureImage(path, error));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 5.0);
    EXPECT_NE(error.find("claims 40000x40000 texels, more than the 33554432"), std::string::npos) << error;
    // Through a scene: a warning at the file name, the shader keeps its tint.
    const std::string xml = sceneWith(
        "<texture name=\"big\" type=\"image\">\n<sourcefile>huge.png</sourcefile>\n</texture>\n"
        "<shader name=\"s\" type=\"Lambertian\"><diffuse tex=\"big\">0.2 0.3 0.4</diffuse></shader>");
    Diagnostics diagnostics;
    const Scene scene = load(xml, diagnostics);
    EXPECT_EQ(scene.shaders[0].diffuseTexture, kNoTexture);
    ASSERT_EQ(diagnostics.warnings().size(), 1u);
    expectIssue(diagnostics.warnings()[0], lineOf(xml, "<sourcefile>"), "sourcefile", path);
    EXPECT_NE(diagnostics.warnings()[0].problem.find("texture 'big'"), std::string::npos);
    // Just inside the cap the header is accepted and decoding fails on the missing data instead.
    std::string inside;
    EXPECT_FALSE(loadTextureImage(writePngClaiming((dir / "tall.png").string(), 1, 1 << 25), inside));
    EXPECT_EQ(inside.find("claims"), std::string::npos) << inside;
}

}  // namespace
}  // namespace vkrt::test

namespace vkrt::test {
namespace {

// A w x h grey PNG, and `links` more names for it (hard links: separate paths, so each is decoded
// on its own, without writing the pixels again).
void writeGreyPng(const std::filesystem::path& path, int w, int h, const std::vector<std::filesystem::path>& links) {
    std::filesystem::create_directories(path.parent_path());
    const std::vector<unsigned char> grey(static_cast<std::size_t>(w) * h, 90);
    auto out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out && out->open(path.string(), OIIO::ImageSpec(w, h, 1, OIIO::TypeDesc::UINT8))) << path;
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, grey.data())) << path;
    out->close();
    for (const std::filesystem::path& link : links) std::filesystem::create_hard_link(path, link);
}

// Issue 38 item 4: images each within the per-image limit cannot add up without bound. Three
// 4800 x 4800 textures (23M texels each): the third would take the scene past 2^26 texels and is
// left out with a warning naming the total; the shader keeps its tint.
TEST_F(TextureParsing, TheScenesTexturesTogetherHaveALimit) {
    writeGreyPng(dir / "big_a.png", 4800, 4800, {dir / "big_b.png", dir / "big_c.png"});
    std::string body;
    for (const char* t : {"a", "b", "c"})
        body += std::string("<texture name=\"") + t + "\" type=\"image\"><sourcefile>big_" + t + ".png</sourcefile></texture>\n";
    body += "<shader name=\"s\" type=\"Lambertian\"><diffuse tex=\"c\">0.5 0.6 0.7</diffuse></shader>";
    Diagnostics diagnostics;
    const Scene scene = load(sceneWith(body), diagnostics);
    EXPECT_EQ(scene.textures.size(), 2u);
    EXPECT_EQ(scene.shaders[0].diffuseTexture, kNoTexture);
    ASSERT_EQ(diagnostics.warnings().size(), 1u);
    EXPECT_NE(diagnostics.warnings()[0].problem.find("69120000 texels, more than the 67108864"), std::string::npos)
        << diagnostics.warnings()[0].problem;
}

// Six 2400 x 2400 faces (34.6M texels) exceed the 2^25 one map may hold: an error from the first
// face's size, naming it.
TEST_F(TextureParsing, AnEnvironmentMapsSixFacesTogetherHaveALimit) {
    std::vector<std::filesystem::path> others;
    for (const char* face : {"negX", "posY", "negY", "posZ", "negZ"}) others.push_back(dir / "big" / (std::string("env_") + face + ".png"));
    writeGreyPng(dir / "big" / "env_posX.png", 2400, 2400, others);
    const Issue issue = errorOf(sceneWith("", " envmapPrefix=\"big/env_\""));
    EXPECT_NE(issue.problem.find("six environment map faces of 2400x2400"), std::string::npos) << issue.problem;
}

}  // namespace
}  // namespace vkrt::test
