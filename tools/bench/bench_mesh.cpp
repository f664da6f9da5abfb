#include "bench_mesh.h"

#include <cmath>
#include <stdexcept>

#include <tiny_obj_loader.h>

namespace vkrt::bench {

namespace {

BenchMesh uvSphere(int n) {
    if (n < 1 || n > 8192) throw std::runtime_error("sphere:N needs 1 <= N <= 8192, got " + std::to_string(n));
    BenchMesh m;
    const int columns = 2 * n + 1;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= 2 * n; ++j) {
            // Angles rounded to float first, as the peer does, so the vertices are bit-identical.
            const auto theta = static_cast<float>(M_PI * i / n), phi = static_cast<float>(M_PI * j / n);
            m.positions.emplace_back(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
        }
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < 2 * n; ++j) {
            const auto a = static_cast<std::uint32_t>(i * columns + j), b = a + 1;
            const auto c = a + static_cast<std::uint32_t>(columns), d = c + 1;
            m.triangles.emplace_back(a, c, b);
            m.triangles.emplace_back(b, c, d);
        }
    return m;
}

BenchMesh objMesh(const std::string& path) {
    tinyobj::ObjReader reader;
    tinyobj::ObjReaderConfig config;
    config.triangulate = false;
    if (!reader.ParseFromFile(path, config)) {
        std::string why = reader.Error();
        while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
        throw std::runtime_error(path + ": cannot read the OBJ file: " + (why.empty() ? "unknown error" : why));
    }
    BenchMesh m;
    const auto& v = reader.GetAttrib().vertices;
    for (std::size_t i = 0; i + 2 < v.size(); i += 3) m.positions.emplace_back(v[i], v[i + 1], v[i + 2]);
    for (const auto& shape : reader.GetShapes()) {
        std::size_t offset = 0;
        for (const auto fv : shape.mesh.num_face_vertices) {
            for (unsigned k = 1; k + 1 < fv; ++k) {
                const auto& idx = shape.mesh.indices;
                m.triangles.emplace_back(idx[offset].vertex_index, idx[offset + k].vertex_index,
                                         idx[offset + k + 1].vertex_index);
            }
            offset += fv;
        }
    }
    if (m.triangles.empty()) throw std::runtime_error(path + ": no triangles");
    for (const glm::uvec3& t : m.triangles)
        if (glm::max(t.x, glm::max(t.y, t.z)) >= m.positions.size())
            throw std::runtime_error(path + ": face refers to vertex " + std::to_string(glm::max(t.x, glm::max(t.y, t.z)) + 1) +
                                     " of " + std::to_string(m.positions.size()));
    return m;
}

}  // namespace

BenchMesh loadBenchMesh(const std::string& source) {
    BenchMesh m = source.rfind("sphere:", 0) == 0 ? uvSphere(std::atoi(source.c_str() + 7)) : objMesh(source);
    m.lo = glm::vec3(1e30f);
    m.hi = glm::vec3(-1e30f);
    for (const glm::vec3& p : m.positions) {
        m.lo = glm::min(m.lo, p);
        m.hi = glm::max(m.hi, p);
    }
    return m;
}

std::vector<bvh::PrimitiveInput> toPrimitives(const BenchMesh& mesh) {
    std::vector<bvh::PrimitiveInput> prims(mesh.triangles.size());
    for (std::size_t i = 0; i < prims.size(); ++i) {
        const glm::uvec3 t = mesh.triangles[i];
        prims[i] = {gpu::PRIM_KIND_TRIANGLE, mesh.positions[t.x], mesh.positions[t.y], mesh.positions[t.z]};
    }
    return prims;
}

}  // namespace vkrt::bench
