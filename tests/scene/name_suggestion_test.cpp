// "did you mean" after a misspelt name (name_suggestion.h): the distance, when a name is close
// enough, and the hint on the loaders' warnings in both formats (and on the error --strict makes of
// them).
#include "name_suggestion.h"
#include "scene_rules.h"
#include "scene_test_files.h"

namespace vkrt::test {
namespace {

TEST(NameSuggestion, EditDistanceCountsASwapOfNeighboursAsOneAndIgnoresCase) {
    EXPECT_EQ(editDistance("sphere", "sphere"), 0);
    EXPECT_EQ(editDistance("shpere", "sphere"), 1);  // swapped neighbours
    EXPECT_EQ(editDistance("sphre", "sphere"), 1);   // a letter missing
    EXPECT_EQ(editDistance("spheere", "sphere"), 1); // a letter extra
    EXPECT_EQ(editDistance("phongexp", "phongExp"), 0);
    EXPECT_EQ(editDistance("box", "sphere"), 6);
    EXPECT_EQ(editDistance("", "mesh"), 4);
}

TEST(NameSuggestion, SuggestsTheOneCloseNameOnly) {
    EXPECT_EQ(didYouMean("shpere", rules::shapeTypeNames(true)), "did you mean 'sphere'?");
    EXPECT_EQ(didYouMean("instanse", rules::shapeTypeNames(true)), "did you mean 'instance'?");
    EXPECT_EQ(didYouMean("BlinPhong", rules::shaderTypeNames()), "did you mean 'BlinnPhong'?");
    EXPECT_EQ(didYouMean("phongexp", {"diffuse", "specular", "phongExp"}), "did you mean 'phongExp'?");
    // Far off, too short to tell a typo from another name, or as close to two names: nothing.
    EXPECT_EQ(didYouMean("cylinder", rules::shapeTypeNames(true)), "");
    EXPECT_EQ(didYouMean("wireframe", {"center", "radius", "shader"}), "");
    EXPECT_EQ(didYouMean("v3", {"v0", "v1", "v2"}), "");
    EXPECT_EQ(didYouMean("cat", {"bat", "car"}), "");
    // Two spellings of one name (envMapPrefix, envmapPrefix) are not a tie.
    EXPECT_EQ(didYouMean("envMapPrefx", {"envMapPrefix", "envmapPrefix"}), "did you mean 'envMapPrefix'?");
}

using NameSuggestions = SceneFiles;

TEST_F(NameSuggestions, XmlUnknownElementAttributeAndTypeSayWhatWasMeant) {
    Diagnostics diagnostics;
    load(sceneWith("<shader name=\"s\" type=\"BlinnPhong\"><diffuse>1 1 1</diffuse><phongexp>8</phongexp></shader>\n"
                   "<shape tpye=\"x\" type=\"shpere\"><shader ref=\"s\"/><center>0 0 0</center><radius>1</radius></shape>\n"
                   "<shape type=\"cylinder\"><shader ref=\"s\"/></shape>\n"
                   "<lihgt type=\"point\"/>"),
         diagnostics);
    const std::vector<Issue>& w = diagnostics.warnings();
    ASSERT_EQ(w.size(), 5u) << ::testing::PrintToString(diagnostics.messages());
    EXPECT_EQ(w[0].element, "phongexp");
    EXPECT_EQ(w[0].hint, "did you mean 'phongExp'?");
    EXPECT_EQ(w[1].element, "lihgt");
    EXPECT_EQ(w[1].hint, "did you mean 'light'?");
    EXPECT_EQ(w[2].value, "tpye");
    EXPECT_EQ(w[2].hint, "did you mean 'type'?");
    EXPECT_EQ(w[3].value, "shpere");
    EXPECT_EQ(w[3].hint, "did you mean 'sphere'?");
    EXPECT_EQ(w[4].value, "cylinder");
    EXPECT_EQ(w[4].hint, "");
}

TEST_F(NameSuggestions, JsonUnknownKeyAndTypeSayWhatWasMeant) {
    Diagnostics diagnostics;
    loadJson(jsonWith(R"("shader": [{"_name": "s", "_type": "Lambertian", "diffuse": "1 0 0", "difuse": "1 1 1"}],
"shape": [{"_type": "shpere", "center": "0 0 0", "radius": 1, "shader": {"_ref": "s"}},
          {"_type": "sphere", "_tpye": "x", "center": "0 0 0", "radius": 1, "shader": {"_ref": "s"}},
          {"_type": "cylinder"}])"),
             diagnostics);
    const std::vector<Issue>& w = diagnostics.warnings();
    ASSERT_EQ(w.size(), 4u) << ::testing::PrintToString(diagnostics.messages());
    EXPECT_EQ(w[0].element, "scene.shader[0].difuse");
    EXPECT_EQ(w[0].hint, "did you mean 'diffuse'?");
    EXPECT_EQ(w[1].element, "scene.shape[0]._type");
    EXPECT_EQ(w[1].hint, "did you mean 'sphere'?");
    EXPECT_EQ(w[2].element, "scene.shape[1]._tpye");
    EXPECT_EQ(w[2].hint, "did you mean '_type'?");
    EXPECT_EQ(w[3].value, "cylinder");
    EXPECT_EQ(w[3].hint, "");
}

// --strict makes the warning the error, and the error says what was meant too.
TEST_F(NameSuggestions, StrictErrorCarriesTheSuggestion) {
    const Issue issue = jsonErrorOf(jsonWith(R"("shape": [{"_type": "shpere", "center": "0 0 0", "radius": 1}])"), /*strict=*/true);
    EXPECT_NE(issue.message().find("unknown shape type, skipped 'shpere'; did you mean 'sphere'?"), std::string::npos)
        << issue.message();
}

}  // namespace
}  // namespace vkrt::test
