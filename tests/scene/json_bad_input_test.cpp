// Malformed JSON input: every error class of bad_input_test.cpp (the XML ones) gets one
// SceneError naming file:line:column, the JSON path and the value, at a position the test
// computes from the text it wrote.
#include "scene_test_files.h"

namespace vkrt::test {
namespace {

using JsonBadInput = SceneFiles;

const std::string kShader = R"("shader": [{"_name": "s", "_type": "Lambertian", "diffuse": "1 1 1"}])";

// A scene with the grey shader and one shape object `shape` (on line 5).
std::string withShape(const std::string& shape) { return jsonWith(kShader + ",\n\"shape\": [" + shape + "]"); }

std::string sphere(const std::string& radius) {
    return R"({"_type": "sphere", "_name": "ball", "center": "0 0 -3", "radius": )" + radius + R"(, "shader": {"_ref": "s"}})";
}

TEST_F(JsonBadInput, MissingSceneFileOrADirectory) {
    Diagnostics diagnostics;
    const std::string path = (dir / "absent.json").string();
    try {
        loadScene(path, {}, diagnostics);
        FAIL();
    } catch (const SceneError& error) {
        EXPECT_EQ(error.issue().file, path);
        EXPECT_EQ(error.issue().element, "json");
        EXPECT_NE(std::string(error.what()).find("not found"), std::string::npos) << error.what();
    }
    std::filesystem::create_directories(dir / "folder.json");
    EXPECT_THROW(loadScene((dir / "folder.json").string(), {}, diagnostics), SceneError);
}

TEST_F(JsonBadInput, MalformedJsonIsReportedAtTheLibrarysLineAndColumn) {
    // nlohmann names the last byte it read: the '@' here.
    const std::string json = "{\n\"scene\": {\n\"camera\": [\n{\"position\": @}]}}\n";
    const Issue issue = jsonErrorOf(json);
    expectJsonIssueAt(issue, json, "@", "json", "@}]}}");  // as XML: the text from where the parser stopped
    EXPECT_EQ(issue.problem, "malformed JSON (syntax error while parsing value - invalid literal; last read: '\"position\": @') at");
    // A missing comma: the parser stops at the next key's closing quote.
    const std::string comma = "{\"scene\": {\n  \"camera\": [] \"light\": []}}";
    const Issue missing = jsonErrorOf(comma);
    EXPECT_EQ(missing.line, 2);
    EXPECT_EQ(missing.column, columnOf(comma, "t\": []}") + 1);
    EXPECT_NE(missing.problem.find("expected '}'"), std::string::npos) << missing.message();
}

TEST_F(JsonBadInput, EmptyTruncatedOrTrailingGarbage) {
    const Issue empty = jsonErrorOf("");
    expectJsonIssue(empty, 1, 1, "json", "end of file");
    EXPECT_NE(empty.problem.find("unexpected end of input"), std::string::npos) << empty.message();
    const std::string full = withShape(sphere("1"));
    const Issue truncated = jsonErrorOf(full.substr(0, full.size() / 2));
    EXPECT_EQ(truncated.element, "json");
    EXPECT_GE(truncated.line, 1);
    EXPECT_EQ(jsonErrorOf(full + "x").element, "json");
}

TEST_F(JsonBadInput, TheRootAndTheSceneMustBeObjects) {
    const std::string array = "\n  [1, 2]";
    expectJsonIssue(jsonErrorOf(array), 2, 3, "json", "[1, 2]");
    const std::string scene = R"({"scene": "none"})";
    const Issue issue = jsonErrorOf(scene);
    expectJsonIssueAt(issue, scene, "\"none\"", "scene", "none");
    EXPECT_EQ(issue.problem, "expected an object, found a string");
}

TEST_F(JsonBadInput, SceneWithoutCamera) {
    const std::string json = "{\"scene\": {\"light\": [{\"position\": \"0 1 0\", \"intensity\": \"1 1 1\"}]}}";
    const Issue issue = jsonErrorOf(json);
    expectJsonIssue(issue, 1, 11, "scene", "");
    EXPECT_EQ(issue.problem, "the scene has no camera");
}

TEST_F(JsonBadInput, CameraWithoutPositionOrDirection) {
    const std::string noPosition = "{\"scene\": {\n\"camera\": [{\"viewDir\": \"0 0 -1\"}]}}";
    const Issue a = jsonErrorOf(noPosition);
    expectJsonIssue(a, 2, 12, "scene.camera[0]", "");
    EXPECT_EQ(a.problem, "missing required key position");
    const Issue b = jsonErrorOf("{\"scene\": {\n\"camera\": [{\"position\": \"0 0 0\"}]}}");
    expectJsonIssue(b, 2, 12, "scene.camera[0]", "");
    EXPECT_EQ(b.problem, "missing required key viewDir (or lookatPoint)");
}

TEST_F(JsonBadInput, ZeroViewDirAndLookatAtTheEye) {
    const std::string zero = "{\"scene\": {\n\"camera\": [{\"position\": \"0 0 0\",\n \"viewDir\": [0, 0.0, -0]}]}}";
    expectJsonIssueAt(jsonErrorOf(zero), zero, "[0, 0.0", "scene.camera[0].viewDir", "[0, 0.0, -0]");
    const std::string eye = "{\"scene\": {\n\"camera\": [{\"position\": \"1 2 3\",\n \"lookatPoint\": \"1 2 3\"}]}}";
    expectJsonIssueAt(jsonErrorOf(eye), eye, "\"1 2 3\"}", "scene.camera[0].lookatPoint", "1 2 3");
}

TEST_F(JsonBadInput, NonPositiveFocalLengthOrImagePlaneWidth) {
    const std::string f = "{\"scene\": {\"camera\": [{\"position\": \"0 0 0\", \"viewDir\": \"0 0 -1\",\n\"focalLength\": 0}]}}";
    expectJsonIssueAt(jsonErrorOf(f), f, "0}", "scene.camera[0].focalLength", "0");
    const std::string w = "{\"scene\": {\"camera\": [{\"position\": \"0 0 0\", \"viewDir\": \"0 0 -1\",\n\"imagePlaneWidth\": -0.50}]}}";
    const Issue issue = jsonErrorOf(w);
    expectJsonIssueAt(issue, w, "-0.50", "scene.camera[0].imagePlaneWidth", "-0.50");  // quoted as written
    EXPECT_EQ(issue.problem, "image plane width must be positive");
}

TEST_F(JsonBadInput, WrongTypesNameWhatWasFound) {
    const std::string text = withShape(sphere("\"big\""));
    expectJsonIssueAt(jsonErrorOf(text), text, "\"big\"", "scene.shape[0].radius", "big");
    EXPECT_EQ(jsonErrorOf(text).problem, "not a number");
    const std::string boolean = withShape(sphere("true"));
    const Issue b = jsonErrorOf(boolean);
    expectJsonIssueAt(b, boolean, "true", "scene.shape[0].radius", "true");
    EXPECT_EQ(b.problem, "expected a number, found a boolean");
    const std::string object = withShape(R"({"_type": "sphere", "center": {"x": 0}, "radius": 1, "shader": {"_ref": "s"}})");
    const Issue o = jsonErrorOf(object);
    expectJsonIssueAt(o, object, "{\"x\"", "scene.shape[0].center", "{\"x\": 0}");
    EXPECT_EQ(o.problem, "expected 3 numbers (a string or an array), found an object");
    const std::string list = jsonWith(R"("shape": "all of them")");
    EXPECT_EQ(jsonErrorOf(list).problem, "expected an array of objects, found a string");
    const std::string element = jsonWith(R"("shape": [{"_type": "box", "minPt": "0 0 0", "maxPt": "1 1 1", "shader": {"_ref": "s"}}, 7])");
    expectJsonIssueAt(jsonErrorOf(element), element, "7]", "scene.shape[1]", "7");
    const std::string name = jsonWith(R"("shader": [{"_name": 5, "_type": "Lambertian"}])");
    EXPECT_EQ(jsonErrorOf(name).problem, "expected a string, found a number");
}

TEST_F(JsonBadInput, MissingVectorComponentsInAStringOrAnArray) {
    const std::string text = withShape(R"({"_type": "sphere", "center": "0 1", "radius": 1, "shader": {"_ref": "s"}})");
    const Issue a = jsonErrorOf(text);
    expectJsonIssueAt(a, text, "\"0 1\"", "scene.shape[0].center", "0 1");
    EXPECT_EQ(a.problem, "expected 3 numbers, found 2");  // the course's parser left z uninitialised
    const std::string array = withShape(R"({"_type": "sphere", "center": [0, 1, 2, 3], "radius": 1, "shader": {"_ref": "s"}})");
    const Issue b = jsonErrorOf(array);
    expectJsonIssueAt(b, array, "[0, 1, 2, 3]", "scene.shape[0].center", "[0, 1, 2, 3]");
    EXPECT_EQ(b.problem, "expected 3 numbers, found 4");
}

TEST_F(JsonBadInput, NonFiniteOrBeyondFloatNumbers) {
    const std::string big = withShape(sphere("1e39"));
    const Issue a = jsonErrorOf(big);
    expectJsonIssueAt(a, big, "1e39", "scene.shape[0].radius", "1e39");
    EXPECT_EQ(a.problem, "not a finite 32-bit number");
    const std::string inString = withShape(R"({"_type": "sphere", "center": "0 -1e39 0", "radius": 1, "shader": {"_ref": "s"}})");
    expectJsonIssueAt(jsonErrorOf(inString), inString, "\"0 -1e39", "scene.shape[0].center", "-1e39");
    const std::string inArray = withShape(R"({"_type": "sphere", "center": [0, 0, 3.5e38], "radius": 1, "shader": {"_ref": "s"}})");
    expectJsonIssueAt(jsonErrorOf(inArray), inArray, "3.5e38", "scene.shape[0].center[2]", "3.5e38");
    const std::string nan = withShape(R"({"_type": "sphere", "center": "nan 0 0", "radius": 1, "shader": {"_ref": "s"}})");
    EXPECT_EQ(jsonErrorOf(nan).problem, "not a finite 32-bit number");
    // Beyond double range nlohmann refuses the number while parsing; the path is still named.
    const std::string huge = withShape(sphere("1e400"));
    const Issue h = jsonErrorOf(huge);
    expectJsonIssueAt(h, huge, "1e400", "scene.shape[0].radius", "1e400");
    EXPECT_EQ(h.problem, "not a finite 32-bit number");
}

TEST_F(JsonBadInput, SphereWithoutRadiusAndNonPositiveRadii) {
    const std::string json = withShape(R"({"_type": "sphere", "_name": "ball", "center": "0 0 0", "shader": {"_ref": "s"}})");
    const Issue issue = jsonErrorOf(json);
    expectJsonIssueAt(issue, json, R"({"_type": "sphere")", "scene.shape[0]", "");
    EXPECT_EQ(issue.problem, "missing required key radius");
    for (const char* radius : {"-1", "0", "-0.0"}) {
        SCOPED_TRACE(radius);
        const std::string text = withShape(sphere(radius));
        // At the number, not at its key.
        expectJsonIssue(jsonErrorOf(text), 5, columnOf(text, "\"radius\": ") + 10, "scene.shape[0].radius", radius);
    }
}

// An inverted box is a warning (LittleOfEverything.json has one): the corners are swapped on the
// inverted axis only; --strict refuses it at the same place.
TEST_F(JsonBadInput, InvertedBoxIsSwappedWithAWarningAndRefusedUnderStrict) {
    const std::string json = withShape(R"({"_type": "box", "minPt": "0 2 0", "maxPt": [1, 1, 1], "shader": {"_ref": "s"}})");
    const Issue issue = jsonErrorOf(json, /*strict=*/true);
    expectJsonIssueAt(issue, json, "\"0 2 0\"", "scene.shape[0].minPt", "0 2 0 > [1, 1, 1]");
    EXPECT_EQ(issue.problem, "greater than maxPt on the y axis, read with the corners swapped there");
    Diagnostics diagnostics;
    const Scene scene = loadJson(json, diagnostics);
    ASSERT_EQ(diagnostics.warnings().size(), 1u);
    EXPECT_EQ(diagnostics.warnings()[0].problem, issue.problem);
    ASSERT_EQ(scene.shapes.size(), 1u);
    EXPECT_EQ(scene.shapes[0].minPt, glm::vec3(0, 1, 0));
    EXPECT_EQ(scene.shapes[0].maxPt, glm::vec3(1, 2, 1));
    // Two axes are both named.
    Diagnostics two;
    const Scene both = loadJson(withShape(R"({"_type": "box", "minPt": "2 0 3", "maxPt": "1 1 1", "shader": {"_ref": "s"}})"), two);
    ASSERT_EQ(two.warnings().size(), 1u);
    EXPECT_EQ(two.warnings()[0].problem, "greater than maxPt on the x and z axis, read with the corners swapped there");
    EXPECT_EQ(both.shapes[0].minPt, glm::vec3(1, 0, 1));
    EXPECT_EQ(both.shapes[0].maxPt, glm::vec3(2, 1, 3));
}

TEST_F(JsonBadInput, AreaLightZeroNormalNegativeSizesAndMissingWidth) {
    const auto area = [](const std::string& normal, const std::string& width, const std::string& length) {
        return jsonWith(R"("light": [{"_type": "area", "position": "0 5 0", "intensity": "1 1 1",)" "\n\"normal\": " + normal +
                        ",\n\"width\": " + width + ",\n\"length\": " + length + "}]");
    };
    expectJsonIssue(jsonErrorOf(area("\"0 0 0\"", "1", "1")), 5, 11, "scene.light[0].normal", "0 0 0");
    expectJsonIssue(jsonErrorOf(area("\"0 -1 0\"", "-2", "1")), 6, 10, "scene.light[0].width", "-2");
    expectJsonIssue(jsonErrorOf(area("\"0 -1 0\"", "2", "-1")), 7, 11, "scene.light[0].length", "-1");
    expectJsonIssue(jsonErrorOf(area("\"0 -1 0\"", "-0.001", "1")), 6, 10, "scene.light[0].width", "-0.001");
    const std::string missing = jsonWith(R"("light": [{"_type": "area", "position": "0 5 0", "intensity": "1 1 1", "normal": "0 -1 0"}])");
    const Issue issue = jsonErrorOf(missing);
    expectJsonIssue(issue, 4, 11, "scene.light[0]", "");
    EXPECT_EQ(issue.problem, "missing required key width");
}

TEST_F(JsonBadInput, LightWithoutIntensityOrShape) {
    EXPECT_EQ(jsonErrorOf(jsonWith(R"("light": [{"_type": "point", "position": "0 5 0"}])")).problem, "missing required key intensity");
    EXPECT_EQ(jsonErrorOf(jsonWith(R"("light": [{"_type": "shape", "intensity": "1 1 1"}])")).problem, "missing required key shape");
}

TEST_F(JsonBadInput, ShapeOrPrototypeWithoutShaderOrType) {
    const std::string json = withShape(R"({"_type": "sphere", "_name": "lonely", "center": "0 0 0", "radius": 1})");
    const Issue issue = jsonErrorOf(json);
    expectJsonIssueAt(issue, json, R"({"_type": "sphere")", "scene.shape[0]", "lonely");
    EXPECT_EQ(issue.problem, "missing required key shader");
    const std::string proto = jsonWith(kShader + ",\n" + R"("instance": [{"_name": "p", "_type": "sphere", "center": "0 0 0", "radius": 1}])");
    EXPECT_EQ(jsonErrorOf(proto).element, "scene.instance[0]");
    const std::string untyped = withShape(R"({"_name": "x", "shader": {"_ref": "s"}})");
    const Issue t = jsonErrorOf(untyped);
    expectJsonIssue(t, 5, 11, "scene.shape[0]", "");
    EXPECT_EQ(t.problem, "missing required key _type (or type)");
}

// A reference to a shader the file never defines (sd20190404_oneOBJ_Al.json's whiteMat) is a
// warning at the reference: the shape shows one grey Lambertian placeholder per missing name.
// --strict refuses it there.
TEST_F(JsonBadInput, UnresolvedShaderReferenceIsAGreyPlaceholderWithAWarning) {
    const std::string json = withShape(R"({"_type": "sphere", "center": "0 0 0", "radius": 1, "shader": {"_ref": "Grey Mat"}},)" "\n"
                                       R"({"_type": "sphere", "center": "0 3 0", "radius": 1, "shader": {"_ref": "Grey Mat"}})");
    const Issue issue = jsonErrorOf(json, /*strict=*/true);
    expectJsonIssueAt(issue, json, "\"Grey Mat\"", "scene.shape[0].shader._ref", "Grey Mat");
    EXPECT_EQ(issue.problem, "unresolved shader reference, shown as a grey Lambertian placeholder");
    Diagnostics diagnostics;
    const Scene scene = loadJson(json, diagnostics);
    EXPECT_EQ(diagnostics.warnings().size(), 2u);  // one per reference
    ASSERT_EQ(scene.shaders.size(), 2u);           // s and one placeholder for both shapes
    EXPECT_EQ(scene.shapes[0].shader, 1);
    EXPECT_EQ(scene.shapes[1].shader, 1);
    const Shader& placeholder = scene.shaders[1];
    EXPECT_EQ(placeholder.name, "Grey Mat");
    EXPECT_EQ(placeholder.type, ShaderType::Lambertian);
    EXPECT_EQ(placeholder.diffuse, glm::vec3(0.5f));
    // The same on an instance's override and on a shape light's shape.
    const std::string instance = jsonWith(kShader + ",\n" +
        R"("instance": [{"_name": "p", "_type": "sphere", "center": "0 0 0", "radius": 1, "shader": {"_ref": "s"}}],)" "\n"
        R"("shape": [{"_type": "instance", "_id": "p", "shader": {"_ref": "nope"}}])");
    expectJsonIssueAt(jsonErrorOf(instance, true), instance, "\"nope\"", "scene.shape[0].shader._ref", "nope");
    Diagnostics overridden;
    const Scene placed = loadJson(instance, overridden);
    ASSERT_EQ(placed.instances.size(), 1u);
    EXPECT_EQ(placed.shaders[placed.instances[0].shaderOverride].name, "nope");
    const std::string emitter = jsonWith(kShader + ",\n" +
        R"("light": [{"_type": "shape", "intensity": "1 1 1", "shape": {"_type": "sphere", "center": "0 0 0", "radius": 1, "shader": {"_ref": "nope"}}}])");
    EXPECT_EQ(jsonErrorOf(emitter, true).element, "scene.light[0].shape.shader._ref");
}

TEST_F(JsonBadInput, UnresolvedOrMissingInstanceId) {
    const std::string json = withShape(R"({"_type": "instance", "_name": "egg", "_id": "eggBase"})");
    const Issue issue = jsonErrorOf(json);
    expectJsonIssueAt(issue, json, "\"eggBase\"", "scene.shape[0]._id", "eggBase");
    EXPECT_EQ(issue.problem, "unresolved instance id");
    EXPECT_EQ(jsonErrorOf(withShape(R"({"_type": "instance", "_name": "egg"})")).problem, "missing required key _id (or id)");
}

TEST_F(JsonBadInput, UnresolvedTextureReference) {
    const std::string json = jsonWith(R"("shader": [{"_name": "t", "_type": "Lambertian", "diffuse": {"tex": "earth", "data": "1 1 1"}}])");
    const Issue issue = jsonErrorOf(json);
    expectJsonIssueAt(issue, json, "\"earth\"", "scene.shader[0].diffuse.tex", "earth");
    EXPECT_EQ(issue.problem, "unresolved texture reference");
}

TEST_F(JsonBadInput, MissingOrBrokenMeshFiles) {
    std::filesystem::create_directories(dir / "adir.obj");
    write("empty.obj", "# nothing here\nv 0 0 0\n");
    write("badindex.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
    for (const char* file : {"objFiles/dragon.obj", "adir.obj", "empty.obj", "badindex.obj"}) {
        SCOPED_TRACE(file);
        const std::string json = withShape(R"({"_type": "mesh", "shader": {"_ref": "s"}, "file": ")" + std::string(file) + "\"}");
        expectJsonIssueAt(jsonErrorOf(json), json, "\"" + std::string(file), "scene.shape[0].file", (dir / file).string());
    }
    const std::string proto = jsonWith(kShader + ",\n" + R"("instance": [{"_name": "d", "_type": "mesh", "file": "objFiles/dragon.obj", "shader": {"_ref": "s"}}])");
    const Issue issue = jsonErrorOf(proto);
    EXPECT_EQ(issue.element, "scene.instance[0].file");
    EXPECT_NE(issue.problem.find("not found"), std::string::npos);
}

TEST_F(JsonBadInput, ShaderParametersOutOfRange) {
    const auto shader = [](const std::string& body) { return jsonWith(R"("shader": [{"_name": "x", )" + body + "}]"); };
    const std::string phong = shader(R"("_type": "BlinnPhong", "diffuse": "1 1 1", "phongExp": -1)");
    expectJsonIssueAt(jsonErrorOf(phong), phong, "-1}", "scene.shader[0].phongExp", "-1");
    const std::string murky = shader(R"("_type": "Dielectric", "attenuationCoef": "0.9 -0.1 0.9")");
    expectJsonIssueAt(jsonErrorOf(murky), murky, "\"0.9 -0.1", "scene.shader[0].attenuationCoef", "0.9 -0.1 0.9");
    const std::string rough = shader(R"("_type": "Mirror", "roughness": -0.5)");
    EXPECT_EQ(jsonErrorOf(rough).problem, "must not be negative");
    const std::string glass = shader(R"("_type": "Dielectric", "refractiveIndex": 0)");
    const Issue issue = jsonErrorOf(glass);
    expectJsonIssueAt(issue, glass, "0}", "scene.shader[0].refractiveIndex", "0");
    EXPECT_EQ(issue.problem, "must be positive");
    EXPECT_EQ(jsonErrorOf(shader(R"("diffuse": "1 1 1")")).problem, "missing required key _type (or type)");
    // A nameless shader is skipped with a warning (sd20200409_mirroredScene.json), refused under --strict.
    EXPECT_EQ(jsonErrorOf(jsonWith(R"("shader": [{"_type": "Lambertian"}])"), true).problem,
              "a shader without _name (or name) cannot be referred to, skipped");
}

TEST_F(JsonBadInput, SingularScaleAndBadRotationAxes) {
    const auto transformed = [](const std::string& step) {
        return withShape(R"({"_type": "sphere", "center": "0 0 0", "radius": 1, "shader": {"_ref": "s"}, "xform": [)" + step + "]}");
    };
    const std::string scale = transformed(R"({"type": "scale", "amount": "1 0 1"})");
    const Issue s = jsonErrorOf(scale);
    expectJsonIssueAt(s, scale, "\"1 0 1\"", "scene.shape[0].xform[0].amount", "1 0 1");
    EXPECT_EQ(s.problem, "a zero scale factor makes the transform singular");
    const std::string axis = transformed(R"({"type": "rotation", "axis": "W", "amount": 30})");
    const Issue a = jsonErrorOf(axis);
    expectJsonIssueAt(a, axis, "\"W\"", "scene.shape[0].xform[0].axis", "W");
    EXPECT_EQ(a.problem, "axis must be X, Y or Z, not");
    EXPECT_EQ(jsonErrorOf(transformed(R"({"type": "rotation", "amount": 30})")).problem, "missing required key axis");
    EXPECT_EQ(jsonErrorOf(withShape(R"({"_type": "sphere", "center": "0 0 0", "radius": 1, "shader": {"_ref": "s"}, "xform": {}})")).problem,
              "expected an array, found an object");
    const std::string object = withShape(R"({"_type": "sphere", "center": "0 0 0", "radius": 1, "shader": {"_ref": "s"}, "transform": {"rotate": {"_axis": "Q", "_angle": 1}}})");
    EXPECT_EQ(jsonErrorOf(object).element, "scene.shape[0].transform.rotate._axis");
}

// Issue 22: negative colours and a mirrorCoef outside 0..1 warn with their path and are kept (as XML).
TEST_F(JsonBadInput, NegativeColoursAndAMirrorCoefOutsideZeroToOneWarn) {
    const std::string json = jsonWith(
        R"("shader": [{"_name": "g", "_type": "Glaze", "diffuse": {"tex": "t", "data": "1 -2 1"}, "mirrorCoef": -0.5}],)" "\n"
        R"("texture": [{"_name": "t", "sourcefile": "none.png"}],)" "\n"
        R"("light": [{"position": "0 1 0", "intensity": [-1, 1, 1]}])");
    Diagnostics diagnostics;
    const Scene scene = loadJson(json, diagnostics);
    EXPECT_EQ(scene.shaders[0].diffuse, glm::vec3(1, -2, 1));
    EXPECT_EQ(scene.shaders[0].mirrorCoef, -0.5f);
    EXPECT_EQ(scene.lights[0].intensity, glm::vec3(-1, 1, 1));
    std::vector<std::string> paths;
    for (const Issue& w : diagnostics.warnings()) paths.push_back(w.element);
    for (const char* path : {"scene.shader[0].diffuse.data", "scene.shader[0].mirrorCoef", "scene.light[0].intensity"})
        EXPECT_NE(std::find(paths.begin(), paths.end(), path), paths.end()) << path;
}

// Issue 22: the composed matrix is checked where it is made, at the xform, not later by the BVH builder.
TEST_F(JsonBadInput, AComposedTransformBeyondFloatIsAnErrorAtTheXform) {
    std::string steps;
    for (int i = 0; i < 5; ++i) steps += std::string(i ? ", " : "") + R"({"type": "scale", "amount": "1e10 1e10 1e10"})";
    const std::string json = withShape(R"({"_type": "sphere", "center": "0 0 0", "radius": 1, "shader": {"_ref": "s"}, "xform": [)" + steps + "]}");
    const Issue issue = jsonErrorOf(json);
    expectJsonIssueAt(issue, json, "[{\"type\"", "scene.shape[0].xform", "");
    EXPECT_NE(issue.problem.find("overflows float"), std::string::npos) << issue.message();
}

// Issue 21: xformEnd beside xform is the pose at the end of the motion; the other handedness is an
// error at the xformEnd.
TEST_F(JsonBadInput, XformEndMovesAShapeAndTheOtherHandednessIsAnError) {
    const Scene scene = loadJsonClean(withShape(R"({"_type": "sphere", "center": "0 0 0", "radius": 1, "shader": {"_ref": "s"}, )"
                                                R"("xform": [{"type": "translate", "amount": "1 0 0"}], "xformEnd": [{"type": "translate", "amount": "2 0 0"}]})"));
    ASSERT_EQ(scene.instances.size(), 1u);
    EXPECT_TRUE(scene.instances[0].moving);
    EXPECT_EQ(glm::vec3(scene.instances[0].objectToWorldEnd[3]), glm::vec3(2, 0, 0));
    const std::string mirrored = withShape(R"({"_type": "sphere", "center": "0 0 0", "radius": 1, "shader": {"_ref": "s"}, )"
                                           R"("xformEnd": [{"type": "scale", "amount": "1 1 -1"}]})");
    const Issue issue = jsonErrorOf(mirrored);
    expectJsonIssueAt(issue, mirrored, "[{\"type\": \"scale\"", "scene.shape[0].xformEnd", "");
    EXPECT_NE(issue.problem.find("mirrors the object"), std::string::npos) << issue.message();
}

// A shape light does not move: its xformEnd is warned and changes nothing, not even whether its
// points are world positions (which decides how they are rebased to the local origin).
TEST_F(JsonBadInput, AShapeLightsXformEndIsIgnoredWithAWarning) {
    const auto lit = [this](const std::string& extra) {
        // The eye away from the origin, so that rebasing moves world points.
        write("light.json", R"({"scene": {"camera": [{"position": "10 0 0", "viewDir": "0 0 -1"}], )"
                            R"("light": [{"_type": "shape", "intensity": "1 1 1", "shape": {"_type": "sphere", "center": "1 2 3", "radius": 0.5)" +
                                extra + "}}]}}");
        LoadOptions options;
        options.localOrigin = true;
        Diagnostics diagnostics;
        Scene scene = loadScene((dir / "light.json").string(), options, diagnostics);
        return std::pair(scene, diagnostics.warnings().size());
    };
    const auto [still, stillWarnings] = lit("");
    const auto [moved, movedWarnings] = lit(R"(, "xformEnd": [{"type": "translate", "amount": "5 0 0"}])");
    ASSERT_EQ(still.emitters.size(), 1u);
    ASSERT_EQ(moved.emitters.size(), 1u);
    EXPECT_EQ(moved.emitters[0].shape.center, still.emitters[0].shape.center);
    EXPECT_EQ(moved.emitters[0].objectToWorld, still.emitters[0].objectToWorld);
    EXPECT_EQ(movedWarnings, stillWarnings + 1);
}

TEST_F(JsonBadInput, NestingDeeperThan64LevelsIsRefusedWhereItGoesTooDeep) {
    // Each level's path repeats its parent's: 200000 levels would need ~100 GB of paths.
    const std::string json = jsonWith("\"deep\": " + std::string(200000, '[') + std::string(200000, ']'));
    const Issue issue = jsonErrorOf(json);
    const int column = columnOf(json, "[[") + 62;  // the 65th container: the root, "scene" and 62 brackets are open
    expectJsonIssue(issue, 4, column, "json", "");
    EXPECT_EQ(issue.problem, "nested deeper than 64 levels, not a scene");
    // 60 levels are still a document (under an unknown key: a warning).
    Diagnostics diagnostics;
    loadJson(jsonWith("\"deep\": " + std::string(60, '[') + std::string(60, ']')), diagnostics);
    ASSERT_EQ(diagnostics.warnings().size(), 1u);
    EXPECT_EQ(diagnostics.warnings()[0].element, "scene.deep");
}

TEST_F(JsonBadInput, LineAndColumnAreRightWithCrLfTabsAndMultiByteText) {
    std::string json = withShape(sphere("-2"));
    json.insert(json.find("\"shape\""), "\t\"_bgColor\": \"0.5 0.5 0.5\", \"note\": \"\xC3\xA9t\xC3\xA9\",\n");  // two 2-byte characters
    std::string crlf;
    for (char c : json) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    Diagnostics diagnostics;
    try {
        loadJson(crlf, diagnostics);
        FAIL();
    } catch (const SceneError& error) {
        expectJsonIssueAt(error.issue(), json, "-2", "scene.shape[0].radius", "-2");
    }
    ASSERT_EQ(diagnostics.warnings().size(), 1u);  // "note": columns count bytes, and the tab is one
    expectJsonIssueAt(diagnostics.warnings()[0], json, "\"note\"", "scene.note", "");
}

}  // namespace
}  // namespace vkrt::test
