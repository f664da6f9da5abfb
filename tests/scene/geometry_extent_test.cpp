// Geometry beyond what float intersection handles is warned at the element (geometry_extent.h,
// issue 22): a triangle more than 1e12 from the eye, a sphere, box or light more than 1e18 from it,
// a triangle spanning more than 2^20 times its distance from the eye. The limits themselves are
// measured on both renderers in tests/stability/extent_limits_test.cpp; here: which elements warn,
// where, and that nearer ones do not.
#include "scene_test_files.h"

namespace vkrt::test {
namespace {

using GeometryExtent = SceneFiles;

const std::string kShader = "<shader name=\"s\" type=\"Lambertian\"><diffuse>1 1 1</diffuse></shader>\n";

std::string sphereAt(const std::string& z) {
    return "<shape name=\"ball\" type=\"sphere\"><shader ref=\"s\"/><center>0 0 " + z + "</center><radius>1</radius></shape>";
}

TEST_F(GeometryExtent, SpheresBoxesAndLightsBeyond1e18FromTheEyeWarnAtTheirLine) {
    Diagnostics near;
    load(sceneWith(kShader + sphereAt("-1e17") + "<light type=\"point\"><position>0 1e17 0</position><intensity>1 1 1</intensity></light>"), near);
    EXPECT_TRUE(near.warnings().empty()) << near.messages()[0];

    const std::string far = sceneWith(kShader + sphereAt("-1e19") +
                                      "\n<shape name=\"slab\" type=\"box\"><shader ref=\"s\"/><minPt>-1 -1 -1</minPt><maxPt>1 2e18 1</maxPt></shape>"
                                      "\n<light type=\"point\"><position>0 1e20 0</position><intensity>1 1 1</intensity></light>");
    Diagnostics d;
    load(far, d);
    ASSERT_EQ(d.warnings().size(), 3u);
    expectIssue(d.warnings()[0], lineOf(far, "name=\"ball\""), "shape 'ball'", "");
    EXPECT_NE(d.warnings()[0].problem.find("reaches 1e+19 from the camera's eye"), std::string::npos) << d.messages()[0];
    expectIssue(d.warnings()[1], lineOf(far, "name=\"slab\""), "shape 'slab'", "");
    expectIssue(d.warnings()[2], lineOf(far, "<light"), "light", "");
    EXPECT_NE(d.warnings()[2].problem.find("may light nothing"), std::string::npos) << d.messages()[2];
    // --strict: the first becomes the error.
    EXPECT_NE(errorOf(far, /*strict=*/true).message().find("shape 'ball'"), std::string::npos);
}

TEST_F(GeometryExtent, TrianglesBeyond1e12FromTheEyeWarn) {
    const auto tri = [](const std::string& z) {
        return "<shape name=\"tri\" type=\"triangle\"><shader ref=\"s\"/><v0>-1 -1 " + z + "</v0><v1>1 -1 " + z + "</v1><v2>0 1 " + z +
               "</v2></shape>";
    };
    Diagnostics near;
    load(sceneWith(kShader + tri("-1e11")), near);
    EXPECT_TRUE(near.warnings().empty()) << near.messages()[0];
    const std::string far = sceneWith(kShader + tri("-1e13"));
    Diagnostics d;
    load(far, d);
    ASSERT_EQ(d.warnings().size(), 1u);
    expectIssue(d.warnings()[0], lineOf(far, "name=\"tri\""), "shape 'tri'", "");
    EXPECT_NE(d.warnings()[0].problem.find("a corner lies 1e+13"), std::string::npos) << d.messages()[0];
}

// One ground triangle of half-width W seen from 1 above: hits near the camera are computed to
// ~2^-24 W, garbage at W = 1e7 (measured in extent_limits_test.cpp).
TEST_F(GeometryExtent, AHugeTriangleNearTheEyeWarnsAboutItsResolution) {
    const auto ground = [](const std::string& w) {
        return "<shape name=\"ground\" type=\"triangle\"><shader ref=\"s\"/><v0>-" + w + " -1 " + w + "</v0><v1>" + w + " -1 " + w +
               "</v1><v2>0 -1 -" + w + "</v2></shape>";
    };
    Diagnostics fine;
    load(sceneWith(kShader + ground("1e5")), fine);
    EXPECT_TRUE(fine.warnings().empty()) << fine.messages()[0];
    const std::string huge = sceneWith(kShader + ground("1e7"));
    Diagnostics d;
    load(huge, d);
    ASSERT_EQ(d.warnings().size(), 1u);
    expectIssue(d.warnings()[0], lineOf(huge, "name=\"ground\""), "shape 'ground'", "");
    EXPECT_NE(d.warnings()[0].problem.find("passes 1 from it"), std::string::npos) << d.messages()[0];
    EXPECT_NE(d.warnings()[0].problem.find("split it into smaller triangles"), std::string::npos) << d.messages()[0];
    // A triangle whose plane holds the eye is seen edge-on: nothing to resolve, no warning.
    Diagnostics edgeOn;
    load(sceneWith(kShader + "<shape name=\"t\" type=\"triangle\"><shader ref=\"s\"/><v0>0 0 0</v0><v1>1e7 0 0</v1><v2>0 1e7 0</v2></shape>"),
         edgeOn);
    EXPECT_TRUE(edgeOn.warnings().empty()) << edgeOn.messages()[0];
}

// Meshes are checked triangle by triangle where placed: an instance scaled by 1e13 warns at the
// instance, naming the mesh triangle; the same mesh at scale 1 does not.
TEST_F(GeometryExtent, AnInstancedMeshWarnsAtTheInstanceNamingTheTriangle) {
    write("tri.obj", "v -1 -1 -5\nv 1 -1 -5\nv 0 1 -5\nf 1 2 3\n");
    const std::string body = kShader + "<instance name=\"m\" type=\"mesh\"><file>tri.obj</file><shader ref=\"s\"/></instance>\n" +
                             "<shape name=\"small\" type=\"instance\" id=\"m\"/>\n"
                             "<shape name=\"huge\" type=\"instance\" id=\"m\"><transform><scale>1e13 1e13 1e13</scale></transform></shape>";
    const std::string xml = sceneWith(body);
    Diagnostics d;
    load(xml, d);
    ASSERT_EQ(d.warnings().size(), 1u);
    expectIssue(d.warnings()[0], lineOf(xml, "name=\"huge\""), "instance 'huge'", "");
    EXPECT_NE(d.warnings()[0].problem.find("triangle 0 of"), std::string::npos) << d.messages()[0];
}

// Distances are from the eye, not the origin: the same scene 1e15 away (camera included) is fine
// when rebased (what renders load), and, unrebased, still measured from the eye, so it is fine too.
TEST_F(GeometryExtent, DistancesAreMeasuredFromTheEye) {
    const std::string json = jsonWith(
        "\"shader\": [{\"_name\": \"s\", \"_type\": \"Lambertian\", \"diffuse\": \"1 1 1\"}],\n"
        "\"shape\": [{\"_name\": \"ball\", \"_type\": \"sphere\", \"shader\": {\"_ref\": \"s\"}, \"center\": \"0 0 -1e19\", \"radius\": 1}]");
    Diagnostics d;
    loadJson(json, d);
    ASSERT_EQ(d.warnings().size(), 1u);
    expectJsonIssueAt(d.warnings()[0], json, "{\"_name\": \"ball\"", "shape 'ball'", "");
    // Camera and sphere both 1e15 from the origin, 5 apart.
    const std::string xml = "<scene><camera name=\"c\" type=\"perspective\"><position>1e15 0 5</position><viewDir>0 0 -1</viewDir></camera>" +
                            kShader + "<shape name=\"b\" type=\"sphere\"><shader ref=\"s\"/><center>1e15 0 0</center><radius>1</radius></shape></scene>";
    Diagnostics unrebased;
    load(xml, unrebased);
    EXPECT_TRUE(unrebased.warnings().empty()) << unrebased.messages()[0];
}

}  // namespace
}  // namespace vkrt::test
