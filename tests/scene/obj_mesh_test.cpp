// OBJ loading and generated vertex normals, on hand-made files and the course's meshes.
#include <chrono>
#include <cmath>

#include "mesh_normals.h"
#include "obj_mesh.h"
#include "scene_test_files.h"
#include "test_paths.h"

namespace vkrt::test {
namespace {

using ObjMesh = SceneFiles;

void expectNear(glm::vec3 got, glm::vec3 want, float tolerance = 1e-5f) {
    EXPECT_NEAR(got.x, want.x, tolerance);
    EXPECT_NEAR(got.y, want.y, tolerance);
    EXPECT_NEAR(got.z, want.z, tolerance);
}

TEST_F(ObjMesh, QuadAndPentagonAreTriangulated) {
    const Mesh mesh = loadObjMesh(write("poly.obj",
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 3 0 0\nv 3.5 1 0\nv 2.5 2 0\nv 1.5 1 0\n"
        "f 1 2 3 4\nf 5 6 7 8 9\n"));
    EXPECT_EQ(mesh.positions.size(), 9u);
    EXPECT_EQ(mesh.triangles.size(), 2u + 3u);  // an n-gon gives n - 2 triangles
    EXPECT_TRUE(mesh.uvs.empty());
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    for (const glm::vec3& n : mesh.normals) expectNear(n, {0, 0, 1});  // flat, counter-clockwise
}

TEST_F(ObjMesh, NegativeRelativeIndicesAndUnknownKeywordsAreFine) {
    const Mesh mesh = loadObjMesh(write("rel.obj",
        "mtllib nothere.mtl\ng part\ngroup weird keyword\ns 1\nusemtl red\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n"));
    ASSERT_EQ(mesh.triangles.size(), 1u);
    EXPECT_EQ(mesh.triangles[0], glm::uvec3(0, 1, 2));
}

TEST_F(ObjMesh, GeneratedNormalsAreAngleWeighted) {
    // A cube corner at the origin: the square in the xy plane (normal +z) split into two triangles
    // that meet the vertex with 45-degree corners each, and one triangle in the xz plane (normal
    // +y) meeting it with a 90-degree corner. Angle weighting gives both planes pi/2 in total, so
    // the normal is normalize(0, 1, 1). A plain average (two faces against one) or area weighting
    // (area 1 against 0.5) would tilt it towards +z.
    const Mesh mesh = loadObjMesh(write("corner.obj",
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 -1\n"
        "f 1 2 3\nf 1 3 4\nf 1 2 5\n"));
    const float k = 1.0f / std::sqrt(2.0f);
    expectNear(mesh.normals[0], {0, k, k});
}

TEST_F(ObjMesh, DegenerateFacesContributeNothingAndIsolatedVerticesGetZero) {
    const std::vector<glm::vec3> positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {5, 5, 5}};
    const std::vector<glm::uvec3> triangles = {{0, 1, 2}, {0, 1, 3}};  // second: collinear, zero area
    const std::vector<glm::vec3> normals = angleWeightedVertexNormals(positions, triangles);
    expectNear(normals[0], {0, 0, 1});
    expectNear(normals[1], {0, 0, 1});
    EXPECT_EQ(normals[3], glm::vec3(0.0f));  // only in the degenerate face
    EXPECT_EQ(normals[4], glm::vec3(0.0f));  // in no face at all
}

TEST_F(ObjMesh, FileNormalsAndUvsAreKeptPerCorner) {
    const Mesh mesh = loadObjMesh(write("full.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 2\nvn 1 0 0\n"
        "f 1/1/1 2/2/1 3/3/1\nf 1/1/2 3/3/2 2/2/2\n"));
    ASSERT_EQ(mesh.triangles.size(), 2u);
    // Vertex 1 appears with two different normals, so it becomes two mesh vertices.
    EXPECT_EQ(mesh.positions.size(), 6u);
    ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    const glm::uvec3 first = mesh.triangles[0];
    expectNear(mesh.normals[first.x], {0, 0, 1});  // normalised from (0 0 2)
    EXPECT_EQ(mesh.uvs[first.y], glm::vec2(1, 0));
    EXPECT_EQ(mesh.positions[first.z], glm::vec3(0, 1, 0));
    expectNear(mesh.normals[mesh.triangles[1].x], {1, 0, 0});
}

TEST_F(ObjMesh, UvsWithoutNormalsKeepUvsAndGenerateNormals) {
    const Mesh mesh = loadObjMesh(write("uv.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n"));
    ASSERT_EQ(mesh.uvs.size(), 3u);
    EXPECT_EQ(mesh.uvs[mesh.triangles[0].z], glm::vec2(0, 1));
    expectNear(mesh.normals[0], {0, 0, 1});
}

TEST_F(ObjMesh, ErrorsSayWhy) {
    EXPECT_THROW(loadObjMesh((dir / "none.obj").string()), std::runtime_error);
    EXPECT_THROW(loadObjMesh(write("nofaces.obj", "v 0 0 0\n")), std::runtime_error);
    try {
        loadObjMesh(write("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"));
        FAIL();
    } catch (const std::runtime_error& error) {
        EXPECT_STREQ(error.what(), "OBJ line 4: f: vertex index beyond the 3 defined before this line '4'");
    }
    EXPECT_THROW(loadObjMesh(write("inf.obj", "v 0 0 1e999\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")), std::runtime_error);
}

// The message loading `text` as dir/name gives, or "(loaded)".
class ObjMeshErrors : public SceneFiles {
protected:
    std::string objError(const std::string& name, const std::string& text) const {
        try {
            loadObjMesh(write(name, text));
        } catch (const std::runtime_error& error) {
            return error.what();
        }
        return "(loaded)";
    }
};

// Issue 22: what tinyobjloader accepted silently (read as 0, wrapped, or dropped) is refused with
// the OBJ's line, the keyword and the value as written (obj_validation.h).
TEST_F(ObjMeshErrors, GarbageTinyobjloaderWouldAcceptIsRefusedAtItsLine) {
    const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    EXPECT_EQ(objError("nan.obj", tri + "v nan 0 0\nf 1 2 3\n"), "OBJ line 4: v: not a finite 32-bit number 'nan'");
    EXPECT_EQ(objError("inf.obj", "v 0 inf 0\n" + tri + "f 1 2 3\n"), "OBJ line 1: v: not a finite 32-bit number 'inf'");
    EXPECT_EQ(objError("junk.obj", tri + "v 1 2 three\nf 1 2 3\n"), "OBJ line 4: v: not a finite 32-bit number 'three'");
    EXPECT_EQ(objError("two.obj", "v 0 0\n" + tri + "f 2 3 4\n"), "OBJ line 1: v: expected 3 coordinates (or 4, or 3 and a colour), found 2 ' 0 0'");
    EXPECT_EQ(objError("huge.obj", tri + "f 1 2 99999999999999999999\n"),
              "OBJ line 4: f: vertex index beyond the range of an int '99999999999999999999'");
    EXPECT_EQ(objError("uv.obj", tri + "vt 0 0\nf 1/1 2/1 3/-2\n"),
              "OBJ line 5: f: texture coordinate index counts back past the first one (1 defined before this line) '-2'");
    EXPECT_EQ(objError("zero.obj", tri + "f 0 1 2\n"), "OBJ line 4: f: vertex index 0 (OBJ indices start at 1, or count back from -1) '0'");
    EXPECT_EQ(objError("word.obj", tri + "f 1 2 x\n"), "OBJ line 4: f: vertex index is not an integer 'x'");
    EXPECT_EQ(objError("short.obj", tri + "f 1 2\n"), "OBJ line 4: f: a face needs at least 3 corners, found 2");
    EXPECT_EQ(objError("ahead.obj", "f 1 2 3\n" + tri), "OBJ line 1: f: vertex index beyond the 0 defined before this line '1'");
    // Lines end at \n, \r\n or a lone \r (tinyobjloader's reading), and line numbers count them so.
    EXPECT_EQ(objError("cr.obj", "v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 4\r"), "OBJ line 4: f: vertex index beyond the 3 defined before this line '4'");
    EXPECT_EQ(objError("crlf.obj", "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 4\r\n"), "OBJ line 4: f: vertex index beyond the 3 defined before this line '4'");
    EXPECT_EQ(objError("plus.obj", "v +1 0 0\nv 1 +0.5 0\nv 0 1 0\nf +1 2 3\n"), "(loaded)");
    // Still fine: comments, w and vertex colours, v//vn corners, negative indices.
    EXPECT_EQ(objError("ok.obj", "v 0 0 0 1 # w\nv 1 0 0 0.5 0.5 0.5\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf -3 -2 -1\n"), "(loaded)");
}

// Issue 22: one face of 100,000 corners (2.2 MB) spent 165 s in triangulation; it is refused
// before tinyobjloader sees it, at its line, in well under a second (bound: 10 s).
TEST_F(ObjMeshErrors, AFaceOfTooManyCornersIsRefusedQuickly) {
    std::string text;
    const std::size_t n = 100000;
    for (std::size_t i = 0; i < n; ++i) text += "v " + std::to_string(std::cos(i * 6.283185307 / n)) + " " + std::to_string(std::sin(i * 6.283185307 / n)) + " 0\n";
    text += "f";
    for (std::size_t i = 1; i <= n; ++i) text += " " + std::to_string(i);
    text += "\n";
    const auto start = std::chrono::steady_clock::now();
    EXPECT_EQ(objError("poly.obj", text),
              "OBJ line 100001: f: a face of 100000 corners; vkrt takes faces of up to 4096 (triangulation time grows as the square of the corners)");
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
}

TEST(UpstreamObj, AlObjWithGroupLinesAndPolygonsLoads) {
    VKRT_SKIP_WITHOUT(vkrt::test::upstreamDir());
    // al.obj: quads, polygons up to 23 vertices, `g`, non-standard `group`, `usemtl`, `mtllib`.
    // 280 triangles + 2980 quads + 180 larger polygons = 7124 triangles (SOURCES.md count).
    const Mesh mesh = loadObjMesh(upstreamDir() + "/objFiles/al.obj");
    EXPECT_EQ(mesh.triangles.size(), 7124u);
    EXPECT_EQ(mesh.positions.size(), 3618u);
    for (const glm::uvec3& t : mesh.triangles) {
        ASSERT_LT(t.x, mesh.positions.size());
        ASSERT_LT(t.y, mesh.positions.size());
        ASSERT_LT(t.z, mesh.positions.size());
    }
    int unit = 0;
    for (const glm::vec3& n : mesh.normals) unit += std::abs(glm::length(n) - 1.0f) < 1e-4f;
    EXPECT_GT(unit, 3500);  // every vertex used by a non-degenerate face has a unit normal
}

TEST(UpstreamObj, IcosahedronNormalsPointOutwardFromTheCentre) {
    VKRT_SKIP_WITHOUT(vkrt::test::upstreamDir());
    // A regular icosahedron centred at the origin: by symmetry the angle-weighted normal at each
    // vertex is the direction from the centre.
    const Mesh mesh = loadObjMesh(upstreamDir() + "/objFiles/icosahedron.obj");
    ASSERT_EQ(mesh.triangles.size(), 20u);
    glm::vec3 centre(0.0f);
    for (const glm::vec3& p : mesh.positions) centre += p / float(mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::vec3 radial = glm::normalize(mesh.positions[i] - centre);
        EXPECT_NEAR(std::abs(glm::dot(mesh.normals[i], radial)), 1.0f, 1e-4f) << "vertex " << i;
    }
}

}  // namespace
}  // namespace vkrt::test
