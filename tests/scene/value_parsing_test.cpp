// Numbers in element text, as the course files write them, and what happens to bad ones.
#include <cmath>
#include <limits>

#include "scene_test_files.h"

namespace vkrt::test {
namespace {

class ValueParsing : public SceneFiles {
protected:
    // A scene whose only light has the given <intensity> text.
    static std::string withIntensity(const std::string& text) {
        return sceneWith("<light type=\"point\"><position>0 1 0</position><intensity>" + text + "</intensity></light>");
    }
    // A scene whose only sphere has the given <radius> text.
    static std::string withRadius(const std::string& text) {
        return sceneWith("<shader name=\"s\" type=\"Lambertian\"><diffuse>1 1 1</diffuse></shader>\n"
                         "<shape name=\"ball\" type=\"sphere\"><shader ref=\"s\"/><center>0 0 -3</center><radius>" +
                         text + "</radius></shape>");
    }
};

TEST_F(ValueParsing, AcceptsTheSpellingsFoundInCourseFiles) {
    // Leading/trailing/multiple spaces, tabs, newlines, ".8", "1.", "-0.0", "+2", exponents.
    const Scene scene = loadClean(withIntensity("  .8\t 1.  \n -0.0 "));
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.lights[0].intensity, glm::vec3(0.8f, 1.0f, -0.0f));
    EXPECT_TRUE(std::signbit(scene.lights[0].intensity.z));
    EXPECT_EQ(loadClean(withIntensity("+2 1e-1 3E1")).lights[0].intensity, glm::vec3(2.0f, 0.1f, 30.0f));
    EXPECT_EQ(loadClean(withRadius(" 2.5 ")).shapes[0].radius, 2.5f);
}

TEST_F(ValueParsing, CommentInsideAValueIsSkipped) {
    EXPECT_EQ(loadClean(withIntensity("1 <!-- green --> 2 3")).lights[0].intensity, glm::vec3(1, 2, 3));
}

TEST_F(ValueParsing, NumberRunningIntoTheNextIsReadLikeIstreamWithAWarning) {
    // table.xml: "0.0 2.5.0 5.0" -> istream reads 0, 2.5, .0 and leaves "5.0" unread.
    const std::string xml = withIntensity("0.0 2.5.0 5.0");
    Diagnostics diagnostics;
    const Scene scene = load(xml, diagnostics);
    EXPECT_EQ(scene.lights[0].intensity, glm::vec3(0.0f, 2.5f, 0.0f));
    ASSERT_EQ(diagnostics.warnings().size(), 1u);
    const Issue& w = diagnostics.warnings()[0];
    expectIssue(w, lineOf(xml, "<intensity>"), "intensity", "0.0 2.5.0 5.0");
    EXPECT_NE(w.problem.find("0 2.5 0"), std::string::npos) << w.problem;  // says what it read
}

TEST_F(ValueParsing, ExtraTokensAfterThreeNumbersAreAWarning) {
    const std::string xml = withIntensity("1 2 3 4");
    Diagnostics diagnostics;
    EXPECT_EQ(load(xml, diagnostics).lights[0].intensity, glm::vec3(1, 2, 3));
    ASSERT_EQ(diagnostics.warnings().size(), 1u);
    expectIssue(diagnostics.warnings()[0], lineOf(xml, "<intensity>"), "intensity", "1 2 3 4");

    Diagnostics scalar;
    EXPECT_EQ(load(withRadius("1.5 2"), scalar).shapes[0].radius, 1.5f);
    EXPECT_EQ(scalar.warnings().size(), 1u);
}

TEST_F(ValueParsing, StrictTurnsTheRecoveryIntoAnError) {
    const std::string xml = withIntensity("0.0 2.5.0 5.0");
    expectIssue(errorOf(xml, /*strict=*/true), lineOf(xml, "<intensity>"), "intensity", "0.0 2.5.0 5.0");
    const std::string extra = withIntensity("1 2 3 junk");
    expectIssue(errorOf(extra, true), lineOf(extra, "<intensity>"), "intensity", "1 2 3 junk");
}

TEST_F(ValueParsing, MissingComponentIsAnError) {
    const std::string xml = withIntensity("1 2");
    const Issue issue = errorOf(xml);
    expectIssue(issue, lineOf(xml, "<intensity>"), "intensity", "1 2");
    EXPECT_NE(issue.problem.find("expected 3 numbers, found 2"), std::string::npos) << issue.problem;
}

TEST_F(ValueParsing, EmptyValueIsAnError) {
    const std::string xml = withRadius("");
    const Issue issue = errorOf(xml);
    EXPECT_EQ(issue.line, lineOf(xml, "<radius>"));
    EXPECT_EQ(issue.element, "radius");
    EXPECT_NE(issue.problem.find("found 0"), std::string::npos) << issue.problem;
}

TEST_F(ValueParsing, NonNumberIsAnErrorNamingTheToken) {
    for (const char* bad : {"1 two 3", "1 2 x3", "1,2,3", "- 1 2", "0x10 1 2"}) {
        SCOPED_TRACE(bad);
        const std::string xml = withIntensity(bad);
        const Issue issue = errorOf(xml);
        EXPECT_EQ(issue.line, lineOf(xml, "<intensity>"));
        EXPECT_EQ(issue.element, "intensity");
        EXPECT_NE(issue.problem.find("not a number"), std::string::npos) << issue.message();
        EXPECT_NE(std::string(bad).find(issue.value), std::string::npos) << issue.message();
        EXPECT_FALSE(issue.value.empty());
    }
    const std::string xml = withIntensity("1 two 3");
    EXPECT_EQ(errorOf(xml).value, "two");
}

TEST_F(ValueParsing, NanInfAndOutOfRangeAreErrors) {
    for (const char* bad : {"nan", "NaN", "inf", "-infinity", "1e39", "1e400"}) {
        SCOPED_TRACE(bad);
        const std::string xml = withRadius(bad);
        const Issue issue = errorOf(xml);
        expectIssue(issue, lineOf(xml, "<radius>"), "radius", bad);
        EXPECT_NE(issue.problem.find("finite"), std::string::npos) << issue.message();
    }
}

// Accepted as a number; a sphere that large is beyond what float intersection computes, which is
// a warning at the shape (geometry_extent.h), not a parse error.
TEST_F(ValueParsing, LargestFloatIsStillAccepted) {
    Diagnostics diagnostics;
    const Scene scene = load(withRadius("3.4e38"), diagnostics);
    EXPECT_FLOAT_EQ(scene.shapes[0].radius, 3.4e38f);
    EXPECT_TRUE(std::isfinite(scene.shapes[0].radius));
    ASSERT_EQ(diagnostics.warnings().size(), 1u);
    EXPECT_NE(diagnostics.warnings()[0].problem.find("beyond the 1e+18"), std::string::npos) << diagnostics.messages()[0];
}

// The bound is where a float rounds to infinity (2^128 - 2^103 = 3.40282357e38), not the largest
// float itself: 3.4028235e38, the shortest text of the largest float (what vkrt convert writes),
// lies above it and reads as it; 3.4028236e38 is past the midpoint.
TEST_F(ValueParsing, TheLargestFloatsShortestTextReadsAsTheLargestFloat) {
    Diagnostics diagnostics;  // the extent warning of LargestFloatIsStillAccepted
    const Scene scene = load(withRadius("3.4028235e38"), diagnostics);
    EXPECT_EQ(scene.shapes[0].radius, std::numeric_limits<float>::max());
    const std::string xml = withRadius("3.4028236e38");
    EXPECT_NE(errorOf(xml).problem.find("finite"), std::string::npos);
}

}  // namespace
}  // namespace vkrt::test
