#include "obj_mesh.h"

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include <tiny_obj_loader.h>

#include "input_limits.h"
#include "mesh_normals.h"
#include "obj_validation.h"

namespace vkrt {

namespace {

struct Corners {
    std::vector<tinyobj::index_t> indices;  // three per triangle
    bool allHaveNormals = true;
    bool allHaveUVs = true;
};

// All triangle corners of all groups. tinyobjloader's triangulation already split the polygons;
// a face that still has more corners (it gives up on some degenerate polygons) is fanned here.
Corners collectTriangleCorners(const std::vector<tinyobj::shape_t>& shapes) {
    Corners corners;
    for (const tinyobj::shape_t& shape : shapes) {
        std::size_t offset = 0;
        for (unsigned char faceSize : shape.mesh.num_face_vertices) {
            const auto& idx = shape.mesh.indices;
            for (std::size_t k = 2; k < faceSize; ++k) {
                corners.indices.push_back(idx[offset]);
                corners.indices.push_back(idx[offset + k - 1]);
                corners.indices.push_back(idx[offset + k]);
            }
            offset += faceSize;
        }
    }
    for (const tinyobj::index_t& i : corners.indices) {
        corners.allHaveNormals = corners.allHaveNormals && i.normal_index >= 0;
        corners.allHaveUVs = corners.allHaveUVs && i.texcoord_index >= 0;
    }
    return corners;
}

void checkIndex(int index, std::size_t count, const char* what) {
    if (index < 0 || static_cast<std::size_t>(index) >= count)
        throw std::runtime_error(std::string("face refers to a ") + what + " that does not exist (index " +
                                 std::to_string(index + 1) + " of " + std::to_string(count) + ")");
}

struct Triple {
    int v, vt, vn;
    bool operator==(const Triple&) const = default;
};
struct TripleHash {
    std::size_t operator()(const Triple& t) const {
        std::size_t h = std::hash<int>()(t.v);
        h = h * 1000003u ^ std::hash<int>()(t.vt);
        return h * 1000003u ^ std::hash<int>()(t.vn);
    }
};

// An istream over text already in memory, without the copy std::istringstream makes (a 100 MB OBJ
// would be held three times).
struct TextBuffer : std::streambuf {
    explicit TextBuffer(const std::string& text) {
        char* begin = const_cast<char*>(text.data());  // read only: the get area is never written
        setg(begin, begin, begin + text.size());
    }
};

glm::vec3 vec3At(const std::vector<tinyobj::real_t>& values, int index) {
    const std::size_t i = static_cast<std::size_t>(index) * 3;
    return {values[i], values[i + 1], values[i + 2]};
}

}  // namespace

Mesh loadObjMesh(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw std::runtime_error("mesh file not found");
    if (!std::filesystem::is_regular_file(path, ec)) throw std::runtime_error("mesh path is not a regular file");
    if (const std::uintmax_t size = std::filesystem::file_size(path, ec); !ec && size > inputLimits().meshFileBytes)
        throw std::runtime_error("the mesh file is " + std::to_string(size) + " bytes; an OBJ file may have at most " +
                                 std::to_string(inputLimits().meshFileBytes) + inputLimitHint("mesh-bytes"));
    std::ifstream file(path, std::ios::binary);
    if (!file) throw std::runtime_error("cannot open mesh file");
    std::stringstream buffer;
    buffer << file.rdbuf();
    const std::string text = buffer.str();
    validateObjText(text);  // what tinyobjloader would accept silently (obj_validation.h)
    TextBuffer buffered(text);
    std::istream in(&buffered);

    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warning, error;
    // No material reader: mtllib lines are skipped. No vertex-colour fallback: we do not use them.
    if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warning, &error, &in, nullptr, /*triangulate=*/true,
                          /*default_vcols_fallback=*/false))
        throw std::runtime_error("not a readable OBJ file (" + error + ")");

    const Corners corners = collectTriangleCorners(shapes);
    if (corners.indices.empty()) throw std::runtime_error("OBJ file has no faces");

    const std::size_t vertexCount = attrib.vertices.size() / 3;
    for (const tinyobj::index_t& i : corners.indices) {
        checkIndex(i.vertex_index, vertexCount, "vertex");
        if (corners.allHaveNormals) checkIndex(i.normal_index, attrib.normals.size() / 3, "normal");
        if (corners.allHaveUVs) checkIndex(i.texcoord_index, attrib.texcoords.size() / 2, "texture coordinate");
    }
    for (tinyobj::real_t v : attrib.vertices)
        if (!std::isfinite(v)) throw std::runtime_error("vertex coordinate is not a finite number");

    Mesh mesh;
    mesh.path = path;
    const std::size_t triangleCount = corners.indices.size() / 3;
    mesh.triangles.reserve(triangleCount);

    if (!corners.allHaveNormals && !corners.allHaveUVs) {
        // Positions only (every course file): the OBJ vertices are the mesh vertices.
        mesh.positions.reserve(vertexCount);
        for (std::size_t v = 0; v < vertexCount; ++v) mesh.positions.push_back(vec3At(attrib.vertices, static_cast<int>(v)));
        for (std::size_t t = 0; t < triangleCount; ++t)
            mesh.triangles.emplace_back(corners.indices[3 * t].vertex_index, corners.indices[3 * t + 1].vertex_index,
                                        corners.indices[3 * t + 2].vertex_index);
    } else {
        // OBJ indexes positions, normals and uvs separately; one mesh vertex per distinct triple.
        std::unordered_map<Triple, std::uint32_t, TripleHash> vertexOf;
        std::vector<std::uint32_t> corner(corners.indices.size());
        for (std::size_t c = 0; c < corners.indices.size(); ++c) {
            const tinyobj::index_t& i = corners.indices[c];
            const Triple key{i.vertex_index, corners.allHaveUVs ? i.texcoord_index : -1,
                             corners.allHaveNormals ? i.normal_index : -1};
            auto [it, inserted] = vertexOf.try_emplace(key, static_cast<std::uint32_t>(mesh.positions.size()));
            if (inserted) {
                mesh.positions.push_back(vec3At(attrib.vertices, key.v));
                if (key.vn >= 0) {
                    const glm::vec3 n = vec3At(attrib.normals, key.vn);
                    const float length = glm::length(n);
                    mesh.normals.push_back(length > 0.0f && std::isfinite(length) ? n / length : glm::vec3(0.0f));
                }
                if (key.vt >= 0) {
                    const std::size_t k = static_cast<std::size_t>(key.vt) * 2;
                    mesh.uvs.emplace_back(attrib.texcoords[k], attrib.texcoords[k + 1]);
                }
            }
            corner[c] = it->second;
        }
        for (std::size_t t = 0; t < triangleCount; ++t)
            mesh.triangles.emplace_back(corner[3 * t], corner[3 * t + 1], corner[3 * t + 2]);
    }
    if (!corners.allHaveNormals) mesh.normals = angleWeightedVertexNormals(mesh.positions, mesh.triangles);
    return mesh;
}

}  // namespace vkrt
