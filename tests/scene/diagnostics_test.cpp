// Diagnostics and SceneError on their own: the one-line message format and strictness.
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
