// Environment maps at scene load, both formats: the course's scenes load theirs (cube faces and the
// vertical cross), a face that is missing or of the wrong size is an error at the element that
// named it, with the file, and the -Z rule follows LoadOptions.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "environment_test_maps.h"
#include "scene_loader.h"
#include "test_paths.h"

namespace vkrt::test {
namespace {

int lineOfText(const std::string& text, const std::string& needle) {
    const std::size_t at = text.find(needle);
    EXPECT_NE(at, std::string::npos) << needle;
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

std::string fileText(const std::string& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

const FaceTexels kGrey = [](int face, int x, int y) { return glm::u8vec3(30 * face, 20 * x, 20 * y); };

class EnvironmentLoading : public ::testing::Test {
protected:
    void SetUp() override {
        dir = std::filesystem::temp_directory_path() /
              ("vkrt_env_" + std::to_string(getpid()) + "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::create_directories(dir);
    }
    void TearDown() override { std::filesystem::remove_all(dir); }

    std::string write(const std::string& name, const std::string& text) const {
        const std::string path = (dir / name).string();
        std::ofstream(path) << text;
        return path;
    }
    // A JSON scene whose sceneParameters are `parameters` (the envMap keys on lines of their own).
    std::string json(const std::string& parameters) const {
        return write("scene.json", "{\n\"scene\": {\n\"camera\": [{\"position\": \"0 0 0\", \"viewDir\": \"0 0 -1\"}],\n"
                                   "\"sceneParameters\": {\n" + parameters + "\n}\n}\n}\n");
    }
    std::string xml(const std::string& parameters) const {
        return write("scene.xml", "<?xml version=\"1.0\"?>\n<scene>\n<camera name=\"c\" type=\"perspective\"><position>0 0 0</position>"
                                  "<viewDir>0 0 -1</viewDir></camera>\n<sceneParameters>\n" + parameters + "\n</sceneParameters>\n</scene>\n");
    }
    static Issue errorOf(const std::string& path) {
        Diagnostics diagnostics;
        try {
            loadScene(path, {}, diagnostics);
        } catch (const SceneError& e) {
            return e.issue();
        }
        ADD_FAILURE() << "no error loading " << path;
        return {};
    }
    // The issue is at `needle`'s line of the scene file and quotes `value`, the file at fault.
    static void expectAt(const Issue& issue, const std::string& scene, const std::string& needle, const std::string& value) {
        EXPECT_EQ(issue.file, scene);
        EXPECT_EQ(issue.line, lineOfText(fileText(scene), needle));
        EXPECT_EQ(issue.value, value);
        EXPECT_NE(issue.message().find(scene + ":" + std::to_string(issue.line) + ":"), std::string::npos) << issue.message();
        EXPECT_NE(issue.message().find("'" + value + "'"), std::string::npos) << issue.message();
    }

    std::filesystem::path dir;
};

TEST_F(EnvironmentLoading, CourseScenesLoadTheirCubeFacesAndCross) {
    struct Case {
        std::string path;
        std::string needle;  // where the file names the map
        int faceSize;
        bool negZMirrored;
    };
    const Case cases[] = {
        {jsonSceneDir() + "/environmentMappedScene.json", "envMapPrefix", 1024, true},
        {jsonSceneDir() + "/LittleOfEverything.json", "envMapPrefix", 1024, true},
        {jsonSceneDir() + "/rowOfBunnys.json", "envMapPrefix", 1024, true},
        {jsonSceneDir() + "/diffuseScene_multipleSpheres.json", "envMapVertCross", 512, false},
        {jsonSceneDir() + "/sd20210420_diffuseScene_multipleSpheres.json", "envMapVertCross", 512, false},
        {upstreamDir() + "/mirrorTest2.xml", "envmapPrefix", 1024, false},
        {upstreamDir() + "/dielectric_Test00.xml", "envMapPrefix", 1024, false},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.path);
        VKRT_SKIP_WITHOUT(c.path);
        Diagnostics diagnostics;
        const Scene scene = loadScene(c.path, {}, diagnostics);
        ASSERT_EQ(scene.environment.faceSize, c.faceSize);
        for (const auto& face : scene.environment.faces) EXPECT_EQ(face.size(), std::size_t(c.faceSize) * c.faceSize);
        EXPECT_EQ(scene.environment.negZMirrored, c.negZMirrored);
        EXPECT_EQ(scene.environment.where.file, c.path);
        EXPECT_EQ(scene.environment.where.line, lineOfText(fileText(c.path), c.needle));
        for (const Issue& warning : diagnostics.warnings()) EXPECT_EQ(warning.message().find("nvironment"), std::string::npos) << warning.message();
    }
}

TEST_F(EnvironmentLoading, TheNegZRuleFollowsLoadOptions) {
    const std::string path = jsonSceneDir() + "/environmentMappedScene.json";
    VKRT_SKIP_WITHOUT(path);
    Diagnostics diagnostics;
    LoadOptions options;
    options.environmentNegZ = NegZRule::OpenGL;
    EXPECT_FALSE(loadScene(path, options, diagnostics).environment.negZMirrored);
    options.environmentNegZ = NegZRule::Measure;
    const Scene measured = loadScene(path, options, diagnostics);
    EXPECT_TRUE(measured.environment.negZMirrored);
    EXPECT_LT(measured.environment.negZSeamErrorMirrored, measured.environment.negZSeamErrorAsOpenGL);
}

TEST_F(EnvironmentLoading, AMissingFaceIsAnErrorAtTheElementNamingTheFile) {
    writeCubeFaces((dir / "sky/f_").string(), 4, kGrey);
    std::filesystem::remove(dir / "sky/f_negY.png");
    const std::string missing = (dir / "sky/f_negY.png").string();
    const std::string scene = json("\"envMapPrefix\": \"sky/f_\"");
    const Issue issue = errorOf(scene);
    expectAt(issue, scene, "envMapPrefix", missing);
    EXPECT_NE(issue.problem.find("negY"), std::string::npos) << issue.problem;
    const std::string xmlScene = xml("<envMapPrefix>sky/f_</envMapPrefix>");
    expectAt(errorOf(xmlScene), xmlScene, "<envMapPrefix>", missing);
    EXPECT_EQ(errorOf(xmlScene).element, "envMapPrefix");
}

// LoadOptions::environmentTexels = false (vkrt convert): the names are resolved and kept, nothing
// is read, so a scene converts without decoding its faces (and converts even where they are gone).
TEST_F(EnvironmentLoading, WithoutTexelsTheNamesAreKeptAndNoFileIsRead) {
    writeCubeFaces((dir / "sky/f_").string(), 4, kGrey);
    std::filesystem::remove(dir / "sky/f_negY.png");
    LoadOptions options;
    options.environmentTexels = false;
    for (const std::string& scene : {json("\"envMapPrefix\": \"sky/f_\""), xml("<envMapPrefix>sky/f_</envMapPrefix>")}) {
        Diagnostics diagnostics;
        const Scene loaded = loadScene(scene, options, diagnostics);
        EXPECT_EQ(loaded.envMapPrefix, (dir / "sky/f_").string());
        EXPECT_EQ(loaded.environment.faceSize, 0);
        EXPECT_TRUE(diagnostics.warnings().empty());
    }
}

TEST_F(EnvironmentLoading, FacesOfTheWrongSizeAreErrorsNamingTheFace) {
    writeCubeFaces((dir / "a_").string(), 4, kGrey);
    writePng((dir / "a_posZ.png").string(), 8, 8, [](int, int) { return glm::u8vec3(9); });  // larger than the others
    const std::string scene = json("\"envMapPrefix\": \"a_\"");
    const Issue differ = errorOf(scene);
    expectAt(differ, scene, "envMapPrefix", (dir / "a_posZ.png").string());
    EXPECT_NE(differ.problem.find("differ in size"), std::string::npos) << differ.problem;

    writeCubeFaces((dir / "b_").string(), 4, kGrey);
    writePng((dir / "b_posX.png").string(), 4, 6, [](int, int) { return glm::u8vec3(9); });  // not square
    const std::string xmlScene = xml("<envMapPrefix>b_</envMapPrefix>");
    const Issue square = errorOf(xmlScene);
    expectAt(square, xmlScene, "<envMapPrefix>", (dir / "b_posX.png").string());
    EXPECT_NE(square.problem.find("not square"), std::string::npos) << square.problem;
}

TEST_F(EnvironmentLoading, ACrossMustBeThreeByFourCells) {
    writePng((dir / "cross.png").string(), 12, 15, [](int, int) { return glm::u8vec3(9); });
    const std::string scene = json("\"bgColor\": \"0 0 0\",\n\"envMapVertCross\": \"cross.png\"");
    const Issue issue = errorOf(scene);
    expectAt(issue, scene, "envMapVertCross", (dir / "cross.png").string());
    EXPECT_NE(issue.problem.find("3k x 4k"), std::string::npos) << issue.problem;

    const std::string missing = json("\"envMapVertCross\": \"nothing.png\"");
    expectAt(errorOf(missing), missing, "envMapVertCross", (dir / "nothing.png").string());

    // 3k x 4k loads: each face its cell (kVerticalCross), e.g. -Z the centre cell mirrored left-right.
    writePng((dir / "cross.png").string(), 6, 8, [](int x, int y) { return glm::u8vec3(x, y, 7); });
    Diagnostics diagnostics;
    const Scene loaded = loadScene(json("\"envMapVertCross\": \"cross.png\""), {}, diagnostics);
    ASSERT_EQ(loaded.environment.faceSize, 2);
    EXPECT_EQ(loaded.environment.faces[5][0], packRgb(glm::u8vec3(3, 2, 7)));  // -Z texel (0, 0): cell (1, 1)'s texel (1, 0)
}

TEST_F(EnvironmentLoading, ThePrefixWinsOverTheCrossWithAWarning) {
    writeCubeFaces((dir / "f_").string(), 4, kGrey);
    const std::string scene = json("\"envMapPrefix\": \"f_\",\n\"envMapVertCross\": \"cross.png\"");  // the cross need not exist
    Diagnostics diagnostics;
    const Scene loaded = loadScene(scene, {}, diagnostics);
    EXPECT_EQ(loaded.environment.faceSize, 4);
    EXPECT_EQ(loaded.envMapVertCross, (dir / "cross.png").string());  // still recorded (the writers keep it)
    ASSERT_EQ(diagnostics.warnings().size(), 1u);
    EXPECT_EQ(diagnostics.warnings()[0].line, lineOfText(fileText(scene), "envMapVertCross"));
    EXPECT_EQ(diagnostics.warnings()[0].problem, kIgnoredVertCross);
}

}  // namespace
}  // namespace vkrt::test
