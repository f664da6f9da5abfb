// <shape>, <instance> prototypes and <transform> (docs/XML_FORMAT.md §3.6-3.9).
#include <cmath>

#include "json_writer.h"
#include "scene_test_files.h"
#include "xml_writer.h"

namespace vkrt::test {
namespace {

using ShapeParsing = SceneFiles;
using TransformParsing = SceneFiles;

const std::string kShader = "<shader name=\"s\" type=\"Lambertian\"><diffuse>1 1 1</diffuse></shader>\n";

glm::vec3 apply(const glm::mat4& m, glm::vec3 p) { return glm::vec3(m * glm::vec4(p, 1.0f)); }

void expectNear(glm::vec3 got, glm::vec3 want, float tolerance = 1e-5f) {
    EXPECT_NEAR(got.x, want.x, tolerance);
    EXPECT_NEAR(got.y, want.y, tolerance);
    EXPECT_NEAR(got.z, want.z, tolerance);
}

TEST_F(ShapeParsing, SphereBoxTriangle) {
    const Scene scene = loadClean(sceneWith(kShader +
        "<shape name=\"ball\" type=\"sphere\"><shader ref=\"s\"/><center>1 2 3</center><radius>0.5</radius></shape>\n"
        "<shape name=\"ground\" type=\"box\"><shader ref=\"s\" /><minPt>-50.0 -0.5 -50.0</minPt><maxPt>50.0 0.0 50.0</maxPt></shape>\n"
        "<shape name=\"tri\" type=\"triangle\"><shader ref=\"s\"/><v0>0 0 0</v0><v1>1 0 0</v1><v2>0 1 0</v2></shape>"));
    ASSERT_EQ(scene.shapes.size(), 3u);
    EXPECT_EQ(scene.shapes[0].type, ShapeType::Sphere);
    EXPECT_EQ(scene.shapes[0].name, "ball");
    EXPECT_EQ(scene.shapes[0].center, glm::vec3(1, 2, 3));
    EXPECT_EQ(scene.shapes[0].radius, 0.5f);
    EXPECT_EQ(scene.shapes[0].shader, 0);
    EXPECT_EQ(scene.shapes[0].where.line, 5);
    EXPECT_EQ(scene.shapes[1].type, ShapeType::Box);
    EXPECT_EQ(scene.shapes[1].minPt, glm::vec3(-50, -0.5f, -50));
    EXPECT_EQ(scene.shapes[1].maxPt, glm::vec3(50, 0, 50));
    EXPECT_EQ(scene.shapes[2].type, ShapeType::Triangle);
    EXPECT_EQ(scene.shapes[2].v1, glm::vec3(1, 0, 0));
    EXPECT_EQ(scene.shapes[2].v2, glm::vec3(0, 1, 0));
    EXPECT_TRUE(scene.prototypes.empty());
    EXPECT_TRUE(scene.instances.empty());
}

TEST_F(ShapeParsing, ZeroThicknessBoxIsAllowed) {
    const Scene scene = loadClean(sceneWith(kShader +
        "<shape type=\"box\"><shader ref=\"s\"/><minPt>0 1 0</minPt><maxPt>1 1 1</maxPt></shape>"));
    EXPECT_EQ(scene.shapes[0].minPt.y, scene.shapes[0].maxPt.y);
}

TEST_F(ShapeParsing, ShaderRefAfterGeometryAndShaderDefinedAfterTheShape) {
    // boxSphereTest.xml / CornellRoom*.xml put <shader ref> last; child order never matters.
    const Scene scene = loadClean(sceneWith(
        "<shape type=\"sphere\"><center>0 0 0</center><radius>1</radius><shader ref=\"late\"/></shape>\n"
        "<shader name=\"first\" type=\"Lambertian\"><diffuse>1 0 0</diffuse></shader>\n"
        "<shader name=\"late\" type=\"Lambertian\"><diffuse>0 1 0</diffuse></shader>"));
    ASSERT_EQ(scene.shapes.size(), 1u);
    EXPECT_EQ(scene.shaders[scene.shapes[0].shader].name, "late");
}

TEST_F(ShapeParsing, InlineShaderIsRegisteredGloballyAndUsed) {
    const Scene scene = loadClean(sceneWith(
        "<shape name=\"a\" type=\"sphere\"><shader name=\"inl\" type=\"Glaze\"><diffuse>0 0 1</diffuse><mirrorCoef>0.5</mirrorCoef></shader>"
        "<center>0 0 0</center><radius>1</radius></shape>\n"
        "<shape name=\"b\" type=\"sphere\"><shader ref=\"inl\"/><center>3 0 0</center><radius>1</radius></shape>\n"
        "<shape name=\"c\" type=\"sphere\"><shader type=\"Mirror\"/><center>6 0 0</center><radius>1</radius></shape>"));
    ASSERT_EQ(scene.shaders.size(), 2u);
    EXPECT_EQ(scene.shaders[0].name, "inl");
    EXPECT_EQ(scene.shaders[0].type, ShaderType::Glaze);
    EXPECT_EQ(scene.shapes[0].shader, 0);
    EXPECT_EQ(scene.shapes[1].shader, 0);
    EXPECT_EQ(scene.shaders[scene.shapes[2].shader].type, ShaderType::Mirror);  // nameless, its shape's own
}

TEST_F(ShapeParsing, MeshShapeAndPrototypeShareOneMeshPerFile) {
    write("obj/tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n");
    const Scene scene = loadClean(sceneWith(kShader +
        "<shape name=\"m1\" type=\"mesh\"><file>obj/tri.obj</file><shader ref=\"s\"/></shape>\n"
        "<instance name=\"proto\" type=\"mesh\"><file>obj/../obj/tri.obj</file><shader ref=\"s\"/></instance>\n"
        "<shape name=\"m2\" type=\"instance\" id=\"proto\"/>"));
    ASSERT_EQ(scene.meshes.size(), 1u);
    EXPECT_EQ(scene.meshes[0].triangles.size(), 2u);
    ASSERT_EQ(scene.shapes.size(), 1u);
    EXPECT_EQ(scene.shapes[0].type, ShapeType::Mesh);
    EXPECT_EQ(scene.shapes[0].mesh, 0);
    ASSERT_EQ(scene.prototypes.size(), 1u);
    EXPECT_EQ(scene.prototypes[0].mesh, 0);
}

TEST_F(ShapeParsing, PrototypesAreNotShapesAndInstancesOverrideOrInheritTheShader) {
    const Scene scene = loadClean(sceneWith(
        "<shader name=\"blueMat\" type=\"Lambertian\"><diffuse>0.4 0.4 1.0</diffuse></shader>\n"
        "<shader name=\"red\" type=\"Lambertian\"><diffuse>1 0 0</diffuse></shader>\n"
        "<instance name=\"eggBase\" type=\"sphere\"><shader ref=\"blueMat\"/><center>0.0 0.0 0.0</center><radius>1.0</radius></instance>\n"
        "<shape name=\"plain\" type=\"instance\" id=\"eggBase\"/>\n"
        "<shape name=\"redEgg\" type=\"instance\" id=\"eggBase\"><shader ref=\"red\"/></shape>"));
    EXPECT_TRUE(scene.shapes.empty());
    ASSERT_EQ(scene.prototypes.size(), 1u);
    EXPECT_EQ(scene.prototypes[0].name, "eggBase");
    EXPECT_EQ(scene.prototypes[0].shader, 0);
    ASSERT_EQ(scene.instances.size(), 2u);
    EXPECT_EQ(scene.instances[0].name, "plain");
    EXPECT_EQ(scene.instances[0].prototype, 0);
    EXPECT_EQ(scene.instances[0].shaderOverride, -1);
    EXPECT_EQ(scene.instances[0].objectToWorld, glm::mat4(1.0f));
    EXPECT_EQ(scene.instances[1].shaderOverride, 1);
}

TEST_F(ShapeParsing, PrototypeDefinedAfterItsInstanceStillResolves) {
    const Scene scene = loadClean(sceneWith(kShader +
        "<shape name=\"i\" type=\"instance\" id=\"later\"/>\n"
        "<instance name=\"later\" type=\"box\"><shader ref=\"s\"/><minPt>0 0 0</minPt><maxPt>1 1 1</maxPt></instance>"));
    ASSERT_EQ(scene.instances.size(), 1u);
    EXPECT_EQ(scene.prototypes[scene.instances[0].prototype].type, ShapeType::Box);
}

TEST_F(ShapeParsing, UnknownShapeAndPrototypeTypesAreSkippedWithWarnings) {
    const std::string xml = sceneWith(kShader +
        "<shape name=\"c\" type=\"cylinder\"><shader ref=\"s\"/></shape>\n"
        "<instance name=\"skyModel\" type=\"skysphere\"><shader ref=\"s\"/><radius>2000.0</radius></instance>\n"
        "<shape name=\"sky\" type=\"instance\" id=\"skyModel\"><transform><rotate axis=\"X\">-90</rotate></transform></shape>\n"
        "<shape name=\"ok\" type=\"sphere\"><shader ref=\"s\"/><center>0 0 0</center><radius>1</radius></shape>");
    Diagnostics diagnostics;
    const Scene scene = load(xml, diagnostics);
    EXPECT_EQ(scene.shapes.size(), 1u);
    EXPECT_TRUE(scene.prototypes.empty());
    EXPECT_TRUE(scene.instances.empty());
    ASSERT_EQ(diagnostics.warnings().size(), 3u);
    expectIssue(diagnostics.warnings()[0], lineOf(xml, "skysphere"), "instance", "skysphere");  // pass 1
    expectIssue(diagnostics.warnings()[1], lineOf(xml, "cylinder"), "shape", "cylinder");
    expectIssue(diagnostics.warnings()[2], lineOf(xml, "id=\"skyModel\""), "shape", "skyModel");
}

TEST_F(ShapeParsing, UnknownElementsWarnWithTheirLineAndAreIgnored) {
    const std::string xml = sceneWith(kShader +
        "<!-- a comment --> stray text -->\n"
        "<shape name=\"b1\" type=\"sphere\">\n<attribute>wireframe</attribute>\n<shader ref=\"s\"/><center>0 0 0</center><radius>1</radius></shape>\n"
        "<fog density=\"1\"/>");
    Diagnostics diagnostics;
    const Scene scene = load(xml, diagnostics);
    EXPECT_EQ(scene.shapes.size(), 1u);
    ASSERT_EQ(diagnostics.warnings().size(), 2u);
    // In the order of the passes (XML_FORMAT.md §7.2): the scene's own children, then its shapes.
    expectIssue(diagnostics.warnings()[0], lineOf(xml, "<fog"), "fog", "");
    expectIssue(diagnostics.warnings()[1], lineOf(xml, "<attribute>"), "attribute", "");
    EXPECT_THROW(load(xml, diagnostics, /*strict=*/true), SceneError);
}

TEST_F(ShapeParsing, DegenerateTriangleIsAWarning) {
    const std::string xml = sceneWith(kShader +
        "<shape name=\"flat\" type=\"triangle\"><shader ref=\"s\"/><v0>0 0 0</v0><v1>1 1 1</v1><v2>2 2 2</v2></shape>");
    Diagnostics diagnostics;
    EXPECT_EQ(load(xml, diagnostics).shapes.size(), 1u);
    ASSERT_EQ(diagnostics.warnings().size(), 1u);
    expectIssue(diagnostics.warnings()[0], lineOf(xml, "flat"), "shape", "flat");
}

TEST_F(TransformParsing, ListedOrderIsMultipliedLeftToRight) {
    const Scene scene = loadClean(sceneWith(kShader +
        "<instance name=\"p\" type=\"sphere\"><shader ref=\"s\"/><center>0 0 0</center><radius>1</radius></instance>\n"
        "<shape type=\"instance\" id=\"p\"><transform name=\"xform1\"><translate>10 0 0</translate><scale>2 2 2</scale></transform></shape>\n"
        "<shape type=\"instance\" id=\"p\"><transform name=\"xform1\"><scale>2 2 2</scale><translate>10 0 0</translate></transform></shape>"));
    ASSERT_EQ(scene.instances.size(), 2u);
    // T*S: scale first, then translate -> (1,0,0) goes to (12,0,0).
    expectNear(apply(scene.instances[0].objectToWorld, {1, 0, 0}), {12, 0, 0});
    // S*T: translate first, then scale -> (1,0,0) goes to (22,0,0).
    expectNear(apply(scene.instances[1].objectToWorld, {1, 0, 0}), {22, 0, 0});
}

TEST_F(TransformParsing, RotationsAreRightHandedDegreesAboutEachAxisAnyCase) {
    const Scene scene = loadClean(sceneWith(kShader +
        "<instance name=\"p\" type=\"sphere\"><shader ref=\"s\"/><center>0 0 0</center><radius>1</radius></instance>\n"
        "<shape type=\"instance\" id=\"p\"><transform><rotate axis=\"X\">90</rotate></transform></shape>\n"
        "<shape type=\"instance\" id=\"p\"><transform><rotate axis=\"y\">90</rotate></transform></shape>\n"
        "<shape type=\"instance\" id=\"p\"><transform><rotate axis=\"Zaxis\">90</rotate></transform></shape>\n"
        "<shape type=\"instance\" id=\"p\"><transform><rotate axis=\"Z\">4500</rotate></transform></shape>"));
    ASSERT_EQ(scene.instances.size(), 4u);
    expectNear(apply(scene.instances[0].objectToWorld, {0, 1, 0}), {0, 0, 1});   // X: y -> z
    expectNear(apply(scene.instances[1].objectToWorld, {0, 0, 1}), {1, 0, 0});   // Y: z -> x
    expectNear(apply(scene.instances[2].objectToWorld, {1, 0, 0}), {0, 1, 0});   // Z: x -> y
    expectNear(apply(scene.instances[3].objectToWorld, {1, 0, 0}), {-1, 0, 0});  // 4500 = 12*360 + 180
}

TEST_F(TransformParsing, TransformOnAPlainShapeMakesItsOwnPrototypeAndInstance) {
    const Scene scene = loadClean(sceneWith(kShader +
        "<shape name=\"moved\" type=\"box\"><shader ref=\"s\"/><minPt>0 0 0</minPt><maxPt>1 1 1</maxPt>"
        "<transform><translate>0 5 0</translate></transform></shape>"));
    EXPECT_TRUE(scene.shapes.empty());
    ASSERT_EQ(scene.prototypes.size(), 1u);
    ASSERT_EQ(scene.instances.size(), 1u);
    EXPECT_EQ(scene.instances[0].name, "moved");
    EXPECT_EQ(scene.instances[0].shaderOverride, -1);
    expectNear(apply(scene.instances[0].objectToWorld, scene.prototypes[0].maxPt), {1, 6, 1});
}

TEST_F(TransformParsing, BadAxisAndZeroScaleAreErrors) {
    const std::string prototype =
        kShader + "<instance name=\"p\" type=\"sphere\"><shader ref=\"s\"/><center>0 0 0</center><radius>1</radius></instance>\n";
    const std::string axis = sceneWith(prototype + "<shape type=\"instance\" id=\"p\"><transform><rotate axis=\"W\">90</rotate></transform></shape>");
    expectIssue(errorOf(axis), lineOf(axis, "<rotate"), "rotate", "W");
    const std::string noAxis = sceneWith(prototype + "<shape type=\"instance\" id=\"p\"><transform><rotate>90</rotate></transform></shape>");
    EXPECT_EQ(errorOf(noAxis).element, "rotate");
    const std::string scale = sceneWith(prototype + "<shape type=\"instance\" id=\"p\"><transform><scale>1 0 1</scale></transform></shape>");
    expectIssue(errorOf(scale), lineOf(scale, "<scale>"), "scale", "1 0 1");
}

// Issue 22: repeated scales overflowed the composed matrix and only the BVH builder noticed
// ("bvh: instance 0"); the transform parser says it at the <transform>, for growth and for shrinkage.
TEST_F(TransformParsing, AComposedTransformBeyondFloatIsAnErrorAtTheTransform) {
    const std::string prototype =
        kShader + "<instance name=\"p\" type=\"sphere\"><shader ref=\"s\"/><center>0 0 0</center><radius>1</radius></instance>\n";
    std::string grow, shrink;
    for (int i = 0; i < 5; ++i) grow += "<scale>1e10 1e10 1e10</scale>";  // 1e50
    for (int i = 0; i < 5; ++i) shrink += "<scale>1e-10 1 1</scale>";     // inverse 1e50
    const std::string big = sceneWith(prototype + "<shape type=\"instance\" id=\"p\">\n<transform>" + grow + "</transform></shape>");
    const Issue b = errorOf(big);
    expectIssue(b, lineOf(big, "<transform>"), "transform", "");
    EXPECT_NE(b.problem.find("overflows float"), std::string::npos) << b.message();
    const std::string small = sceneWith(prototype + "<shape type=\"sphere\"><shader ref=\"s\"/><center>0 0 0</center><radius>1</radius>\n<transform>" +
                                        shrink + "</transform></shape>");
    const Issue s = errorOf(small);
    expectIssue(s, lineOf(small, "<transform>"), "transform", "");
    EXPECT_NE(s.problem.find("float"), std::string::npos) << s.message();
    // Three of them (1e30, inverse 1e-30) are still a float matrix with a float inverse: loaded,
    // with the warning that a sphere reaching 1e30 is beyond float intersection (geometry_extent.h).
    std::string three;
    for (int i = 0; i < 3; ++i) three += "<scale>1e10 1e10 1e10</scale>";
    Diagnostics diagnostics;
    EXPECT_NO_THROW(load(sceneWith(prototype + "<shape type=\"instance\" id=\"p\"><transform>" + three + "</transform></shape>"), diagnostics));
    ASSERT_EQ(diagnostics.warnings().size(), 1u);
    EXPECT_NE(diagnostics.warnings()[0].problem.find("reaches 1e+30"), std::string::npos) << diagnostics.messages()[0];
}

// Issue 21: <transformEnd> beside <transform> is the pose at the end of the motion (motion blur),
// on instances and transformed plain shapes; a pose of the other handedness is an error at the
// <transformEnd>; both writers keep it.
TEST_F(TransformParsing, TransformEndIsThePoseAtTheEndOfTheMotion) {
    const std::string prototype =
        kShader + "<instance name=\"p\" type=\"sphere\"><shader ref=\"s\"/><center>0 0 0</center><radius>1</radius></instance>\n";
    const Scene scene = loadClean(sceneWith(prototype +
        "<shape name=\"a\" type=\"instance\" id=\"p\"><transform><translate>1 0 0</translate></transform>"
        "<transformEnd><translate>3 0 0</translate><rotate axis=\"Y\">90</rotate></transformEnd></shape>\n"
        "<shape name=\"b\" type=\"box\"><shader ref=\"s\"/><minPt>0 0 0</minPt><maxPt>1 1 1</maxPt>"
        "<transformEnd><scale>2 2 2</scale></transformEnd></shape>\n"
        "<shape name=\"c\" type=\"instance\" id=\"p\"><transform><translate>0 1 0</translate></transform></shape>"));
    ASSERT_EQ(scene.instances.size(), 3u);
    const Instance& a = scene.instances[0];
    EXPECT_TRUE(a.moving);
    ASSERT_EQ(a.stepsEnd.size(), 2u);
    expectNear(apply(a.objectToWorld, {0, 0, 0}), {1, 0, 0});
    expectNear(apply(a.objectToWorldEnd, {1, 0, 0}), {3, 0, -1});
    // A plain shape with only a <transformEnd> starts where it stands (the identity).
    const Instance& b = scene.instances[1];
    EXPECT_TRUE(b.moving && b.ownPrototype);
    EXPECT_EQ(b.objectToWorld, glm::mat4(1.0f));
    expectNear(apply(b.objectToWorldEnd, {1, 1, 1}), {2, 2, 2});
    EXPECT_FALSE(scene.instances[2].moving);
    for (const std::string& text : {xmlSceneText(scene, dir), jsonSceneText(scene, dir)})
        EXPECT_NE(text.find(text.front() == '<' ? "transformEnd" : "xformEnd"), std::string::npos) << text;

    const std::string mirrored = sceneWith(prototype +
        "<shape type=\"instance\" id=\"p\"><transform><translate>1 0 0</translate></transform>\n"
        "<transformEnd><scale>-1 1 1</scale></transformEnd></shape>");
    const Issue issue = errorOf(mirrored);
    expectIssue(issue, lineOf(mirrored, "<transformEnd>"), "transformEnd", "");
    EXPECT_NE(issue.problem.find("mirrors the object"), std::string::npos) << issue.message();
}

}  // namespace
}  // namespace vkrt::test
