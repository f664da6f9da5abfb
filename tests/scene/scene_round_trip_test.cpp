// vkrt convert's writers (issue 19): every course file, XML -> JSON -> XML and JSON -> XML -> JSON,
// gives a field-by-field equal scene model (scene_compare.h: floats by bit pattern, paths by the file
// they name, mesh and texture data element by element), and a hand-made scene holding every field
// the model has survives both writers. The models are compared with an independent walk of the two
// loads; the renders of round-tripped files are compared in tests/agreement/scene_round_trip_render_test.cpp.
#include <algorithm>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "json_writer.h"
#include "number_text.h"
#include "scene_compare.h"
#include "scene_loader.h"
#include "scene_test_files.h"
#include "scene_writing.h"
#include "test_paths.h"
#include "xml_writer.h"

namespace vkrt::test {
namespace {

namespace fs = std::filesystem;

enum class Format { Json, Xml };

std::vector<std::string> filesIn(const std::string& dir, const std::string& extension) {
    std::vector<std::string> paths;
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().extension() == extension) paths.push_back(entry.path().string());
    std::sort(paths.begin(), paths.end());
    return paths;
}

// The scene written in `format` as dir/name, and the text written.
std::string writeScene(const Scene& scene, Format format, const fs::path& path) {
    const std::string text = format == Format::Json ? jsonSceneText(scene, path.parent_path()) : xmlSceneText(scene, path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
    return text;
}

Scene loadQuietly(const std::string& path) {
    Diagnostics diagnostics;  // the files' warnings are the loader tests' concern
    LoadOptions options;
    options.environmentTexels = false;  // the writers write an environment map's names, as vkrt convert loads it
    return loadScene(path, options, diagnostics);
}

// original -> first format -> second format, each load compared with the original. The second
// write of the first format's text must also reproduce that text byte for byte (a fixed point).
void expectRoundTrip(const std::string& path, Format first, Format second, const fs::path& outDir) {
    SCOPED_TRACE(path);
    const Scene original = writing::asWritten(loadQuietly(path));
    const std::string stem = fs::path(path).stem().string();
    const char* firstExt = first == Format::Json ? ".json" : ".xml";
    const char* secondExt = second == Format::Json ? ".json" : ".xml";
    const fs::path a = outDir / (stem + firstExt);
    const std::string firstText = writeScene(original, first, a);
    const Scene once = loadQuietly(a.string());
    const SceneDifferences d1 = compareScenes(original, once);
    EXPECT_TRUE(d1.equal()) << "after " << firstExt << ":\n" << d1.summary();

    const fs::path b = outDir / (stem + "_back" + secondExt);
    writeScene(once, second, b);
    const Scene twice = loadQuietly(b.string());
    const SceneDifferences d2 = compareScenes(original, twice);
    EXPECT_TRUE(d2.equal()) << "after " << firstExt << " and " << secondExt << ":\n" << d2.summary();

    const fs::path c = outDir / (stem + "_again" + firstExt);
    EXPECT_EQ(writeScene(twice, first, c), firstText) << "writing the round-tripped model again gives other text";
}

TEST(SceneRoundTrip, EveryXmlSceneThroughJsonAndBack) {
    VKRT_SKIP_WITHOUT(upstreamDir());
    std::vector<std::string> paths = filesIn(upstreamDir(), ".xml");
    ASSERT_EQ(paths.size(), 54u) << upstreamDir();
    for (const std::string& bundled : filesIn(sourceDir() + "/scenes", ".xml")) paths.push_back(bundled);
    const fs::path out = freshArtifactDir("round_trip_xml");
    for (const std::string& path : paths) expectRoundTrip(path, Format::Json, Format::Xml, out);
}

TEST(SceneRoundTrip, EveryJsonSceneThroughXmlAndBack) {
    VKRT_SKIP_WITHOUT(jsonSceneDir());
    const std::vector<std::string> paths = filesIn(jsonSceneDir(), ".json");
    ASSERT_EQ(paths.size(), 58u) << jsonSceneDir();
    const fs::path out = freshArtifactDir("round_trip_json");
    for (const std::string& path : paths) expectRoundTrip(path, Format::Xml, Format::Json, out);
}

// Every field of the model, in forms the corpus lacks: several cameras with a non-first default
// and an orthographic one, every shader type with textures on both colours, a nameless inline
// shader, shape lights (a sphere with a transform, an instance of a prototype with a shader of its
// own), both environment-map fields, a transformed plain shape and instances, and numbers that
// need all nine digits, -0 and a subnormal.
class SceneRoundTripFields : public SceneFiles {};

TEST_F(SceneRoundTripFields, AHandMadeSceneWithEveryFieldSurvivesBothWriters) {
    write("tex.ppm", "P3\n2 1\n255\n255 0 0 0 255 0\n");
    write("m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n");
    writeCubeFaces("faces/sky_");  // (cross.png is not read: the prefix wins, with a warning)
    const std::string xml = R"(<?xml version="1.0"?>
<scene bgColor="0.1 0.2 0.30000001">
  <sceneParameters><envMapPrefix>faces/sky_</envMapPrefix><envMapVertCross>cross.png</envMapVertCross><camera>side</camera></sceneParameters>
  <camera name="main"><position>0 1 5</position><lookatPoint>0 0 0</lookatPoint><focalLength>0.7</focalLength></camera>
  <camera name="side" type="orthographic"><position>-0 1e-40 3.4028235e38</position><viewDir>1 0 -1</viewDir><imagePlaneWidth>4</imagePlaneWidth></camera>
  <light type="point"><position>1 2 3</position><intensity>0.123456791 1 1</intensity></light>
  <light type="shape"><intensity>4 4 4</intensity><shape name="bulb" type="sphere"><center>0 3 0</center><radius>0.25</radius>
    <transform><translate>0 1 0</translate><scale>2 2 2</scale></transform></shape></light>
  <light type="area"><position>0 5 0</position><intensity>1 1 1</intensity><normal>0 -1 0.5</normal><width>2</width><length>0</length></light>
  <light type="shape"><intensity>1 0.5 0.25</intensity><shape name="lamp" type="instance" id="tri"><shader ref="glass"/>
    <transform><rotate axis="Y">4500</rotate></transform></shape></light>
  <texture name="t" type="image"><sourcefile>tex.ppm</sourcefile></texture>
  <texture name="sameFile"><sourcefile>./tex.ppm</sourcefile></texture>
  <shader name="lam" type="Lambertian"><diffuse tex="t">0.5 0.25 1</diffuse></shader>
  <shader name="bp" type="BlinnPhong"><diffuse>0.1 0.1 0.1</diffuse><specular tex="sameFile">1 1 1</specular><phongExp>64</phongExp></shader>
  <shader name="bpm" type="BlinnPhongMirrored"><diffuse>1 0 0</diffuse><specular>1 1 1</specular><phongExp>3</phongExp><mirrorCoef>0.5</mirrorCoef><roughness>0.1</roughness></shader>
  <shader name="old mirror" type="BlinnPhong"><diffuse>1 0 0</diffuse><mirrorCoef>0.25</mirrorCoef></shader>
  <shader name="mirror" type="Mirror"><roughness>1.4</roughness></shader>
  <shader name="glaze" type="Glaze"><diffuse>0 1 0</diffuse><mirrorCoef>0.3</mirrorCoef><roughness>0</roughness></shader>
  <shader name="glass" type="Dielectric"><refractiveIndex>1.5</refractiveIndex><attenuationCoef>0.9 0.8 0.7</attenuationCoef></shader>
  <shader name="cool" type="CoolToWarm"><diffuse>0.2 0.3 0.4</diffuse></shader>
  <shader name="pt" type="Diffuse"><diffuse>0.7 0.7 0.7</diffuse></shader>
  <shader name="glow" type="Emitter"><emission>5 5 5</emission></shader>
  <instance name="tri" type="triangle"><shader ref="lam"/><v0>0 0 0</v0><v1>1 0 0</v1><v2>0 1 0</v2></instance>
  <instance name="mesh" type="mesh"><shader ref="cool"/><file>m.obj</file></instance>
  <shape name="ground" type="box"><shader ref="bp"/><minPt>-1 -1 -1</minPt><maxPt>1 0 1</maxPt></shape>
  <shape type="sphere"><shader type="Lambertian"><diffuse>0.3 0.3 0.3</diffuse></shader><center>0 0 0</center><radius>1</radius></shape>
  <shape name="moved" type="sphere"><shader ref="glow"/><center>0 0 0</center><radius>2</radius>
    <transform><rotate axis="X">90</rotate><translate>1 2 3</translate><scale>1 0.5 -1</scale></transform></shape>
  <shape name="plain mesh" type="mesh"><shader ref="pt"/><file>m.obj</file></shape>
  <shape name="i1" type="instance" id="tri"><shader ref="mirror"/><transform><translate>5 0 0</translate></transform></shape>
  <shape name="i2" type="instance" id="mesh"/>
  <shape name="i3" type="instance" id="tri"><transform/></shape>
  <shape name="unusedShaders" type="triangle"><shader ref="bpm"/><v0>0 0 0</v0><v1>0 0 1</v1><v2>0 1 0</v2></shape>
  <shape name="t2" type="triangle"><shader ref="old mirror"/><v0>0 0 0</v0><v1>0 0 1</v1><v2>0 1 0</v2></shape>
  <shape name="t3" type="triangle"><shader ref="glaze"/><v0>0 0 0</v0><v1>0 0 1</v1><v2>0 1 0</v2></shape>
  <shape name="t4" type="triangle"><shader ref="missing one"/><v0>0 0 0</v0><v1>0 0 1</v1><v2>0 1 0</v2></shape>
</scene>
)";
    Diagnostics diagnostics;
    const Scene original = load(xml, diagnostics);
    // The scene holds what the test means it to (a guard against the test itself going stale).
    ASSERT_EQ(original.cameras.size(), 2u);
    ASSERT_EQ(original.defaultCamera, 1);
    ASSERT_EQ(original.emitters.size(), 2u);
    ASSERT_EQ(original.emitters[1].prototype, 0);
    ASSERT_EQ(original.textures.size(), 1u);
    ASSERT_FALSE(original.envMapPrefix.empty());
    ASSERT_FALSE(original.envMapVertCross.empty());
    ASSERT_EQ(std::count_if(original.shaders.begin(), original.shaders.end(), [](const Shader& s) { return s.name.empty(); }), 1);
    ASSERT_TRUE(std::signbit(original.cameras[1].position.x));
    ASSERT_GT(original.cameras[1].position.y, 0.0f);
    ASSERT_LT(original.cameras[1].position.y, 1e-38f);  // subnormal

    const Scene expected = writing::asWritten(original);
    for (Format first : {Format::Json, Format::Xml}) {
        const Format second = first == Format::Json ? Format::Xml : Format::Json;
        SCOPED_TRACE(first == Format::Json ? "json then xml" : "xml then json");
        const fs::path a = dir / (first == Format::Json ? "out.json" : "out.xml");
        writeScene(original, first, a);
        const Scene once = loadQuietly(a.string());
        EXPECT_TRUE(compareScenes(expected, once).equal()) << compareScenes(expected, once).summary();
        const fs::path b = dir / (second == Format::Json ? "back.json" : "back.xml");
        writeScene(once, second, b);
        const Scene twice = loadQuietly(b.string());
        EXPECT_TRUE(compareScenes(expected, twice).equal()) << compareScenes(expected, twice).summary();
    }
}

// Meshes are numbered by first use; a transformed mesh shape (an instance in the model) before a
// plain one, and a shape light's mesh after both in the file, come back in the same order.
TEST_F(SceneRoundTripFields, MeshesComeBackInTheOrderOfFirstUse) {
    write("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    write("b.obj", "v 0 0 0\nv 2 0 0\nv 0 2 0\nf 1 2 3\n");
    write("c.obj", "v 0 0 0\nv 3 0 0\nv 0 3 0\nf 1 2 3\n");
    const std::string xml = R"(<scene><camera><position>0 0 5</position><viewDir>0 0 -1</viewDir></camera>
  <shader name="s" type="Lambertian"><diffuse>1 1 1</diffuse></shader>
  <shape type="mesh"><shader ref="s"/><file>b.obj</file><transform><translate>1 0 0</translate></transform></shape>
  <shape type="mesh"><shader ref="s"/><file>a.obj</file></shape>
  <light type="shape"><intensity>1 1 1</intensity><shape type="mesh"><file>c.obj</file></shape></light>
</scene>
)";
    Diagnostics diagnostics;
    const Scene original = load(xml, diagnostics);
    ASSERT_EQ(original.meshes.size(), 3u);
    EXPECT_EQ(fs::path(original.meshes[0].path).filename(), "c.obj");  // lights are placed before shapes
    for (Format format : {Format::Json, Format::Xml}) {
        const fs::path out = dir / (format == Format::Json ? "meshes.json" : "meshes_out.xml");
        writeScene(original, format, out);
        const SceneDifferences d = compareScenes(original, loadQuietly(out.string()));
        EXPECT_TRUE(d.equal()) << out << ":\n" << d.summary();
    }
}

// Each floatText reads back as its float through the loaders' path (decimal -> double -> float),
// over random bit patterns of every exponent, subnormals and the extremes included.
TEST(SceneWriting, EveryFloatTextReadsBackAsTheSameFloat) {
    std::mt19937 random(19);
    std::vector<float> values = {0.0f, -0.0f, 1.0f, 0.1f, 1e-45f, -1e-45f, 1.17549435e-38f, 3.40282347e38f, -3.40282347e38f};
    for (int i = 0; i < 200000; ++i) {
        const std::uint32_t bits = random();
        float f;
        std::memcpy(&f, &bits, sizeof f);
        if (std::isfinite(f)) values.push_back(f);
    }
    std::size_t wrong = 0;
    for (float f : values) {
        const std::string text = writing::floatText(f);
        double parsed = 0.0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), parsed);
        const std::optional<float> back = finiteFloat(parsed);  // the loaders' narrowing and range check
        if (error != std::errc() || end != text.data() + text.size() || !back || std::memcmp(&*back, &f, sizeof f) != 0) {
            if (++wrong < 5) ADD_FAILURE() << text << " does not read back as " << f;
        }
    }
    EXPECT_EQ(wrong, 0u) << "of " << values.size();
    EXPECT_EQ(writing::floatText(0.1f), "0.1");  // shortest, not 0.100000001
    EXPECT_EQ(writing::floatText(-0.0f), "-0");
}

// The comparison itself: a changed field is reported under its path, -0 differs from 0, and two
// spellings of one file are the same path.
TEST(SceneCompare, ReportsEachDifferingFieldByItsPath) {
    Scene a;
    a.cameras.push_back(Camera{});
    a.shaders.push_back(Shader{});
    a.shaders.push_back(Shader{});
    a.meshes.push_back(Mesh{});
    a.meshes[0].path = "/tmp/x/m.obj";
    Scene b = a;
    EXPECT_TRUE(compareScenes(a, b).equal());
    b.meshes[0].path = "/tmp/x/../x/./m.obj";
    EXPECT_TRUE(compareScenes(a, b).equal()) << compareScenes(a, b).summary();
    b.shaders[1].diffuse.y = 0.25f;
    b.cameras[0].position.x = -0.0f;
    const SceneDifferences d = compareScenes(a, b);
    EXPECT_EQ(d.count, 2u);
    EXPECT_NE(d.summary().find("shaders[1].diffuse: 1 1 1 vs 1 0.25 1"), std::string::npos) << d.summary();
    EXPECT_NE(d.summary().find("cameras[0].position: 0 0 0 vs -0 0 0"), std::string::npos) << d.summary();
    b = a;
    b.meshes[0].positions.push_back(glm::vec3(1.0f));
    EXPECT_NE(compareScenes(a, b).summary().find("meshes[0].positions.size: 0 vs 1"), std::string::npos);
    // Bulk data names the first differing element by its values.
    Scene c = b;
    c.meshes[0].positions[0].z = 2.0f;
    EXPECT_NE(compareScenes(b, c).summary().find("meshes[0].positions[0]: 1 1 1 vs 1 1 2"), std::string::npos)
        << compareScenes(b, c).summary();
}

}  // namespace
}  // namespace vkrt::test
