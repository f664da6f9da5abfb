// <camera>, <light>, background and environment-map forms (docs/XML_FORMAT.md §3.1-3.4).
#include "json_writer.h"
#include "scene_compare.h"
#include "scene_test_files.h"
#include "xml_writer.h"

namespace vkrt::test {
namespace {

using CameraParsing = SceneFiles;
using LightParsing = SceneFiles;
using BackgroundParsing = SceneFiles;

std::string sceneWithCameras(const std::string& cameras, const std::string& extra = "") {
    return "<scene>\n" + cameras + "\n" + extra + "\n</scene>\n";
}

TEST_F(CameraParsing, PerspectiveWithViewDirAndAllChildren) {
    const Scene scene = loadClean(sceneWithCameras(
        "<camera name=\"main\" type=\"perspective\"><position>0 3.0 4.0</position><viewDir>0 -1.5 -3.0</viewDir>"
        "<focalLength>0.40</focalLength><imagePlaneWidth>0.25</imagePlaneWidth></camera>"));
    ASSERT_EQ(scene.cameras.size(), 1u);
    const Camera& c = scene.cameras[0];
    EXPECT_EQ(c.name, "main");
    EXPECT_EQ(c.type, CameraType::Perspective);
    EXPECT_EQ(c.position, glm::vec3(0, 3, 4));
    EXPECT_EQ(c.gaze, glm::vec3(0, -1.5f, -3));  // kept as written, not normalised
    EXPECT_FLOAT_EQ(c.focalLength, 0.4f);
    EXPECT_FLOAT_EQ(c.imagePlaneWidth, 0.25f);
    EXPECT_EQ(c.where.line, 2);
    EXPECT_EQ(scene.defaultCamera, 0);
}

TEST_F(CameraParsing, DefaultsFocalLengthOneAndImagePlaneWidthHalf) {
    const Scene scene = loadClean(sceneWithCameras("<camera><position>1 2 3</position><viewDir>0 0 -1</viewDir></camera>"));
    EXPECT_EQ(scene.cameras[0].type, CameraType::Perspective);  // no type attribute
    EXPECT_EQ(scene.cameras[0].focalLength, 1.0f);
    EXPECT_EQ(scene.cameras[0].imagePlaneWidth, 0.5f);
}

TEST_F(CameraParsing, LookatPointOverridesViewDirWhicheverComesFirst) {
    const Scene scene = loadClean(sceneWithCameras(
        "<camera><lookatPoint>0 0.0 -3.0</lookatPoint><position>0 6.0 1.0</position><viewDir>1 0 0</viewDir></camera>"));
    EXPECT_EQ(scene.cameras[0].gaze, glm::vec3(0, -6, -4));
}

// Extreme but valid camera values (issue 22): the direction and the focalLength / imagePlaneWidth
// ratio are what the image depends on, so the loader scales them by powers of two (exact) into the
// range where float normalisation neither underflows nor overflows; inside it nothing changes.
TEST_F(CameraParsing, ExtremeViewDirAndFocalLengthAreScaledExactlyIntoFloatRange) {
    const auto camera = [&](const std::string& children) {
        return loadClean(sceneWithCameras("<camera><position>0 0 0</position>" + children + "</camera>")).cameras[0];
    };
    for (const char* tiny : {"0 0 -1e-25", "0 0 -1e-30", "0 0 -1e20", "0 0 -1e-40"}) {
        SCOPED_TRACE(tiny);
        const Camera c = camera(std::string("<viewDir>") + tiny + "</viewDir>");
        EXPECT_EQ(c.gaze.x, 0.0f);
        EXPECT_EQ(c.gaze.y, 0.0f);
        EXPECT_LE(c.gaze.z, -1.0f);  // largest component in [1, 2)
        EXPECT_GT(c.gaze.z, -2.0f);
        EXPECT_EQ(glm::normalize(c.gaze), glm::vec3(0, 0, -1));
    }
    // A direction keeps its components' ratios exactly (a power of two scales every bit pattern).
    const Camera skew = camera("<viewDir>3e-30 -1.5e-30 -6e-30</viewDir>");
    EXPECT_EQ(skew.gaze.x / skew.gaze.z, 3e-30f / -6e-30f);
    EXPECT_EQ(skew.gaze.y / skew.gaze.z, -1.5e-30f / -6e-30f);
    const Camera far = camera("<viewDir>0 0 -1</viewDir><focalLength>1e20</focalLength><imagePlaneWidth>5e19</imagePlaneWidth>");
    EXPECT_EQ(far.focalLength / far.imagePlaneWidth, 1e20f / 5e19f);
    EXPECT_LT(far.focalLength, 2.0f);
    // Inside the range, bit for bit as written.
    const Camera plain = camera("<viewDir>0 -1.5 -3.0</viewDir><focalLength>0.40</focalLength><imagePlaneWidth>0.25</imagePlaneWidth>");
    EXPECT_EQ(plain.gaze, glm::vec3(0, -1.5f, -3));
    EXPECT_EQ(plain.focalLength, 0.4f);
    EXPECT_EQ(plain.imagePlaneWidth, 0.25f);
    // A field narrower than float resolves is loaded with a warning naming it.
    Diagnostics diagnostics;
    load(sceneWithCameras("<camera name=\"tele\"><position>0 0 0</position><viewDir>0 0 -1</viewDir>"
                          "<focalLength>1e20</focalLength></camera>"), diagnostics);
    ASSERT_EQ(diagnostics.warnings().size(), 1u);
    EXPECT_NE(diagnostics.warnings()[0].problem.find("narrower than float directions resolve"), std::string::npos);
    EXPECT_EQ(diagnostics.warnings()[0].value, "tele");
}

TEST_F(CameraParsing, OrthographicIsSupported) {
    const Scene scene = loadClean(sceneWithCameras(
        "<camera type=\"orthographic\"><position>0 0 5</position><viewDir>0 0 -1</viewDir><imagePlaneWidth>4</imagePlaneWidth></camera>"));
    EXPECT_EQ(scene.cameras[0].type, CameraType::Orthographic);
    EXPECT_EQ(scene.cameras[0].imagePlaneWidth, 4.0f);
}

TEST_F(CameraParsing, SeveralCamerasAreKeptInOrderAndSceneParametersCanPickOne) {
    const std::string cameras =
        "<camera name=\"a\"><position>0 0 0</position><viewDir>0 0 -1</viewDir></camera>\n"
        "<camera name=\"b\"><position>1 0 0</position><viewDir>0 0 -1</viewDir></camera>\n"
        "<camera name=\"c\"><position>2 0 0</position><viewDir>0 0 -1</viewDir></camera>";
    const Scene first = loadClean(sceneWithCameras(cameras));
    ASSERT_EQ(first.cameras.size(), 3u);
    EXPECT_EQ(first.cameras[0].name, "a");
    EXPECT_EQ(first.cameras[1].name, "b");
    EXPECT_EQ(first.cameras[2].name, "c");
    EXPECT_EQ(first.defaultCamera, 0);
    const Scene picked = loadClean(sceneWithCameras(cameras, "<sceneParameters><camera> b </camera></sceneParameters>"));
    EXPECT_EQ(picked.defaultCamera, 1);
}

// Issue 21: a thin lens is two optional camera elements, in both formats; negative values are
// errors at the element, one without the other is a warning (the camera stays a pinhole), and both
// writers keep them.
TEST_F(CameraParsing, FocusDistanceAndApertureMakeAThinLens) {
    const std::string xml = sceneWithCameras(
        "<camera><position>0 0 0</position><viewDir>0 0 -1</viewDir><focusDistance>4.5</focusDistance>"
        "<aperture>0.25</aperture></camera>");
    const Scene scene = loadClean(xml);
    EXPECT_EQ(scene.cameras[0].focusDistance, 4.5f);
    EXPECT_EQ(scene.cameras[0].aperture, 0.25f);
    EXPECT_TRUE(scene.cameras[0].thinLens());
    EXPECT_FALSE(loadClean(sceneWithCameras("<camera><position>0 0 0</position><viewDir>0 0 -1</viewDir></camera>")).cameras[0].thinLens());

    const Scene json = loadJsonClean(
        "{\"scene\": {\"camera\": [{\"position\": \"0 0 0\", \"viewDir\": \"0 0 -1\", \"focusDistance\": 4.5, \"aperture\": 0.25}]}}");
    EXPECT_EQ(json.cameras[0].focusDistance, 4.5f);
    EXPECT_EQ(json.cameras[0].aperture, 0.25f);

    for (const std::string& text : {xmlSceneText(scene, dir), jsonSceneText(scene, dir)}) {
        EXPECT_NE(text.find("focusDistance"), std::string::npos) << text;
        EXPECT_NE(text.find("aperture"), std::string::npos) << text;
    }
}

TEST_F(CameraParsing, BadLensValuesAreErrorsAndHalfALensIsAWarning) {
    const std::string negative = sceneWithCameras(
        "<camera><position>0 0 0</position><viewDir>0 0 -1</viewDir>\n<aperture>-0.1</aperture><focusDistance>2</focusDistance></camera>");
    const Issue e = errorOf(negative);
    expectIssue(e, lineOf(negative, "<aperture>"), "aperture", "-0.1");
    EXPECT_NE(e.problem.find("must not be negative"), std::string::npos) << e.message();
    const std::string json = "{\"scene\": {\"camera\": [{\"position\": \"0 0 0\", \"viewDir\": \"0 0 -1\", \"focusDistance\": -3}]}}";
    const Issue j = jsonErrorOf(json);
    expectJsonIssueAt(j, json, "-3", "scene.camera[0].focusDistance", "-3");

    const std::string half = sceneWithCameras(
        "<camera name=\"c\"><position>0 0 0</position><viewDir>0 0 -1</viewDir>\n<focusDistance>2</focusDistance></camera>");
    Diagnostics d;
    const Scene scene = load(half, d);
    ASSERT_EQ(d.warnings().size(), 1u);
    expectIssue(d.warnings()[0], lineOf(half, "<focusDistance>"), "focusDistance", "c");
    EXPECT_NE(d.warnings()[0].problem.find("stays a pinhole"), std::string::npos);
    EXPECT_FALSE(scene.cameras[0].thinLens());
}

// Issue 39: the up vector is vkrt's addition (the course's formats have none; docs/RENDERING.md §1
// has the rule without one): an optional camera element or key, any length, kept by both writers
// and compared by the round trip's model comparison; a file without one writes none.
TEST_F(CameraParsing, UpVectorIsAnOptionalElementThatBothWritersKeep) {
    const Scene xml = loadClean(sceneWithCameras(
        "<camera><position>0 5 0</position><viewDir>0 -1 0</viewDir><up>0 0 -2.5</up></camera>"));
    ASSERT_TRUE(xml.cameras[0].up.has_value());
    EXPECT_EQ(*xml.cameras[0].up, glm::vec3(0, 0, -2.5f));  // kept as written, not normalised
    const Scene json = loadJsonClean("{\"scene\": {\"camera\": [{\"position\": \"0 5 0\", \"viewDir\": \"0 -1 0\", \"up\": \"0 0 -2.5\"}]}}");
    ASSERT_TRUE(json.cameras[0].up.has_value());
    EXPECT_EQ(*json.cameras[0].up, glm::vec3(0, 0, -2.5f));

    for (const Scene& back : {loadClean(xmlSceneText(xml, dir)), loadJsonClean(jsonSceneText(xml, dir))}) {
        const SceneDifferences d = compareScenes(xml, back);
        EXPECT_TRUE(d.equal()) << d.summary();
        ASSERT_TRUE(back.cameras[0].up.has_value());
        EXPECT_EQ(*back.cameras[0].up, glm::vec3(0, 0, -2.5f));
    }
    const Scene none = loadClean(sceneWithCameras("<camera><position>0 5 0</position><viewDir>0 -1 0</viewDir></camera>"));
    EXPECT_FALSE(none.cameras[0].up.has_value());
    for (const std::string& text : {xmlSceneText(none, dir), jsonSceneText(none, dir)})
        EXPECT_TRUE(text.find("<up>") == std::string::npos && text.find("\"up\"") == std::string::npos) << text;

    // The comparison the converter's round trip relies on sees a lost, added or changed up vector.
    Scene changed = xml;
    changed.cameras[0].up = glm::vec3(1, 0, 0);
    EXPECT_NE(compareScenes(xml, changed).summary().find("cameras[0].up: 0 0 -2.5 vs 1 0 0"), std::string::npos)
        << compareScenes(xml, changed).summary();
    EXPECT_NE(compareScenes(xml, none).summary().find("cameras[0].up.given"), std::string::npos)
        << compareScenes(xml, none).summary();
}

TEST_F(CameraParsing, UpVectorsThatCannotOrientTheCameraAreErrorsAtTheElement) {
    const struct {
        const char* up;
        const char* problem;
    } cases[] = {
        {"0 0 0", "zero length"},
        {"0 2 0", "parallel to the view direction"},
        {"0 -1e-30 0", "parallel to the view direction"},  // any length, the direction decides
        {"0.00001 1 0", "parallel to the view direction"},  // within the rule's threshold
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.up);
        const std::string xml = sceneWithCameras(
            std::string("<camera><position>0 5 0</position><viewDir>0 -1 0</viewDir>\n<up>") + c.up + "</up></camera>");
        const Issue e = errorOf(xml);
        expectIssue(e, lineOf(xml, "<up>"), "up", c.up);
        EXPECT_NE(e.problem.find(c.problem), std::string::npos) << e.message();

        const std::string json = std::string("{\"scene\": {\"camera\": [{\"position\": \"0 5 0\", \"viewDir\": \"0 -1 0\",\n\"up\": \"") +
                                 c.up + "\"}]}}";
        const Issue j = jsonErrorOf(json);
        expectJsonIssueAt(j, json, std::string("\"") + c.up, "scene.camera[0].up", c.up);
        EXPECT_NE(j.problem.find(c.problem), std::string::npos) << j.message();
    }
    // Parallel to a lookatPoint gaze too; a non-number is the usual vector error.
    const std::string lookat = sceneWithCameras(
        "<camera><position>0 0 0</position><lookatPoint>3 0 0</lookatPoint>\n<up>-1 0 0</up></camera>");
    expectIssue(errorOf(lookat), lineOf(lookat, "<up>"), "up", "-1 0 0");
    const std::string nan = sceneWithCameras("<camera><position>0 0 0</position><viewDir>0 0 -1</viewDir>\n<up>nan 1 0</up></camera>");
    EXPECT_EQ(errorOf(nan).line, lineOf(nan, "<up>"));
}

TEST_F(CameraParsing, UnknownCameraTypeWarnsAndIsPerspective) {
    const std::string xml = sceneWithCameras("<camera type=\"fisheye\"><position>0 0 0</position><viewDir>0 0 -1</viewDir></camera>");
    Diagnostics diagnostics;
    EXPECT_EQ(load(xml, diagnostics).cameras[0].type, CameraType::Perspective);
    ASSERT_EQ(diagnostics.warnings().size(), 1u);
    expectIssue(diagnostics.warnings()[0], 2, "camera", "fisheye");
}

TEST_F(LightParsing, PointLight) {
    const Scene scene = loadClean(sceneWith("<light type=\"point\"><position>0 10 0</position><intensity>1.0 0.5 0.25</intensity></light>"));
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.lights[0].type, LightType::Point);
    EXPECT_EQ(scene.lights[0].position, glm::vec3(0, 10, 0));
    EXPECT_EQ(scene.lights[0].intensity, glm::vec3(1, 0.5f, 0.25f));
    EXPECT_EQ(scene.lights[0].where.line, 4);
}

TEST_F(LightParsing, AreaLightNormalIsNormalisedAndSizesKept) {
    // happyBuddha puts normal last; student files use non-unit normals like 10 10 10.
    const Scene scene = loadClean(sceneWith(
        "<light type=\"area\"><position>10.0 8.0 1.0</position><intensity>0.8 0.8 0.8</intensity>"
        "<width>8</width><length>4</length><normal>10 10 10</normal></light>"));
    const Light& light = scene.lights[0];
    EXPECT_EQ(light.type, LightType::Area);
    EXPECT_EQ(light.position, glm::vec3(10, 8, 1));
    const float k = 1.0f / std::sqrt(3.0f);
    EXPECT_NEAR(light.normal.x, k, 1e-6f);
    EXPECT_NEAR(light.normal.y, k, 1e-6f);
    EXPECT_NEAR(light.normal.z, k, 1e-6f);
    EXPECT_EQ(light.width, 8.0f);
    EXPECT_EQ(light.length, 4.0f);
}

TEST_F(LightParsing, ZeroSizedAreaLightLoads) {
    // 0x0 is the point light (tests/stability checks the images are identical); only negative
    // sizes are errors (bad_input_test).
    const Scene scene = loadClean(sceneWith(
        "<light type=\"area\"><position>0 5 0</position><intensity>1 1 1</intensity>"
        "<normal>0 -1 0</normal><width>0</width><length>0</length></light>"));
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.lights[0].type, LightType::Area);
    EXPECT_EQ(scene.lights[0].width, 0.0f);
    EXPECT_EQ(scene.lights[0].length, 0.0f);
}

TEST_F(LightParsing, AreaChildrenOnAPointLightAreIgnoredSilently) {
    // solarSystem.xml, oneSphereUpPt.xml; even a zero normal there is not looked at.
    const Scene scene = loadClean(sceneWith(
        "<light type=\"point\" name=\"main-light\"><position>1 2 3</position><intensity>1 1 1</intensity>"
        "<normal>0 0 0</normal><width>-1</width><length>4</length></light>"));
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.lights[0].type, LightType::Point);
}

TEST_F(LightParsing, UnknownLightTypeWarnsAndIsSkipped) {
    const std::string xml = sceneWith(
        "<light type=\"spot\"><position>0 1 0</position><intensity>1 1 1</intensity></light>\n"
        "<light type=\"point\"><position>0 2 0</position><intensity>1 1 1</intensity></light>");
    Diagnostics diagnostics;
    const Scene scene = load(xml, diagnostics);
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.lights[0].position.y, 2.0f);
    ASSERT_EQ(diagnostics.warnings().size(), 1u);
    expectIssue(diagnostics.warnings()[0], lineOf(xml, "spot"), "light", "spot");
}

// vkrt's addition (docs/XML_FORMAT.md §3.4), the JSON shape light in XML so that vkrt convert
// keeps it: an emitter from any shape, an instance with its transform included; the shape's
// shader is optional. Emitter::lightsBefore keeps its place among the lights.
TEST_F(LightParsing, ShapeLightsAreEmittersAsInJson) {
    const std::string xml = sceneWith(
        "<shader name=\"grey\" type=\"Lambertian\"><diffuse>0.5 0.5 0.5</diffuse></shader>\n"
        "<instance name=\"box\" type=\"box\"><shader ref=\"grey\"/><minPt>0 0 0</minPt><maxPt>2 2 2</maxPt></instance>\n"
        "<light type=\"shape\"><intensity>1 0.5 0</intensity><shape type=\"sphere\"><center>1 2 3</center><radius>0.5</radius></shape></light>\n"
        "<light type=\"shape\"><intensity>0 0 2</intensity><shape name=\"lamp\" type=\"instance\" id=\"box\">"
        "<shader type=\"Lambertian\"><diffuse>1 1 1</diffuse></shader><transform><translate>10 0 0</translate></transform></shape></light>");
    Diagnostics diagnostics;
    const Scene scene = load(xml, diagnostics);
    ASSERT_EQ(scene.emitters.size(), 2u);
    EXPECT_EQ(scene.emitters[0].shape.center, glm::vec3(1, 2, 3));
    EXPECT_EQ(scene.emitters[0].shape.shader, -1);
    EXPECT_EQ(scene.emitters[0].radiance, glm::vec3(1, 0.5f, 0));
    EXPECT_EQ(scene.emitters[1].prototype, 0);
    EXPECT_EQ(scene.emitters[1].name, "lamp");
    ASSERT_EQ(scene.emitters[1].shape.shader, 1);  // the inline (nameless) definition, registered in pass 1
    EXPECT_EQ(scene.shaders[1].diffuse, glm::vec3(1.0f));
    EXPECT_TRUE(scene.lights.empty());  // a shape light is an emitter only
    EXPECT_EQ(scene.emitters[0].lightsBefore, 0);
    EXPECT_EQ(scene.emitters[1].lightsBefore, 0);
    EXPECT_TRUE(diagnostics.warnings().empty());  // rendered as what it is: no fallback warning

    const std::string noShape = sceneWith("<light type=\"shape\"><intensity>1 1 1</intensity></light>");
    expectIssue(errorOf(noShape), lineOf(noShape, "<light"), "light", "");
    const std::string badId = sceneWith(
        "<light type=\"shape\"><intensity>1 1 1</intensity><shape type=\"instance\" id=\"nothing\"/></light>");
    expectIssue(errorOf(badId), lineOf(badId, "<shape"), "shape", "nothing");
}

TEST_F(BackgroundParsing, DefaultIsBlack) {
    const Scene scene = loadClean(sceneWith(""));
    EXPECT_EQ(scene.background, glm::vec3(0.0f));
    EXPECT_TRUE(scene.envMapPrefix.empty());
}

TEST_F(BackgroundParsing, RootAttribute) {
    EXPECT_EQ(loadClean(sceneWith("", " bgColor=\"0.5 0.25 1\"")).background, glm::vec3(0.5f, 0.25f, 1.0f));
}

TEST_F(BackgroundParsing, SceneParametersElementWinsOverTheAttribute) {
    const Scene scene = loadClean(
        sceneWith("<sceneParameters><bgColor>0.1 0.2 0.3</bgColor></sceneParameters>", " bgColor=\"1 0 0\""));
    EXPECT_EQ(scene.background, glm::vec3(0.1f, 0.2f, 0.3f));
}

TEST_F(BackgroundParsing, MalformedAttributeNamesTheAttribute) {
    const Issue issue = errorOf(sceneWith("", " bgColor=\"0.5 0.5\""));
    expectIssue(issue, 2, "scene bgColor", "0.5 0.5");
}

TEST_F(BackgroundParsing, EnvMapPrefixAttributeIsResolvedAndLoaded) {
    writeCubeFaces("data/reef_");
    const std::string xml = sceneWith("", " bgColor=\"1 0 0\" envmapPrefix=\"data/reef_\"");
    const Scene scene = loadClean(xml);
    EXPECT_EQ(scene.envMapPrefix, (dir / "data/reef_").lexically_normal().string());  // resolved against the file
    EXPECT_EQ(scene.background, glm::vec3(1, 0, 0));
    EXPECT_EQ(scene.environment.faceSize, 2);
    EXPECT_EQ(scene.environment.where.line, 2);
}

TEST_F(BackgroundParsing, EnvMapPrefixElementWinsOverTheAttribute) {
    writeCubeFaces("images/reef_");  // data/reef_, the attribute's, does not exist: it is not read
    const std::string xml = sceneWith(
        "<sceneParameters>\n<bgColor>0.5 0.5 0.6</bgColor>\n<envMapPrefix>images/reef_</envMapPrefix>\n</sceneParameters>",
        " envmapPrefix=\"data/reef_\"");
    const Scene scene = loadClean(xml);
    EXPECT_EQ(scene.envMapPrefix, (dir / "images/reef_").lexically_normal().string());
    EXPECT_EQ(scene.environment.where.line, lineOf(xml, "<envMapPrefix>"));
}

TEST_F(BackgroundParsing, AMissingEnvironmentMapIsAnErrorAtItsElement) {
    const std::string xml = sceneWith("", " envmapPrefix=\"data/reef_\"");
    expectIssue(errorOf(xml), 2, "scene", (dir / "data/reef_posX.png").lexically_normal().string());
}

// The vertical-cross image is its own field, not the cube faces' prefix (as in JSON); with both
// given, the cube faces are the map and the cross is warned about.
TEST_F(BackgroundParsing, EnvMapVertCrossIsKeptApartFromThePrefix) {
    writeCubeFaces("images/reef_");
    const std::string xml = sceneWith(
        "<sceneParameters>\n<envMapPrefix>images/reef_</envMapPrefix>\n<envMapVertCross>cross.png</envMapVertCross>\n</sceneParameters>");
    Diagnostics diagnostics;
    const Scene scene = load(xml, diagnostics);
    EXPECT_EQ(scene.envMapPrefix, (dir / "images/reef_").lexically_normal().string());
    EXPECT_EQ(scene.envMapVertCross, (dir / "cross.png").lexically_normal().string());
    ASSERT_EQ(diagnostics.warnings().size(), 1u);
    expectIssue(diagnostics.warnings()[0], lineOf(xml, "<envMapVertCross>"), "envMapVertCross", "cross.png");
}

}  // namespace
}  // namespace vkrt::test
