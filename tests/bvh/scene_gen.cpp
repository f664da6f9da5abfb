#include "scene_gen.h"

#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>
#include <tiny_obj_loader.h>

#include "primitives.h"

namespace vkrt::bvh::test {

namespace {
glm::vec3 uniformIn(std::mt19937& rng, const glm::vec3& lo, const glm::vec3& hi) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    return lo + glm::vec3(u(rng), u(rng), u(rng)) * (hi - lo);
}
}  // namespace

std::vector<PrimitiveInput> randomTriangles(std::mt19937& rng, std::size_t count, float extent, float size) {
    std::vector<PrimitiveInput> out(count);
    for (PrimitiveInput& p : out) {
        p.kind = gpu::PRIM_KIND_TRIANGLE;
        const glm::vec3 c = uniformIn(rng, glm::vec3(0.0f), glm::vec3(extent));
        p.a = c + uniformIn(rng, glm::vec3(-size), glm::vec3(size));
        p.b = c + uniformIn(rng, glm::vec3(-size), glm::vec3(size));
        p.c = c + uniformIn(rng, glm::vec3(-size), glm::vec3(size));
    }
    return out;
}

std::vector<PrimitiveInput> randomSpheresAndBoxes(std::mt19937& rng, std::size_t count, float extent, float size) {
    std::uniform_real_distribution<float> u(0.1f, 1.0f);
    std::vector<PrimitiveInput> out(count);
    for (std::size_t i = 0; i < count; ++i) {
        PrimitiveInput& p = out[i];
        const glm::vec3 c = uniformIn(rng, glm::vec3(0.0f), glm::vec3(extent));
        if (i % 2 == 0) {
            p.kind = gpu::PRIM_KIND_SPHERE;
            p.a = c;
            p.b = glm::vec3(size * u(rng), 0.0f, 0.0f);
        } else {
            p.kind = gpu::PRIM_KIND_BOX;
            const glm::vec3 half = size * glm::vec3(u(rng), u(rng), u(rng));
            p.a = c - half;
            p.b = c + half;
        }
    }
    return out;
}

std::vector<PrimitiveInput> loadObjTriangles(const std::string& path) {
    tinyobj::ObjReader reader;
    tinyobj::ObjReaderConfig config;
    config.triangulate = false;
    if (!reader.ParseFromFile(path, config)) throw std::runtime_error(path + ": " + reader.Error());
    const auto& v = reader.GetAttrib().vertices;
    auto vertex = [&](int i) { return glm::vec3(v[3 * i], v[3 * i + 1], v[3 * i + 2]); };
    std::vector<PrimitiveInput> out;
    for (const auto& shape : reader.GetShapes()) {
        std::size_t offset = 0;
        for (const auto fv : shape.mesh.num_face_vertices) {
            for (unsigned k = 1; k + 1 < fv; ++k) {
                PrimitiveInput p;
                p.kind = gpu::PRIM_KIND_TRIANGLE;
                p.a = vertex(shape.mesh.indices[offset].vertex_index);
                p.b = vertex(shape.mesh.indices[offset + k].vertex_index);
                p.c = vertex(shape.mesh.indices[offset + k + 1].vertex_index);
                out.push_back(p);
            }
            offset += fv;
        }
    }
    return out;
}

TestScene singleGroup(std::vector<PrimitiveInput> prims) {
    TestScene s;
    s.groups.push_back(std::move(prims));
    s.instances.push_back({0, glm::mat4(1.0f), gpu::MATERIAL_NONE});
    return s;
}

glm::mat4 randomTransform(std::mt19937& rng, float extent, bool mirror) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const glm::vec3 axis = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) - 0.5f + 1e-3f);
    glm::vec3 scale(0.3f + 2.0f * u(rng), 0.3f + 2.0f * u(rng), 0.3f + 2.0f * u(rng));
    if (mirror) scale[static_cast<int>(u(rng) * 2.999f)] *= -1.0f;
    glm::mat4 m = glm::translate(glm::mat4(1.0f), uniformIn(rng, glm::vec3(0.0f), glm::vec3(extent)));
    m = glm::rotate(m, 6.2831853f * u(rng), axis);
    return glm::scale(m, scale);
}

Aabb sceneBounds(const TestScene& scene) {
    Aabb world;
    for (const InstanceInput& inst : scene.instances)
        for (const PrimitiveInput& p : scene.groups[inst.group]) {
            const Aabb b = boundsOf(p);
            for (int c = 0; c < 8; ++c) {
                const glm::vec3 corner((c & 1) ? b.hi.x : b.lo.x, (c & 2) ? b.hi.y : b.lo.y, (c & 4) ? b.hi.z : b.lo.z);
                world.grow(glm::vec3(inst.objectToWorld * glm::vec4(corner, 1.0f)));
            }
        }
    return world;
}

std::vector<Ray> randomRays(std::mt19937& rng, const TestScene& scene, std::size_t count) {
    const Aabb b = sceneBounds(scene);
    const glm::vec3 margin = 0.5f * (b.hi - b.lo) + 1.0f;
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<Ray> rays(count);
    for (std::size_t i = 0; i < count; ++i) {
        Ray& r = rays[i];
        r.origin = uniformIn(rng, b.lo - margin, b.hi + margin);
        glm::vec3 target = uniformIn(rng, b.lo, b.hi);
        if (i % 2 == 0 && !scene.instances.empty()) {
            const InstanceInput& inst = scene.instances[rng() % scene.instances.size()];
            const auto& prims = scene.groups[inst.group];
            if (!prims.empty()) {
                const Aabb pb = boundsOf(prims[rng() % prims.size()]);
                target = glm::vec3(inst.objectToWorld * glm::vec4(uniformIn(rng, pb.lo, pb.hi), 1.0f));
            }
        }
        const glm::vec3 d = target - r.origin;
        const float len = glm::length(d);
        r.dir = len > 0.0f ? d / len * (0.25f + 4.0f * u(rng)) : glm::vec3(0.0f, 0.0f, 1.0f);
    }
    return rays;
}

}  // namespace vkrt::bvh::test
