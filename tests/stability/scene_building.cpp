#include "scene_building.h"

#include <map>
#include <tuple>

#include "mesh_normals.h"

namespace vkrt::stability {

Camera perspective(glm::vec3 position, glm::vec3 lookAt, float focalLength, float planeWidth) {
    return test::perspectiveCamera(position, lookAt - position, focalLength, planeWidth);
}

Shader lambertian(glm::vec3 diffuse) {
    Shader s;
    s.type = ShaderType::Lambertian;
    s.diffuse = diffuse;
    return s;
}

Shader blinnPhong(glm::vec3 diffuse, glm::vec3 specular, float phongExp) {
    Shader s;
    s.type = ShaderType::BlinnPhong;
    s.diffuse = diffuse;
    s.specular = specular;
    s.phongExp = phongExp;
    return s;
}

Shader mirror(float roughness) {
    Shader s;
    s.type = ShaderType::Mirror;
    s.roughness = roughness;
    return s;
}

Shader glossy(glm::vec3 diffuse, float mirrorCoef, float roughness) {
    Shader s;
    s.type = ShaderType::BlinnPhongMirrored;
    s.diffuse = diffuse;
    s.specular = glm::vec3(0.4f);
    s.phongExp = 24.0f;
    s.mirrorCoef = mirrorCoef;
    s.roughness = roughness;
    return s;
}

Shader dielectric(float eta, glm::vec3 attenuation) {
    Shader s;
    s.type = ShaderType::Dielectric;
    s.refractiveIndex = eta;
    s.attenuation = attenuation;
    return s;
}

int addInstancedMesh(Scene& scene, int mesh, int shader, const glm::mat4& objectToWorld) {
    Shape prototype;
    prototype.type = ShapeType::Mesh;
    prototype.mesh = mesh;
    prototype.shader = shader;
    scene.prototypes.push_back(prototype);
    Instance instance;
    instance.prototype = static_cast<int>(scene.prototypes.size()) - 1;
    instance.objectToWorld = objectToWorld;
    scene.instances.push_back(instance);
    return static_cast<int>(scene.instances.size()) - 1;
}

void addLooseMesh(Scene& scene, int mesh, int shader) {
    Shape shape;
    shape.type = ShapeType::Mesh;
    shape.mesh = mesh;
    shape.shader = shader;
    scene.shapes.push_back(shape);
}

void generateNormals(Mesh& mesh) { mesh.normals = angleWeightedVertexNormals(mesh.positions, mesh.triangles); }

std::vector<glm::ivec3> cubeSphereLattice(int n) {
    std::vector<glm::ivec3> points;
    for (int x = -n; x <= n; x += 2)
        for (int y = -n; y <= n; y += 2)
            for (int z = -n; z <= n; z += 2)
                if (std::abs(x) == n || std::abs(y) == n || std::abs(z) == n) points.emplace_back(x, y, z);
    return points;
}

Mesh cubeSphere(int n, float r) {
    Mesh mesh;
    std::map<std::tuple<int, int, int>, unsigned> index;
    auto vertex = [&](glm::ivec3 p) {
        const auto key = std::make_tuple(p.x, p.y, p.z);
        if (auto it = index.find(key); it != index.end()) return it->second;
        const auto k = static_cast<unsigned>(mesh.positions.size());
        mesh.positions.push_back(r * glm::normalize(glm::vec3(p)));
        index.emplace(key, k);
        return k;
    };
    for (int axis = 0; axis < 3; ++axis) {
        const int b = (axis + 1) % 3, c = (axis + 2) % 3;
        for (int sign : {-1, 1}) {
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) {
                    auto corner = [&](int di, int dj) {
                        glm::ivec3 p(0);
                        p[axis] = sign * n;
                        p[b] = 2 * (i + di) - n;
                        p[c] = 2 * (j + dj) - n;
                        return vertex(p);
                    };
                    const unsigned p00 = corner(0, 0), p10 = corner(1, 0), p11 = corner(1, 1), p01 = corner(0, 1);
                    // e_b x e_c = e_axis: counter-clockwise seen from outside on the + face.
                    if (sign > 0) {
                        mesh.triangles.emplace_back(p00, p10, p11);
                        mesh.triangles.emplace_back(p00, p11, p01);
                    } else {
                        mesh.triangles.emplace_back(p00, p11, p10);
                        mesh.triangles.emplace_back(p00, p01, p11);
                    }
                }
        }
    }
    generateNormals(mesh);
    return mesh;
}

Mesh torus(float ringRadius, float tubeRadius, int ringSegments, int tubeSegments) {
    Mesh mesh;
    constexpr float kTwoPi = 6.28318530717958647692f;
    for (int i = 0; i < ringSegments; ++i)
        for (int j = 0; j < tubeSegments; ++j) {
            const float theta = kTwoPi * static_cast<float>(i) / static_cast<float>(ringSegments);
            const float phi = kTwoPi * static_cast<float>(j) / static_cast<float>(tubeSegments);
            const float ring = ringRadius + tubeRadius * std::cos(phi);
            mesh.positions.emplace_back(ring * std::cos(theta), tubeRadius * std::sin(phi), ring * std::sin(theta));
        }
    auto at = [&](int i, int j) {
        return static_cast<unsigned>(((i + ringSegments) % ringSegments) * tubeSegments + (j + tubeSegments) % tubeSegments);
    };
    for (int i = 0; i < ringSegments; ++i)
        for (int j = 0; j < tubeSegments; ++j) {
            mesh.triangles.emplace_back(at(i, j), at(i, j + 1), at(i + 1, j + 1));
            mesh.triangles.emplace_back(at(i, j), at(i + 1, j + 1), at(i + 1, j));
        }
    generateNormals(mesh);
    return mesh;
}

}  // namespace vkrt::stability
