// Every JSON form the corpus uses (docs/JSON_FORMAT.md), one test each, on small files written
// by the test; positions are computed from the text the test wrote.
#include <cmath>
#include <fstream>

#include "scene_test_files.h"

namespace vkrt::test {
namespace {

using JsonForms = SceneFiles;

const std::string kGrey = R"("shader": [{"_name": "grey", "_type": "Lambertian", "diffuse": "0.5 0.5 0.5"}])";

glm::vec3 apply(const glm::mat4& m, glm::vec3 p) { return glm::vec3(m * glm::vec4(p, 1.0f)); }

void expectNear(glm::vec3 got, glm::vec3 expected) {
    EXPECT_NEAR(got.x, expected.x, 1e-5f);
    EXPECT_NEAR(got.y, expected.y, 1e-5f);
    EXPECT_NEAR(got.z, expected.z, 1e-5f);
}

TEST_F(JsonForms, TheCurrentFormLoadsCleanWithTheXmlDefaults) {
    const Scene scene = loadJsonClean(jsonWith(
        R"("light": [{"_type": "point", "position": "0 5 0", "intensity": "1 1 1"}],)" "\n" +
        std::string(R"("shader": [{"_name": "m", "_type": "Mirror"}, {"_name": "p", "_type": "BlinnPhong", "diffuse": "1 0 0"}],)") + "\n" +
        R"("shape": [{"_type": "sphere", "_name": "ball", "center": "0 0 -3", "radius": 1, "shader": {"_ref": "p"}}])"));
    ASSERT_EQ(scene.cameras.size(), 1u);
    EXPECT_EQ(scene.cameras[0].name, "main");
    EXPECT_EQ(scene.cameras[0].type, CameraType::Perspective);
    EXPECT_EQ(scene.cameras[0].focalLength, 1.0f);
    EXPECT_EQ(scene.cameras[0].imagePlaneWidth, 0.5f);
    EXPECT_EQ(scene.cameras[0].where.line, 3);
    EXPECT_EQ(scene.cameras[0].where.column, 12);  // the camera object's '{' in `"camera": [{`
    EXPECT_EQ(scene.shaders[0].roughness, 0.0f);
    EXPECT_EQ(scene.shaders[1].phongExp, 1.0f);
    EXPECT_EQ(scene.shaders[1].specular, glm::vec3(0.0f));
    EXPECT_EQ(scene.background, glm::vec3(0.0f));
    ASSERT_EQ(scene.shapes.size(), 1u);
    EXPECT_EQ(scene.shapes[0].name, "ball");
    EXPECT_EQ(scene.shapes[0].shader, 1);
    EXPECT_EQ(scene.path, jsonPath);
}

TEST_F(JsonForms, PlainAndUnderscoreKeysAreBothReadAndThePlainOneWins) {
    const std::string json = jsonWith(
        R"("shader": [{"name": "a", "type": "Lambertian", "diffuse": "1 0 0"},)" "\n"
        R"({"name": "b", "_name": "c", "_type": "Lambertian", "diffuse": "0 1 0"}],)" "\n"
        R"("instance": [{"name": "proto", "type": "sphere", "center": "0 0 0", "radius": 1, "shader": {"ref": "a"}}],)" "\n"
        R"("shape": [{"type": "instance", "id": "proto", "shader": {"ref": "b"}}])");
    Diagnostics diagnostics;
    const Scene scene = loadJson(json, diagnostics);
    EXPECT_EQ(scene.shaders[1].name, "b");
    EXPECT_EQ(scene.instances.at(0).shaderOverride, 1);
    ASSERT_EQ(diagnostics.warnings().size(), 1u);
    expectJsonIssueAt(diagnostics.warnings()[0], json, R"("_name": "c")", "scene.shader[1]._name", "");
    EXPECT_EQ(diagnostics.warnings()[0].problem, "both name and _name given, name is used");
}

TEST_F(JsonForms, VectorsAreStringsOrArraysOfThreeNumbers) {
    const Scene scene = loadJsonClean(jsonWith(
        R"("light": [{"_type": "point", "position": [1, 2.5, -3e0], "intensity": "  .8 1. -0.0 "}])"));
    EXPECT_EQ(scene.lights[0].position, glm::vec3(1, 2.5f, -3));
    EXPECT_EQ(scene.lights[0].intensity, glm::vec3(0.8f, 1, 0));
    EXPECT_TRUE(std::signbit(scene.lights[0].intensity.z));
}

TEST_F(JsonForms, NumberListsAreReadLikeTheCoursesIstreamWithAWarning) {
    const std::string json = jsonWith(R"("light": [{"_type": "point", "position": "0.0 2.5.0 5.0", "intensity": "1 1 1"}])");
    Diagnostics diagnostics;
    const Scene scene = loadJson(json, diagnostics);
    EXPECT_EQ(scene.lights[0].position, glm::vec3(0, 2.5f, 0));
    ASSERT_EQ(diagnostics.warnings().size(), 1u);
    expectJsonIssueAt(diagnostics.warnings()[0], json, "\"0.0 2.5.0", "scene.light[0].position", "0.0 2.5.0 5.0");
    EXPECT_EQ(diagnostics.warnings()[0].problem, "malformed number list, read as '0 2.5 0' like the course's istream parser");
}

TEST_F(JsonForms, StringScalarsOfTheFirstFilesAreReadWithAWarning) {
    const std::string json = "{\"scene\": {\n\"camera\": {\"position\": \"0 0 0\", \"viewDir\": \"0 0 -1\", \"focalLength\": \"0.25\"}\n}}";
    Diagnostics diagnostics;
    const Scene scene = loadJson(json, diagnostics);
    EXPECT_EQ(scene.cameras.at(0).focalLength, 0.25f);
    ASSERT_EQ(diagnostics.warnings().size(), 1u);
    expectJsonIssueAt(diagnostics.warnings()[0], json, "\"0.25\"", "scene.camera.focalLength", "0.25");
}

TEST_F(JsonForms, CameraAndLightMayBeSingleObjects) {
    const Scene scene = loadJsonClean(
        "{\"scene\": {\"camera\": {\"position\": \"1 2 3\", \"lookatPoint\": \"1 2 0\"},\n"
        "\"light\": {\"_type\": \"point\", \"position\": \"0 1 0\", \"intensity\": \"1 1 1\"}}}");
    ASSERT_EQ(scene.cameras.size(), 1u);
    EXPECT_EQ(scene.cameras[0].gaze, glm::vec3(0, 0, -3));  // lookatPoint - position
    ASSERT_EQ(scene.lights.size(), 1u);
}

TEST_F(JsonForms, TheDocumentItselfMayBeTheScene) {
    // J26 steps into "scene" when there is one, else reads the document as the scene.
    const Scene scene = loadJsonClean(R"({"camera": [{"position": "0 0 0", "viewDir": "0 0 -1"}], "bgColor": "0 0 1"})");
    EXPECT_EQ(scene.background, glm::vec3(0, 0, 1));
}

TEST_F(JsonForms, LightTypeDefaultsToPointAndAreaLightsKeepTheirSize) {
    const Scene scene = loadJsonClean(jsonWith(
        R"("light": [{"position": "0 5 0", "intensity": "1 1 1"},)" "\n"
        R"({"_type": "area", "position": "0 5 0", "intensity": "1 1 1", "normal": "0 -2 0", "width": 2, "length": 0}])"));
    EXPECT_EQ(scene.lights[0].type, LightType::Point);
    EXPECT_EQ(scene.lights[1].type, LightType::Area);
    EXPECT_EQ(scene.lights[1].normal, glm::vec3(0, -1, 0));
    EXPECT_EQ(glm::vec2(scene.lights[1].width, scene.lights[1].length), glm::vec2(2, 0));
}

TEST_F(JsonForms, BackgroundPrecedenceIsSceneParametersThenUnderscoreThenPlain) {
    EXPECT_EQ(loadJsonClean(jsonWith(R"("bgColor": "0 0 1")")).background, glm::vec3(0, 0, 1));
    EXPECT_EQ(loadJsonClean(jsonWith(R"("bgColor": "0 0 1", "_bgColor": "0 0 1")")).background, glm::vec3(0, 0, 1));

    const std::string json = jsonWith(R"("bgColor": "0 0 1",)" "\n" R"("_bgColor": "0 1 0",)" "\n"
                                      R"("sceneParameters": {"bgColor": [1, 0, 0]})");
    Diagnostics diagnostics;
    EXPECT_EQ(loadJson(json, diagnostics).background, glm::vec3(1, 0, 0));
    ASSERT_EQ(diagnostics.warnings().size(), 2u);  // each disagreeing spelling, in precedence order
    expectJsonIssueAt(diagnostics.warnings()[0], json, "\"0 1 0\"", "scene._bgColor", "0 1 0");
    expectJsonIssueAt(diagnostics.warnings()[1], json, "\"0 0 1\"", "scene.bgColor", "0 0 1");
    EXPECT_EQ(diagnostics.warnings()[0].problem, "ignored, the background is scene.sceneParameters.bgColor");

    Diagnostics second;
    EXPECT_EQ(loadJson(jsonWith(R"("bgColor": "0 0 1", "_bgColor": "0 1 0")"), second).background, glm::vec3(0, 1, 0));
    EXPECT_EQ(second.warnings().size(), 1u);
}

TEST_F(JsonForms, EnvironmentMapsResolveBesideTheFileAndThePrefixWins) {
    writeCubeFaces("images/reef_");
    const std::string json = jsonWith(R"("sceneParameters": {"envMapPrefix": "images/reef_", "envMapVertCross": "images/cross.png"})");
    Diagnostics diagnostics;
    const Scene scene = loadJson(json, diagnostics);
    EXPECT_EQ(scene.envMapPrefix, (dir / "images/reef_").string());
    EXPECT_EQ(scene.envMapVertCross, (dir / "images/cross.png").string());
    EXPECT_EQ(scene.environment.faceSize, 2);
    ASSERT_EQ(diagnostics.warnings().size(), 1u);
    expectJsonIssueAt(diagnostics.warnings()[0], json, "\"images/cross.png\"", "scene.sceneParameters.envMapVertCross", "images/cross.png");
    EXPECT_EQ(diagnostics.warnings()[0].problem, "ignored, the environment map is envMapPrefix's cube faces");
    EXPECT_TRUE(loadJsonClean(jsonWith(R"("sceneParameters": {"envMapVertCross": ""})")).envMapVertCross.empty());
    const std::string missing = jsonWith(R"("sceneParameters": {"envMapVertCross": "nothing.png"})");
    expectJsonIssueAt(jsonErrorOf(missing), missing, "\"nothing.png\"", "scene.sceneParameters.envMapVertCross",
                      (dir / "nothing.png").string());
}

TEST_F(JsonForms, PrototypesAreInstancedWithOrWithoutAShaderOverride) {
    const Scene scene = loadJsonClean(jsonWith(
        R"("shader": [{"_name": "blue", "_type": "Lambertian", "diffuse": "0 0 1"}, {"_name": "red", "_type": "Lambertian", "diffuse": "1 0 0"}],)" "\n"
        R"("instance": [{"_name": "egg", "_type": "sphere", "center": "0 0 0", "radius": 1, "shader": {"_ref": "blue"}}],)" "\n"
        R"("shape": [{"_type": "instance", "_id": "egg", "_name": "plain"},)" "\n"
        R"({"_type": "instance", "_id": "egg", "_name": "red one", "shader": {"_ref": "red"}, "xform": [{"type": "translate", "amount": "0 2 0"}]}])"));
    ASSERT_EQ(scene.prototypes.size(), 1u);
    EXPECT_EQ(scene.shapes.size(), 0u);  // prototypes are not rendered by themselves
    ASSERT_EQ(scene.instances.size(), 2u);
    EXPECT_EQ(scene.instances[0].shaderOverride, -1);
    EXPECT_EQ(scene.instances[0].objectToWorld, glm::mat4(1.0f));
    EXPECT_EQ(scene.instances[1].name, "red one");
    EXPECT_EQ(scene.instances[1].shaderOverride, 1);
    EXPECT_EQ(apply(scene.instances[1].objectToWorld, glm::vec3(0)), glm::vec3(0, 2, 0));
}

TEST_F(JsonForms, APrototypesDanglingShaderIsAWarningWhileItsInstancesNameTheirOwn) {
    const std::string json = jsonWith(kGrey + ",\n" +
        R"("instance": [{"_name": "egg", "_type": "sphere", "center": "0 0 0", "radius": 1, "shader": {"_ref": "blueMat"}}],)" "\n"
        R"("shape": [{"_type": "instance", "_id": "egg", "shader": {"_ref": "grey"}}])");
    Diagnostics diagnostics;
    const Scene scene = loadJson(json, diagnostics);
    ASSERT_EQ(diagnostics.warnings().size(), 1u);
    expectJsonIssueAt(diagnostics.warnings()[0], json, "\"blueMat\"", "scene.instance[0].shader._ref", "blueMat");
    EXPECT_EQ(scene.shaders.at(scene.instances.at(0).shaderOverride).name, "grey");
    expectConsistent(scene);  // the prototype holds a grey placeholder named after the missing shader
    EXPECT_EQ(scene.shaders.at(scene.prototypes.at(0).shader).name, "blueMat");

    // An instance that would render with the placeholder is refused, as any unresolved reference.
    const std::string bare = jsonWith(kGrey + ",\n" +
        R"("instance": [{"_name": "egg", "_type": "sphere", "center": "0 0 0", "radius": 1, "shader": {"_ref": "blueMat"}}],)" "\n"
        R"("shape": [{"_type": "instance", "_id": "egg", "_name": "bare"}])");
    const Issue issue = jsonErrorOf(bare);
    expectJsonIssueAt(issue, bare, R"({"_type": "instance")", "scene.shape[0]", "blueMat");
    EXPECT_NE(issue.problem.find("unresolved"), std::string::npos);
}

TEST_F(JsonForms, MeshesMayBeShapesAndPathsAreRelativeToTheSceneFile) {
    write("models/tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const Scene scene = loadJsonClean(jsonWith(kGrey + ",\n" +
        R"("shape": [{"_type": "mesh", "file": "models/tri.obj", "shader": {"_ref": "grey"}},)" "\n"
        R"({"_type": "mesh", "file": "models/../models/tri.obj", "shader": {"_ref": "grey"}}])"));
    ASSERT_EQ(scene.shapes.size(), 2u);
    EXPECT_EQ(scene.shapes[0].type, ShapeType::Mesh);
    ASSERT_EQ(scene.meshes.size(), 1u);  // one file, loaded once
    EXPECT_EQ(scene.meshes[0].path, (dir / "models/tri.obj").string());
    EXPECT_EQ(scene.shapes[1].mesh, scene.shapes[0].mesh);
}

TEST_F(JsonForms, ColourBindingsTakeATextureInEitherSpelling) {
    write("images/tex.ppm", "P3\n1 1\n255\n255 0 0\n");
    const std::string json = jsonWith(
        R"("shader": [{"_name": "a", "_type": "BlinnPhong", "diffuse": {"tex": "t", "data": "0.5 0.5 0.5"}, "specular": {"_tex": "t", "__text": "1 1 1"}},)" "\n"
        R"({"_name": "b", "_type": "Lambertian", "diffuse": {"tex": "t"}}],)" "\n"
        R"("texture": [{"_name": "t", "_type": "image", "sourcefile": "images/tex.ppm"}])");
    const Scene scene = loadJsonClean(json);  // textures after the shaders that use them: order never matters
    ASSERT_EQ(scene.textures.size(), 1u);
    EXPECT_EQ(scene.textures[0].rgba8.at(0), 0xff0000ffu);
    EXPECT_EQ(scene.shaders[0].diffuseTexture, 0);
    EXPECT_EQ(scene.shaders[0].diffuse, glm::vec3(0.5f));
    EXPECT_EQ(scene.shaders[0].specularTexture, 0);
    EXPECT_EQ(scene.shaders[0].specular, glm::vec3(1));
    EXPECT_EQ(scene.shaders[1].diffuseTexture, 0);
    EXPECT_EQ(scene.shaders[1].diffuse, glm::vec3(1));  // no colour: white, so the texture shows as it is
}

TEST_F(JsonForms, AMissingTextureFileIsAWarningAndTheShaderKeepsItsTint) {
    const std::string json = jsonWith(
        R"("shader": [{"_name": "a", "_type": "Lambertian", "diffuse": {"tex": "t", "data": "0.5 0.5 0.5"}}],)" "\n"
        R"("texture": [{"_name": "t", "sourcefile": "images/none.png"}])");
    Diagnostics diagnostics;
    const Scene scene = loadJson(json, diagnostics);
    EXPECT_EQ(scene.shaders[0].diffuseTexture, kNoTexture);
    ASSERT_EQ(diagnostics.warnings().size(), 1u);
    expectJsonIssueAt(diagnostics.warnings()[0], json, "\"images/none.png\"", "scene.texture[0].sourcefile",
                      (dir / "images/none.png").string());
}

TEST_F(JsonForms, XformComposesInListedOrderSoTheLastListedActsFirst) {
    const auto placed = [&](const std::string& xform) {
        const Scene scene = loadJsonClean(jsonWith(kGrey + ",\n" +
            R"("shape": [{"_type": "sphere", "center": "0 0 0", "radius": 1, "shader": {"_ref": "grey"}, "xform": )" + xform + "}]"));
        EXPECT_EQ(scene.prototypes.size(), 1u);  // a transformed plain shape is a prototype of its own, placed once
        return scene.instances.at(0).objectToWorld;
    };
    // M = T * S: scale first, then translate.
    const glm::mat4 ts = placed(R"([{"type": "translate", "amount": "1 0 0"}, {"type": "scale", "amount": [2, 2, 2]}])");
    EXPECT_EQ(apply(ts, {1, 0, 0}), glm::vec3(3, 0, 0));
    // M = S * T: translate first, then scale.
    const glm::mat4 st = placed(R"([{"type": "scale", "amount": "2 2 2"}, {"type": "translate", "amount": "1 0 0"}])");
    EXPECT_EQ(apply(st, {1, 0, 0}), glm::vec3(4, 0, 0));
    // Degrees, right-handed, any case of the axis letter (as XML; J26 insists on upper case).
    expectNear(apply(placed(R"([{"type": "rotation", "axis": "Y", "amount": 90}])"), {1, 0, 0}), {0, 0, -1});
    expectNear(apply(placed(R"([{"type": "rotation", "axis": "x", "amount": 90}])"), {0, 1, 0}), {0, 0, 1});
    expectNear(apply(placed(R"([{"type": "rotation", "axis": "Z", "amount": -90.0}])"), {1, 0, 0}), {0, -1, 0});
    // translate * rotation: rotate about the origin, then move.
    expectNear(apply(placed(R"([{"type": "translate", "amount": "0 0 5"}, {"type": "rotation", "axis": "Y", "amount": 90}])"), {1, 0, 0}),
               {0, 0, 4});
}

TEST_F(JsonForms, RotateIsReadAsRotationAndUnknownStepsAreIgnoredWithWarnings) {
    const std::string json = jsonWith(kGrey + ",\n" + R"("shape": [{"_type": "sphere", "center": "0 0 0", "radius": 1, "shader": {"_ref": "grey"}, "xform": [)" "\n"
        R"({"type": "rotate", "axis": "Y", "amount": 90},)" "\n" R"({"type": "transform", "amount": "5 5 5"}]}])");
    Diagnostics diagnostics;
    const Scene scene = loadJson(json, diagnostics);
    expectNear(apply(scene.instances.at(0).objectToWorld, {1, 0, 0}), {0, 0, -1});
    ASSERT_EQ(diagnostics.warnings().size(), 2u);
    expectJsonIssueAt(diagnostics.warnings()[0], json, "\"rotate\"", "scene.shape[0].xform[0].type", "rotate");
    expectJsonIssueAt(diagnostics.warnings()[1], json, "\"transform\"", "scene.shape[0].xform[1].type", "transform");
    EXPECT_EQ(diagnostics.warnings()[1].problem, "unknown transform type, ignored");
}

TEST_F(JsonForms, TheTransformObjectIsTranslateRotateScaleWithAWarning) {
    // Keys written scale first: the order of the keys is not what counts, the documented one is.
    const std::string json = jsonWith(kGrey + ",\n" +
        R"("instance": [{"_name": "egg", "_type": "sphere", "center": "0 0 0", "radius": 1, "shader": {"_ref": "grey"}}],)" "\n"
        R"("shape": [{"_type": "instance", "_id": "egg", "transform": {"scale": "1 0.5 1.5", "_name": "x",)" "\n"
        R"("rotate": [{"_axis": "X", "_angle": 90}, {"_axis": "Y", "_angle": 0}], "translate": "2.5 1.5 -4"}},)" "\n"
        R"({"_type": "instance", "_id": "egg", "transform": {"translate": "0 1 0"}}])");
    Diagnostics diagnostics;
    const Scene scene = loadJson(json, diagnostics);
    // threeEggs.xml's right egg: translate, rotate X 90, scale; the z poles land on y = 0 and 3.
    const glm::mat4& m = scene.instances.at(0).objectToWorld;
    expectNear(apply(m, {0, 0, 1}), {2.5f, 0, -4});
    expectNear(apply(m, {0, 0, -1}), {2.5f, 3, -4});
    EXPECT_EQ(apply(scene.instances.at(1).objectToWorld, glm::vec3(0)), glm::vec3(0, 1, 0));
    ASSERT_EQ(diagnostics.warnings().size(), 1u);  // one kind only: nothing was lost
    expectJsonIssueAt(diagnostics.warnings()[0], json, R"({"scale")", "scene.shape[0].transform", "");
    EXPECT_NE(diagnostics.warnings()[0].problem.find("translate * rotate * scale"), std::string::npos);
}

TEST_F(JsonForms, UnknownKeysAreWarnedWithTheirPathNeverDropped) {
    const std::string json = jsonWith(kGrey + ",\n" +
        R"("shape": [{"_type": "sphere", "center": "0 0 0", "radius": 1, "shader": {"_ref": "grey"}, "attribute": "wireframe"}],)" "\n"
        R"("sceneParameters": {"exposure": 2},)" "\n" R"("options": {})");
    Diagnostics diagnostics;
    loadJson(json, diagnostics);
    ASSERT_EQ(diagnostics.warnings().size(), 3u);
    expectJsonIssueAt(diagnostics.warnings()[0], json, "\"options\"", "scene.options", "");
    expectJsonIssueAt(diagnostics.warnings()[1], json, "\"attribute\"", "scene.shape[0].attribute", "");
    expectJsonIssueAt(diagnostics.warnings()[2], json, "\"exposure\"", "scene.sceneParameters.exposure", "");
    EXPECT_EQ(diagnostics.warnings()[0].problem, "unknown key, ignored");
}

TEST_F(JsonForms, ARepeatedKeyKeepsItsFirstValueWithAWarning) {
    const std::string json = jsonWith(R"("bgColor": "1 0 0", "bgColor": {"nested": [1, 2]})");
    Diagnostics diagnostics;
    EXPECT_EQ(loadJson(json, diagnostics).background, glm::vec3(1, 0, 0));
    ASSERT_EQ(diagnostics.warnings().size(), 1u);
    const std::size_t second = json.find("\"bgColor\"", json.find("\"bgColor\"") + 1);
    expectJsonIssue(diagnostics.warnings()[0], 4, static_cast<int>(second - json.rfind('\n', second)), "scene.bgColor", "");
}

TEST_F(JsonForms, ShaderTypesUnusedParametersAndUnknownTypes) {
    const std::string json = jsonWith(
        R"("shader": [{"_name": "m", "_type": "Mirror", "roughness": 1.4, "mirrorCoef": 0.5},)" "\n"
        R"({"_name": "g", "_type": "Glaze", "diffuse": "0 0 1", "mirrorCoef": 0.25},)" "\n"
        R"({"_name": "d", "_type": "Dielectric", "refractiveIndex": 1.5, "attenuationCoef": [0.9, 0.9, 1]},)" "\n"
        R"({"_name": "c", "_type": "CoolToWarm", "diffuse": "1 1 1"},)" "\n"
        R"({"_name": "bpm", "_type": "BlinnPhongMirrored", "diffuse": "1 1 1", "specular": "1 1 1", "phongExp": 32, "mirrorCoef": 0.5, "roughness": 0.1},)" "\n"
        R"({"_name": "old", "_type": "Phong", "diffuse": "1 1 1", "mirrorCoef": 1},)" "\n"
        R"({"_name": "x", "_type": "Velvet", "diffuse": "0 1 0", "fuzz": 1}])");
    Diagnostics diagnostics;
    const Scene scene = loadJson(json, diagnostics);
    EXPECT_EQ(scene.shaders[0].type, ShaderType::Mirror);
    EXPECT_FLOAT_EQ(scene.shaders[0].roughness, 1.4f);
    EXPECT_EQ(scene.shaders[1].mirrorCoef, 0.25f);
    EXPECT_EQ(scene.shaders[2].refractiveIndex, 1.5f);
    EXPECT_EQ(scene.shaders[2].attenuation, glm::vec3(0.9f, 0.9f, 1));
    EXPECT_EQ(scene.shaders[3].type, ShaderType::CoolToWarm);
    EXPECT_EQ(scene.shaders[4].type, ShaderType::BlinnPhongMirrored);
    EXPECT_EQ(scene.shaders[5].type, ShaderType::BlinnPhongMirrored);  // legacy Phong + mirrorCoef, as XML
    EXPECT_EQ(scene.shaders[6].type, ShaderType::Lambertian);
    EXPECT_EQ(scene.shaders[6].diffuse, glm::vec3(0, 1, 0));
    ASSERT_EQ(diagnostics.warnings().size(), 3u);
    expectJsonIssueAt(diagnostics.warnings()[0], json, "\"mirrorCoef\": 0.5", "scene.shader[0].mirrorCoef", "");
    EXPECT_EQ(diagnostics.warnings()[0].problem, "not used by a Mirror shader, ignored");
    expectJsonIssueAt(diagnostics.warnings()[1], json, "\"fuzz\"", "scene.shader[6].fuzz", "");
    expectJsonIssueAt(diagnostics.warnings()[2], json, "\"Velvet\"", "scene.shader[6]._type", "Velvet");
}

// Diffuse renders as itself (path traced, docs/RENDERING.md §5), an Emitter shader as an emitter:
// no warning. Loaded in the file's form, the Emitter is a black Lambertian with its emission.
TEST_F(JsonForms, DiffuseAndEmitterShadersKeepTheirMeaningWithoutAWarning) {
    const std::string json = jsonWith(
        R"("shader": [{"_name": "d1", "_type": "Diffuse", "diffuse": "1 1 1"}, {"_name": "d2", "_type": "Diffuse", "diffuse": "1 0 0"},)" "\n"
        R"({"_name": "lamp", "_type": "Emitter", "emission": "3 3 3"}, {"_name": "lamp2", "_type": "Emitter", "emission": "1 1 1"}])");
    Diagnostics diagnostics;
    const Scene scene = loadJson(json, diagnostics);
    EXPECT_TRUE(scene.shaders[0].diffuseBounce && scene.shaders[1].diffuseBounce);
    EXPECT_EQ(scene.shaders[0].type, ShaderType::Lambertian);
    EXPECT_EQ(scene.shaders[2].emission, glm::vec3(3));
    EXPECT_EQ(scene.shaders[2].diffuse, glm::vec3(0));
    EXPECT_TRUE(diagnostics.warnings().empty());
}

// In the renders' form (LoadOptions::shaderEmitters), shapes and still instances with an Emitter
// shader become shape emitters of radiance `emission`, after the file's lights; a moving one stays
// a shape, with a warning; shapes of other shaders stay where they were.
TEST_F(JsonForms, EmitterShadersMakeTheirShapesEmittersInTheRendersForm) {
    const std::string flat = jsonWith(
        R"("shader": [{"_name": "grey", "_type": "Diffuse", "diffuse": "0.5 0.5 0.5"}, {"_name": "lamp", "_type": "Emitter", "emission": "3 2 1"}],)" "\n"
        R"("light": [{"_type": "point", "position": "0 9 0", "intensity": "1 1 1"}],)" "\n"
        R"("instance": [{"_name": "panel", "_type": "box", "minPt": "0 0 0", "maxPt": "1 1 1", "shader": {"_ref": "grey"}}],)" "\n"
        R"("shape": [{"_type": "sphere", "_name": "bulb", "center": "0 2 0", "radius": 0.5, "shader": {"_ref": "lamp"}},)" "\n"
        R"({"_type": "sphere", "_name": "ball", "center": "0 0 0", "radius": 1, "shader": {"_ref": "grey"}},)" "\n"
        R"({"_type": "instance", "_name": "p1", "_id": "panel", "shader": {"_ref": "lamp"}, "xform": [{"type": "translate", "amount": "5 0 0"}]},)" "\n"
        R"({"_type": "instance", "_name": "p2", "_id": "panel"}])");
    std::ofstream(jsonPath) << flat;
    LoadOptions options;
    options.shaderEmitters = true;
    Diagnostics diagnostics;
    const Scene scene = loadScene(jsonPath, options, diagnostics);
    EXPECT_TRUE(diagnostics.warnings().empty());
    ASSERT_EQ(scene.shapes.size(), 1u);
    EXPECT_EQ(scene.shapes[0].name, "ball");
    ASSERT_EQ(scene.instances.size(), 1u);
    EXPECT_EQ(scene.instances[0].name, "p2");
    ASSERT_EQ(scene.emitters.size(), 2u);
    EXPECT_EQ(scene.emitters[0].name, "bulb");
    EXPECT_EQ(scene.emitters[0].radiance, glm::vec3(3, 2, 1));
    EXPECT_EQ(scene.emitters[0].shape.center, glm::vec3(0, 2, 0));
    EXPECT_EQ(scene.emitters[0].prototype, -1);
    EXPECT_EQ(scene.emitters[1].name, "p1");
    EXPECT_EQ(scene.emitters[1].prototype, 0);
    EXPECT_EQ(glm::vec3(scene.emitters[1].objectToWorld[3]), glm::vec3(5, 0, 0));
    EXPECT_EQ(scene.emitters[1].lightsBefore, 1);  // after the point light
    ASSERT_EQ(scene.lights.size(), 1u);
}

// A shape light is an emitter (rendered as geometry, docs/RENDERING.md §4), not a light; its place
// among the lights is kept for the writers (Emitter::lightsBefore).
TEST_F(JsonForms, ShapeLightsBecomeEmittersThatKeepTheirPlaceAmongTheLights) {
    const std::string json = jsonWith(kGrey + ",\n" +
        R"("instance": [{"_name": "box", "_type": "box", "minPt": "0 0 0", "maxPt": "2 2 2", "shader": {"_ref": "nowhere"}}],)" "\n"
        R"("light": [{"_type": "shape", "intensity": "1 0.5 0", "shape": {"_type": "sphere", "center": "1 2 3", "radius": 0.5}},)" "\n"
        R"({"_type": "point", "position": "0 9 0", "intensity": "1 1 1"},)" "\n"
        R"({"_type": "shape", "intensity": [0, 0, 2], "shape": {"_type": "instance", "_id": "box", "xform": [{"type": "translate", "amount": "10 0 0"}]}}])");
    Diagnostics diagnostics;
    const Scene scene = loadJson(json, diagnostics);
    ASSERT_EQ(scene.emitters.size(), 2u);
    EXPECT_EQ(scene.emitters[0].shape.center, glm::vec3(1, 2, 3));
    EXPECT_EQ(scene.emitters[0].shape.shader, -1);  // optional: the radiance replaces it
    EXPECT_EQ(scene.emitters[1].prototype, 0);
    EXPECT_EQ(scene.emitters[0].radiance, glm::vec3(1, 0.5f, 0));
    EXPECT_EQ(glm::vec3(scene.emitters[1].objectToWorld[3]), glm::vec3(10, 0, 0));
    ASSERT_EQ(scene.lights.size(), 1u);  // the point light only
    EXPECT_EQ(scene.lights[0].position, glm::vec3(0, 9, 0));
    EXPECT_EQ(scene.emitters[0].lightsBefore, 0);  // listed before the point light
    EXPECT_EQ(scene.emitters[1].lightsBefore, 1);  // after it
    EXPECT_TRUE(scene.shapes.empty() && scene.instances.empty());  // an emitter is neither
    ASSERT_EQ(diagnostics.warnings().size(), 1u);  // the prototype's dangling shader only
}

// vkrt's addition (docs/JSON_FORMAT.md §3.1), what XML's <sceneParameters><camera> says: the
// camera to render by name; a name no camera has is an error at that value.
TEST_F(JsonForms, SceneParametersMayNameTheCameraToRender) {
    const std::string two = R"("camera": [{"_name": "a", "position": "0 0 0", "viewDir": "0 0 -1"},)"
                            R"({"_name": "b", "position": "1 0 0", "viewDir": "0 0 -1"}])";
    const Scene scene = loadJsonClean("{\"scene\": {" + two + R"(, "sceneParameters": {"camera": "b"}}})");
    EXPECT_EQ(scene.defaultCamera, 1);
    const std::string json = "{\"scene\": {" + two + R"(, "sceneParameters": {"camera": "c"}}})";
    const Issue issue = jsonErrorOf(json);
    expectJsonIssueAt(issue, json, R"("c")", "scene.sceneParameters.camera", "c");
    EXPECT_NE(issue.problem.find("no camera of that name"), std::string::npos) << issue.message();
    // "" names a nameless camera, as an empty XML <camera/> does.
    const std::string unnamed = R"("camera": [{"_name": "a", "position": "0 0 0", "viewDir": "0 0 -1"},)"
                                R"({"position": "1 0 0", "viewDir": "0 0 -1"}])";
    EXPECT_EQ(loadJsonClean("{\"scene\": {" + unnamed + R"(, "sceneParameters": {"camera": ""}}})").defaultCamera, 1);
}

TEST_F(JsonForms, StrictTurnsTheFirstWarningIntoTheError) {
    const std::string json = jsonWith(R"("fog": 1,)" "\n" R"("haze": 2)");
    const Issue issue = jsonErrorOf(json, /*strict=*/true);
    expectJsonIssueAt(issue, json, "\"fog\"", "scene.fog", "");
}

}  // namespace
}  // namespace vkrt::test
