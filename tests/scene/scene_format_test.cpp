// loadScene picks the format by the file name's extension and confirms it by the content.
#include "scene_test_files.h"

namespace vkrt::test {
namespace {

using SceneFormat = SceneFiles;

const std::string kXml = sceneWith("");
const std::string kJson = jsonWith("");

Scene loadFile(const std::string& path) {
    Diagnostics diagnostics;
    return loadScene(path, {}, diagnostics);
}

Issue errorLoading(const std::string& path) {
    try {
        loadFile(path);
    } catch (const SceneError& error) {
        return error.issue();
    }
    ADD_FAILURE() << "expected a SceneError for " << path;
    return {};
}

TEST_F(SceneFormat, ExtensionAndContentAgreeInAnyCase) {
    EXPECT_EQ(loadFile(write("a.xml", kXml)).cameras.size(), 1u);
    EXPECT_EQ(loadFile(write("a.json", kJson)).cameras.size(), 1u);
    EXPECT_EQ(loadFile(write("b.JSON", kJson)).cameras.size(), 1u);
    EXPECT_EQ(loadFile(write("b.Xml", kXml)).cameras.size(), 1u);
    // A byte order mark and white space before the first byte are skipped.
    EXPECT_EQ(loadFile(write("c.json", "\xEF\xBB\xBF \n\t" + kJson)).cameras.size(), 1u);
}

TEST_F(SceneFormat, ANameThatDisagreesWithTheContentIsAnErrorNamingBoth) {
    const std::string path = write("scene.json", "\n  " + kXml);
    const Issue issue = errorLoading(path);
    EXPECT_EQ(issue.file, path);
    EXPECT_EQ(issue.line, 2);
    EXPECT_EQ(issue.column, 3);
    EXPECT_EQ(issue.problem, "the file is named as JSON but its content is XML");
    EXPECT_EQ(issue.value, "<");
    EXPECT_EQ(errorLoading(write("scene.xml", kJson)).problem, "the file is named as XML but its content is JSON");
}

TEST_F(SceneFormat, AnyOtherNameGoesByTheContent) {
    EXPECT_EQ(loadFile(write("scene.txt", kJson)).cameras.size(), 1u);
    EXPECT_EQ(loadFile(write("scene", kXml)).cameras.size(), 1u);
    const std::string path = write("scene.yaml", "scene:\n  camera: []\n");
    const Issue issue = errorLoading(path);
    EXPECT_EQ(issue.file, path);
    EXPECT_EQ(issue.element, "scene");
    EXPECT_NE(issue.problem.find("cannot tell the scene format"), std::string::npos);
    EXPECT_NE(std::string(SceneError(issue).what()).find(path), std::string::npos);
}

TEST_F(SceneFormat, AKnownNameWithContentOfNeitherKindIsLeftToThatFormatsParser) {
    EXPECT_EQ(errorLoading(write("empty.json", "")).element, "json");
    EXPECT_EQ(errorLoading(write("list.json", "[]")).problem, "expected an object, found an array");
    EXPECT_EQ(errorLoading(write("empty.xml", "  ")).element, "xml");
    EXPECT_NE(errorLoading(write("missing.json", "")).file, "");
    EXPECT_NE(errorLoading((dir / "absent.xml").string()).problem.find("not found"), std::string::npos);
}

}  // namespace
}  // namespace vkrt::test
