#include "scene_tables.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace vkrt {

namespace {

std::uint32_t shaderTypeId(ShaderType type) {
    switch (type) {
    case ShaderType::Lambertian: return gpu::SHADER_LAMBERTIAN;
    case ShaderType::BlinnPhong: return gpu::SHADER_BLINN_PHONG;
    case ShaderType::Mirror: return gpu::SHADER_MIRROR;
    case ShaderType::Glaze: return gpu::SHADER_GLAZE;
    case ShaderType::BlinnPhongMirrored: return gpu::SHADER_BLINN_PHONG_MIRRORED;
    case ShaderType::Dielectric: return gpu::SHADER_DIELECTRIC;
    case ShaderType::CoolToWarm: return gpu::SHADER_COOL_TO_WARM;
    }
    throw std::logic_error("unknown shader type " + std::to_string(static_cast<int>(type)));
}

std::uint32_t textureId(int texture) {
    return texture == kNoTexture ? gpu::TEXTURE_NONE : static_cast<std::uint32_t>(texture);
}

}  // namespace

gpu::Material toGpuMaterial(const Shader& s) {
    gpu::Material m{};
    m.diffuse = glm::vec4(s.diffuse, 0.0f);
    m.specular = glm::vec4(s.specular, s.phongExp);
    m.attenuation = glm::vec4(s.attenuation, s.refractiveIndex);
    m.params = glm::vec4(s.mirrorCoef, s.roughness, 0.0f, 0.0f);
    const std::uint32_t type = s.diffuseBounce ? gpu::SHADER_DIFFUSE : shaderTypeId(s.type);
    m.ids = glm::uvec4(type, textureId(s.diffuseTexture), textureId(s.specularTexture), 0u);
    return m;
}

void areaLightFrame(const glm::vec3& normal, glm::vec3& tangent, glm::vec3& bitangent) {
    const glm::vec3 a = std::abs(normal.z) > 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 0.0f, 1.0f);
    tangent = glm::normalize(glm::cross(a, normal));
    bitangent = glm::cross(normal, tangent);
}

gpu::Light toGpuLight(const Light& light, std::uint32_t areaOrdinal) {
    gpu::Light g{};
    g.position = glm::vec4(light.position, 0.0f);
    g.intensity = glm::vec4(light.intensity, 0.0f);
    if (light.type == LightType::Area) {
        glm::vec3 t, b;
        areaLightFrame(light.normal, t, b);
        g.edgeU = glm::vec4(light.width * t, 0.0f);
        g.edgeV = glm::vec4(light.length * b, 0.0f);
        g.info = glm::uvec4(gpu::LIGHT_AREA, areaOrdinal, 0u, 0u);
    } else {
        g.info = glm::uvec4(gpu::LIGHT_POINT, 0u, 0u, 0u);
    }
    return g;
}

namespace {

// Vertex attributes of every mesh, returning each mesh's first attribute index.
std::vector<std::uint32_t> appendVertexAttribs(const Scene& scene, std::vector<gpu::VertexAttrib>& out) {
    std::vector<std::uint32_t> base;
    for (const Mesh& mesh : scene.meshes) {
        if (mesh.normals.size() != mesh.positions.size() || (!mesh.uvs.empty() && mesh.uvs.size() != mesh.positions.size()))
            throw std::runtime_error(mesh.path + ": mesh has " + std::to_string(mesh.positions.size()) + " positions but " +
                                     std::to_string(mesh.normals.size()) + " normals and " + std::to_string(mesh.uvs.size()) +
                                     " uvs (expected one each per position)");
        base.push_back(static_cast<std::uint32_t>(out.size()));
        for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
            const glm::vec2 uv = mesh.uvs.empty() ? glm::vec2(0.0f) : mesh.uvs[v];
            out.push_back({glm::vec4(mesh.normals[v], uv.x), glm::vec4(uv.y, 0.0f, 0.0f, 0.0f)});
        }
    }
    return base;
}

}  // namespace

SceneTables buildSceneTables(const Scene& scene, const SceneAccel& accel) {
    SceneTables t;
    for (const Shader& s : scene.shaders) t.materials.push_back(toGpuMaterial(s));
    for (std::size_t e = 0; e < scene.emitters.size(); ++e) {
        gpu::Material m{};
        m.diffuse = glm::vec4(scene.emitters[e].radiance, 0.0f);
        m.ids = glm::uvec4(gpu::SHADER_EMITTER, gpu::TEXTURE_NONE, gpu::TEXTURE_NONE, static_cast<std::uint32_t>(e));
        t.materials.push_back(m);
    }
    t.lighting = accel.lighting ? accel.lighting : std::make_shared<const SceneLighting>(buildSceneLighting(scene));

    std::uint32_t areaLights = 0;
    for (const Light& l : scene.lights) t.lights.push_back(toGpuLight(l, l.type == LightType::Area ? areaLights++ : 0u));

    const std::vector<std::uint32_t> attribBase = appendVertexAttribs(scene, t.vertexAttribs);

    const bvh::SceneBvh& bvh = accel.bvh;
    t.primInfos.resize(bvh.prims.size(), gpu::PrimInfo{glm::uvec4(0u, gpu::ATTRIB_NONE, gpu::ATTRIB_NONE, gpu::ATTRIB_NONE)});
    for (std::size_t group = 0; group < bvh.groups.size(); ++group) {
        const bvh::GroupRange& range = bvh.groups[group];
        for (std::uint32_t p = range.firstPrim; p < range.firstPrim + range.primCount; ++p) {
            const PrimOrigin& origin = accel.groupPrims[group][bvh.primSource[p]];
            glm::uvec4 info(static_cast<std::uint32_t>(origin.shape->shader), gpu::ATTRIB_NONE, gpu::ATTRIB_NONE, gpu::ATTRIB_NONE);
            if (origin.triangle >= 0) {
                const int mesh = origin.shape->mesh;
                const glm::uvec3 corners = scene.meshes[mesh].triangles[origin.triangle];
                info.y = attribBase[mesh] + corners.x;
                info.z = attribBase[mesh] + corners.y;
                info.w = attribBase[mesh] + corners.z;
            }
            t.primInfos[p].data = info;
        }
    }

    for (const Texture& tex : scene.textures) {
        t.textures.push_back({glm::uvec4(static_cast<std::uint32_t>(t.texels.size()), static_cast<std::uint32_t>(tex.width),
                                         static_cast<std::uint32_t>(tex.height), 0u)});
        t.texels.insert(t.texels.end(), tex.rgba8.begin(), tex.rgba8.end());
    }
    return t;
}

}  // namespace vkrt
