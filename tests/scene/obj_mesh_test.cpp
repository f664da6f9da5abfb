// OBJ loading and generated vertex normals, on hand-made files and the course's meshes.
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
        EXPECT_NE(std::string(error.what()).find("index 4 of 3"), std::string::npos) << error.what();
    }
    // tinyobjloader reads "nan", "inf" and words as 0; an overflowing exponent becomes inf, caught here.
    EXPECT_THROW(loadObjMesh(write("inf.obj", "v 0 0 1e999\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")), std::runtime_error);
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
