// Diagnostics and SceneError on their own: the one-line message format, strictness, and the summary
// that vkrt prints (one line per distinct warning).
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "diagnostics.h"

namespace vkrt {
namespace {

TEST(Diagnostics, MessageNamesFileLineElementProblemAndQuotedValue) {
    const Issue issue{"dir/scene.xml", 12, "radius", "radius must be positive", "-1"};
    EXPECT_EQ(issue.message(), "dir/scene.xml:12: radius: radius must be positive '-1'");
}

TEST(Diagnostics, AJsonMessageNamesTheColumnAndThePath) {
    Issue issue{"dir/scene.json", 12, "scene.shape[3].radius", "radius must be positive", "-1"};
    issue.column = 17;
    EXPECT_EQ(issue.message(), "dir/scene.json:12:17: scene.shape[3].radius: radius must be positive '-1'");
}

TEST(Diagnostics, MessageOmitsQuotesWhenThereIsNoValue) {
    const Issue issue{"a.xml", 3, "shape", "missing required element <radius>", ""};
    EXPECT_EQ(issue.message(), "a.xml:3: shape: missing required element <radius>");
}

TEST(Diagnostics, MultiLineValueIsFlattenedAndLongValueShortened) {
    const Issue multiLine{"a.xml", 1, "position", "not a number", "1\n\t 2\r\n3"};
    EXPECT_EQ(multiLine.message(), "a.xml:1: position: not a number '1 2 3'");
    const Issue longValue{"a.xml", 1, "e", "p", std::string(5000, 'x')};
    const std::string message = longValue.message();
    EXPECT_LT(message.size(), 300u);
    EXPECT_NE(message.find("...'"), std::string::npos);
}

TEST(Diagnostics, MultiLineProblemIsFlattened) {
    const Issue issue{"a.obj", 0, "file", "not a readable OBJ file (Failed parse `f' line.\nline 4\n)", "a.obj"};
    EXPECT_EQ(issue.message(), "a.obj:0: file: not a readable OBJ file (Failed parse `f' line. line 4 ) 'a.obj'");
}

TEST(Diagnostics, SceneErrorWhatIsTheMessage) {
    const SceneError error(Issue{"s.xml", 7, "camera", "view direction has zero length", "0 0 0"});
    EXPECT_STREQ(error.what(), "s.xml:7: camera: view direction has zero length '0 0 0'");
    EXPECT_EQ(error.issue().line, 7);
    const std::runtime_error& base = error;  // catchable as a runtime_error by callers
    EXPECT_STREQ(base.what(), error.what());
}

TEST(Diagnostics, CollectsWarningsInOrder) {
    Diagnostics diagnostics;
    diagnostics.warn({"a.xml", 2, "x", "first", ""});
    diagnostics.warn({"a.xml", 9, "y", "second", "v"});
    ASSERT_EQ(diagnostics.warnings().size(), 2u);
    EXPECT_EQ(diagnostics.messages()[0], "a.xml:2: x: first");
    EXPECT_EQ(diagnostics.messages()[1], "a.xml:9: y: second 'v'");
}

TEST(Diagnostics, AHintFollowsTheQuotedValue) {
    Issue issue{"s.json", 3, "scene.shape[0]._type", "unknown shape type, skipped", "shpere", 22};
    issue.hint = "did you mean 'sphere'?";
    EXPECT_EQ(issue.message(), "s.json:3:22: scene.shape[0]._type: unknown shape type, skipped 'shpere'; did you mean 'sphere'?");
}

// What vkrt prints: warnings that differ only in their line, value and JSON indices are one line,
// the first of them with how many more and their lines; another problem, element kind, hint or
// file is another line, in the order first found.
TEST(Diagnostics, SummaryPrintsEachDistinctWarningOnceWithHowManyMoreAndWhere) {
    Diagnostics diagnostics;
    for (int i = 0; i < 5; ++i)
        diagnostics.warn({"s.json", 10 + 9 * i, "scene.shader[" + std::to_string(6 + i) + "].diffuse", "not used by a Mirror shader, ignored", "", 3});
    diagnostics.warn({"s.json", 11, "scene.shader[6].specular", "not used by a Mirror shader, ignored", "", 3});
    diagnostics.warn({"s.json", 12, "scene.shape[0].radius", "radius must be positive", "-1"});
    diagnostics.warn({"s.json", 80, "scene.shape[4].radius", "radius must be positive", "-2"});
    diagnostics.warn({"other.json", 5, "scene.shape[0].radius", "radius must be positive", "-3"});
    Issue typo{"s.json", 90, "scene.shape[5]._type", "unknown shape type, skipped", "shpere"};
    typo.hint = "did you mean 'sphere'?";
    diagnostics.warn(typo);
    diagnostics.warn({"s.json", 91, "scene.shape[6]._type", "unknown shape type, skipped", "cylinder"});
    diagnostics.warn({"s.json", 95, "scene.shape[7]._type", "unknown shape type, skipped", "cone"});
    ASSERT_EQ(diagnostics.warnings().size(), 12u);  // every warning is kept; only the printing folds them
    const std::vector<std::string> lines = diagnostics.summary();
    ASSERT_EQ(lines.size(), 6u) << ::testing::PrintToString(lines);
    EXPECT_EQ(lines[0], "s.json:10:3: scene.shader[6].diffuse: not used by a Mirror shader, ignored (and 4 more like it, lines 19-46)");
    EXPECT_EQ(lines[1], "s.json:11:3: scene.shader[6].specular: not used by a Mirror shader, ignored");
    EXPECT_EQ(lines[2], "s.json:12: scene.shape[0].radius: radius must be positive '-1' (and 1 more like it, line 80)");
    EXPECT_EQ(lines[3], "other.json:5: scene.shape[0].radius: radius must be positive '-3'");
    EXPECT_EQ(lines[4], "s.json:90: scene.shape[5]._type: unknown shape type, skipped 'shpere'; did you mean 'sphere'?");
    EXPECT_EQ(lines[5], "s.json:91: scene.shape[6]._type: unknown shape type, skipped 'cylinder' (and 1 more like it, line 95)");
}

TEST(Diagnostics, SummaryOfWarningsWithoutLinesNamesNoLines) {
    Diagnostics diagnostics;
    diagnostics.warn({"a.obj", 0, "obj", "not a readable OBJ file", ""});
    diagnostics.warn({"a.obj", 0, "obj", "not a readable OBJ file", ""});
    ASSERT_EQ(diagnostics.summary().size(), 1u);
    EXPECT_EQ(diagnostics.summary()[0], "a.obj:0: obj: not a readable OBJ file (and 1 more like it)");
}

TEST(Diagnostics, StrictRaisesTheWarningAsSceneError) {
    Diagnostics diagnostics(/*strict=*/true);
    try {
        diagnostics.warn({"a.xml", 4, "attribute", "unknown element", ""});
        FAIL() << "strict warn must throw";
    } catch (const SceneError& error) {
        EXPECT_STREQ(error.what(), "a.xml:4: attribute: unknown element");
    }
    EXPECT_TRUE(diagnostics.warnings().empty());
}

}  // namespace
}  // namespace vkrt
