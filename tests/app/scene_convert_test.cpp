// vkrt convert (issue 19): the output is checked before the input is read, the written file loads
// back as the input's model (checked by convert itself and again here, independently), and a failed
// conversion leaves neither a partial file nor a changed output behind.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "diagnostics.h"
#include "scene_compare.h"
#include "scene_convert.h"
#include "render_options.h"
#include "scene_loader.h"
#include "scene_writing.h"

namespace vkrt {
namespace {

namespace fs = std::filesystem;

fs::path freshDir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("vkrt_convert_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

void writeFile(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

const char* const kScene = R"(<scene bgColor="0.1 0.2 0.3">
  <camera name="main"><position>0 1 5</position><lookatPoint>0 0 0</lookatPoint></camera>
  <light type="area"><position>0 5 0</position><intensity>1 1 1</intensity><normal>0 -1 0</normal><width>2</width><length>1</length></light>
  <shader name="red" type="BlinnPhong"><diffuse>1 0 0</diffuse><specular>1 1 1</specular><phongExp>32</phongExp></shader>
  <instance name="ball" type="sphere"><shader ref="red"/><center>0 0 0</center><radius>1</radius></instance>
  <shape name="b1" type="instance" id="ball"><transform><translate>1 0 0</translate><rotate axis="Y">30</rotate></transform></shape>
  <shape name="floor" type="box"><shader ref="red"/><minPt>-5 -1 -5</minPt><maxPt>5 -0.5 5</maxPt></shape>
</scene>
)";

std::string refusal(const std::string& input, const std::string& output) {
    Diagnostics diagnostics;
    try {
        convertScene(input, output, diagnostics);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

// Issue 38 item 9: names a loader reads but the other format cannot hold. A shape name in Latin-1
// (not UTF-8) from XML, and a shader name with a NUL and a TAB (JSON escapes) referred to by _ref:
// each is written with \xNN in place of what the format cannot hold, the file loads back as that
// model (convert checks), and the renamed shader is still the one its shape refers to.
TEST(SceneConvert, NamesTheOtherFormatCannotHoldAreEscaped) {
    const fs::path dir = freshDir("names");
    writeFile(dir / "latin1.xml",
              "<scene><camera><position>0 0 3</position><viewDir>0 0 -1</viewDir></camera>\n"
              "<shader name=\"g\" type=\"Lambertian\"><diffuse>1 0 0</diffuse></shader>\n"
              "<shape name=\"b\xe8\" type=\"sphere\"><shader ref=\"g\"/><center>0 0 0</center><radius>1</radius></shape></scene>\n");
    Diagnostics diagnostics;
    Conversion c = convertScene((dir / "latin1.xml").string(), (dir / "latin1.json").string(), diagnostics);
    EXPECT_EQ(c.escapedNames, 1u);
    Diagnostics reload;
    Scene json = loadScene((dir / "latin1.json").string(), LoadOptions{}, reload);
    ASSERT_EQ(json.shapes.size(), 1u);
    EXPECT_EQ(json.shapes[0].name, "b\\xE8");
    EXPECT_TRUE(writing::isValidUtf8(readFile(dir / "latin1.json")));

    writeFile(dir / "nul.json",
              R"({"scene": {"camera": {"position": [0, 0, 3], "viewDir": [0, 0, -1]},
                 "shader": [{"_name": "other", "_type": "Lambertian", "diffuse": [0, 1, 0]},
                            {"_name": "s\u0000x\ty", "_type": "Lambertian", "diffuse": [1, 0, 0]}],
                 "shape": [{"_type": "sphere", "center": [0, 0, 0], "radius": 1, "shader": {"_ref": "s\u0000x\ty"}}]}})");
    c = convertScene((dir / "nul.json").string(), (dir / "nul.xml").string(), diagnostics);
    EXPECT_EQ(c.escapedNames, 1u);  // the NUL; XML holds a TAB (as &#09;)
    Scene xml = loadScene((dir / "nul.xml").string(), LoadOptions{}, reload);
    ASSERT_EQ(xml.shaders.size(), 2u);
    EXPECT_EQ(xml.shaders[1].name, "s\\x00x\ty");
    ASSERT_EQ(xml.shapes.size(), 1u);
    EXPECT_EQ(xml.shapes[0].shader, 1);
}

// Two shader names that escape to the same text would make the written refs ambiguous: refused,
// naming the output, the input and both names.
TEST(SceneConvert, NamesThatWouldCollideWhenEscapedAreRefused) {
    const fs::path dir = freshDir("name_collision");
    writeFile(dir / "clash.json",
              R"({"scene": {"camera": {"position": [0, 0, 3], "viewDir": [0, 0, -1]},
                 "shader": [{"_name": "a\u0000", "_type": "Lambertian", "diffuse": [1, 0, 0]},
                            {"_name": "a\\x00", "_type": "Lambertian", "diffuse": [0, 1, 0]}],
                 "shape": [{"_type": "sphere", "center": [0, 0, 0], "radius": 1, "shader": {"_ref": "a\\x00"}}]}})");
    const std::string why = refusal((dir / "clash.json").string(), (dir / "clash.xml").string());
    EXPECT_NE(why.find("clash.xml: not written: "), std::string::npos) << why;
    EXPECT_NE(why.find("clash.json"), std::string::npos) << why;
    EXPECT_NE(why.find("shader names 'a\\x00' and 'a\\\\x00' would both be written as 'a\\x00'"), std::string::npos) << why;
    EXPECT_FALSE(fs::exists(dir / "clash.xml"));
}

TEST(SceneConvert, UTF8ValidationFollowsRfc3629) {
    EXPECT_TRUE(writing::isValidUtf8("plain"));
    EXPECT_TRUE(writing::isValidUtf8("\xc3\xa8\xe2\x82\xac\xf0\x9f\x98\x80"));  // è € 😀
    EXPECT_FALSE(writing::isValidUtf8("\xe8"));              // Latin-1 è
    EXPECT_FALSE(writing::isValidUtf8("\xc0\xaf"));          // overlong '/'
    EXPECT_FALSE(writing::isValidUtf8("\xed\xa0\x80"));      // a surrogate
    EXPECT_FALSE(writing::isValidUtf8("\xf4\x90\x80\x80"));  // beyond U+10FFFF
    EXPECT_FALSE(writing::isValidUtf8("\xe2\x82"));          // cut short
    EXPECT_EQ(writing::writableName("a\xe8\xc3\xa8", writing::NameFormat::Json), "a\\xE8\xc3\xa8");
    EXPECT_EQ(writing::writableName(std::string("a\0b\x1f\t", 5), writing::NameFormat::Xml), "a\\x00b\\x1F\t");
}

TEST(SceneConvert, WritesBothFormatsThatLoadBackAsTheInput) {
    const fs::path dir = freshDir("both");
    writeFile(dir / "in.xml", kScene);
    Diagnostics diagnostics;
    const Scene input = loadScene((dir / "in.xml").string(), LoadOptions{}, diagnostics);
    for (const char* name : {"out.json", "OUT.XML"}) {
        SCOPED_TRACE(name);
        Diagnostics convertWarnings;
        const Conversion c = convertScene((dir / "in.xml").string(), (dir / name).string(), convertWarnings);
        EXPECT_EQ(c.counts, "1 camera, 1 light, 1 shader, 1 shape, 1 instance");
        EXPECT_EQ(c.format, std::string(name) == "out.json" ? "json" : "xml");
        const std::string text = readFile(dir / name);
        EXPECT_EQ(text.front(), c.format == "json" ? '{' : '<');
        Diagnostics reloadWarnings;
        const Scene back = loadScene((dir / name).string(), LoadOptions{}, reloadWarnings);
        EXPECT_TRUE(reloadWarnings.warnings().empty());
        const SceneDifferences d = compareScenes(writing::asWritten(input), back);
        EXPECT_TRUE(d.equal()) << d.summary();
    }
    for (const auto& entry : fs::directory_iterator(dir))
        EXPECT_EQ(entry.path().filename().string().find(".partial-"), std::string::npos) << entry.path();
}

// A bad -o is reported before the input is read: the input here does not even exist, and the
// message names the output.
TEST(SceneConvert, BadOutputsAreRefusedBeforeTheInputIsRead) {
    const fs::path dir = freshDir("bad");
    const std::string missing = (dir / "no_such_scene.xml").string();
    EXPECT_NE(refusal(missing, (dir / "x.bmp").string()).find("x.bmp: unsupported scene format '.bmp' (use .json or .xml)"),
              std::string::npos);
    EXPECT_NE(refusal(missing, (dir / "nowhere" / "x.json").string()).find("does not exist"), std::string::npos);
    fs::create_directories(dir / "folder.json");
    EXPECT_NE(refusal(missing, (dir / "folder.json").string()).find("is a folder"), std::string::npos);
    writeFile(dir / "in.xml", kScene);
    EXPECT_NE(refusal((dir / "in.xml").string(), (dir / "." / "in.xml").string()).find("is the scene file itself"),
              std::string::npos);
    EXPECT_EQ(readFile(dir / "in.xml"), kScene);
}

// A bad input is the loader's located error; an existing output stays as it was and no partial
// file is left.
TEST(SceneConvert, ABadInputLeavesTheOutputUntouched) {
    const fs::path dir = freshDir("untouched");
    writeFile(dir / "bad.xml", "<scene><camera><position>0 0 0</position></camera></scene>");
    writeFile(dir / "out.json", "previous");
    const std::string message = refusal((dir / "bad.xml").string(), (dir / "out.json").string());
    EXPECT_NE(message.find("bad.xml:1: camera: missing required"), std::string::npos) << message;
    EXPECT_EQ(readFile(dir / "out.json"), "previous");
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++files;
    EXPECT_EQ(files, 2u);
}

// Through a symbolic link, `..` from the output folder leads elsewhere than its spelling: the
// written paths must find the mesh from the file's real folder too.
TEST(SceneConvert, PathsWorkFromAnOutputFolderReachedThroughASymbolicLink) {
    const fs::path dir = freshDir("symlink");
    fs::create_directories(dir / "scenes");
    fs::create_directories(dir / "elsewhere" / "deep");
    fs::create_directory_symlink(dir / "elsewhere" / "deep", dir / "link");
    writeFile(dir / "scenes" / "m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    writeFile(dir / "scenes" / "s.xml", R"(<scene><camera><position>0 0 5</position><viewDir>0 0 -1</viewDir></camera>
<shader name="s" type="Lambertian"><diffuse>1 1 1</diffuse></shader><shape type="mesh"><shader ref="s"/><file>m.obj</file></shape></scene>)");
    Diagnostics diagnostics;
    convertScene((dir / "scenes" / "s.xml").string(), (dir / "link" / "out.json").string(), diagnostics);
    Diagnostics reload;
    const Scene viaRealPath = loadScene((dir / "elsewhere" / "deep" / "out.json").string(), LoadOptions{}, reload);
    ASSERT_EQ(viaRealPath.meshes.size(), 1u);
    EXPECT_EQ(viaRealPath.meshes[0].triangles.size(), 1u);
}

// Runs in `dir` and goes back where it was (the relative -o names below are relative to it).
class InFolder {
public:
    explicit InFolder(const fs::path& dir) : previous_(fs::current_path()) { fs::current_path(dir); }
    ~InFolder() { fs::current_path(previous_); }

private:
    fs::path previous_;
};

// A -o relative to the working folder, bare, with `./` or in another folder, names the mesh
// relative to the written file's folder, as docs/SCENE_CONVERSION.md says (the first two were
// written absolute: the output folder "/cwd/." normalised with a trailing separator passed for a
// symbolic link), and the result loads the mesh from there.
TEST(SceneConvert, PathsAreRelativeToTheOutputFolderForEveryRelativeOutputName) {
    const fs::path dir = freshDir("relative");
    fs::create_directories(dir / "scenes");
    fs::create_directories(dir / "sub");
    writeFile(dir / "scenes" / "m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    writeFile(dir / "scenes" / "s.xml", R"(<scene><camera><position>0 0 5</position><viewDir>0 0 -1</viewDir></camera>
<shader name="s" type="Lambertian"><diffuse>1 1 1</diffuse></shader><shape type="mesh"><shader ref="s"/><file>m.obj</file></shape></scene>)");
    const InFolder inDir(dir);
    const struct {
        const char* output;
        const char* meshPath;  // as the written file spells it
    } cases[] = {{"out.json", "\"scenes/m.obj\""}, {"./out.xml", ">scenes/m.obj<"}, {"sub/out.json", "\"../scenes/m.obj\""}};
    for (const auto& c : cases) {
        SCOPED_TRACE(c.output);
        Diagnostics diagnostics;
        convertScene("scenes/s.xml", c.output, diagnostics);
        const std::string text = readFile(c.output);
        EXPECT_NE(text.find(c.meshPath), std::string::npos) << text;
        EXPECT_EQ(text.find(dir.string()), std::string::npos) << text;
        Diagnostics reload;
        const Scene back = loadScene((dir / c.output).string(), LoadOptions{}, reload);
        ASSERT_EQ(back.meshes.size(), 1u);
        EXPECT_EQ(back.meshes[0].triangles.size(), 1u);
    }
}

// Ctrl-C during a conversion stops it between steps and leaves nothing behind.
TEST(SceneConvert, AnInterruptStopsItLeavingNothing) {
    const fs::path dir = freshDir("cancel");
    writeFile(dir / "in.xml", kScene);
    const std::atomic<bool> cancelled{true};
    Diagnostics diagnostics;
    EXPECT_THROW(convertScene((dir / "in.xml").string(), (dir / "out.json").string(), diagnostics, &cancelled), RenderCancelled);
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++files;
    EXPECT_EQ(files, 1u);
}

}  // namespace
}  // namespace vkrt
