#include "scene_compare.h"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <sstream>

#include "scene_writing.h"

namespace vkrt {

namespace {

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

std::string sameFileKey(const std::string& path) {
    std::error_code ec;
    const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, ec);
    return ec ? path : canonical.string();
}

// Walks both models side by side, recording each field that differs under its path.
class Differ {
public:
    explicit Differ(std::size_t limit) : limit_(limit) {}

    void note(const std::string& field, const std::string& a, const std::string& b) {
        if (result.first.size() < limit_) result.first.push_back(field + ": " + a + " vs " + b);
        ++result.count;
    }
    void check(const std::string& field, float a, float b) {
        if (!sameBits(a, b)) note(field, writing::floatText(a), writing::floatText(b));
    }
    void check(const std::string& field, const glm::vec3& a, const glm::vec3& b) {
        if (!sameBits(a.x, b.x) || !sameBits(a.y, b.y) || !sameBits(a.z, b.z))
            note(field, writing::vec3Text(a), writing::vec3Text(b));
    }
    void check(const std::string& field, const glm::mat4& a, const glm::mat4& b) {
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                if (!sameBits(a[c][r], b[c][r]))
                    return note(field + "[" + std::to_string(c) + "][" + std::to_string(r) + "]",
                                writing::floatText(a[c][r]), writing::floatText(b[c][r]));
    }
    void check(const std::string& field, long long a, long long b) {
        if (a != b) note(field, std::to_string(a), std::to_string(b));
    }
    void check(const std::string& field, int a, int b) { check(field, static_cast<long long>(a), static_cast<long long>(b)); }
    void check(const std::string& field, bool a, bool b) { check(field, static_cast<long long>(a), static_cast<long long>(b)); }
    void check(const std::string& field, const std::string& a, const std::string& b) {
        if (a != b) note(field, "'" + a + "'", "'" + b + "'");
    }
    void checkPath(const std::string& field, const std::string& a, const std::string& b) {
        if (sameFileKey(a) != sameFileKey(b)) note(field, "'" + a + "'", "'" + b + "'");
    }
    // Same size, then each element under its index.
    template <typename T, typename F>
    void each(const std::string& field, const std::vector<T>& a, const std::vector<T>& b, F compare) {
        if (a.size() != b.size()) return note(field + ".size", std::to_string(a.size()), std::to_string(b.size()));
        for (std::size_t i = 0; i < a.size(); ++i) compare(field + "[" + std::to_string(i) + "]", a[i], b[i]);
    }
    // Bulk data (texels, vertices): the first differing element only, shown by `text`.
    template <typename T, typename Equal, typename Text>
    void data(const std::string& field, const std::vector<T>& a, const std::vector<T>& b, Equal equal, Text text) {
        if (a.size() != b.size()) return note(field + ".size", std::to_string(a.size()), std::to_string(b.size()));
        for (std::size_t i = 0; i < a.size(); ++i)
            if (!equal(a[i], b[i])) return note(field + "[" + std::to_string(i) + "]", text(a[i]), text(b[i]));
    }

    SceneDifferences result;

private:
    std::size_t limit_;
};

bool sameVec3(const glm::vec3& a, const glm::vec3& b) { return sameBits(a.x, b.x) && sameBits(a.y, b.y) && sameBits(a.z, b.z); }
bool sameVec2(const glm::vec2& a, const glm::vec2& b) { return sameBits(a.x, b.x) && sameBits(a.y, b.y); }
std::string vec2Text(const glm::vec2& v) { return writing::floatText(v.x) + " " + writing::floatText(v.y); }
std::string indexText(const glm::uvec3& t) { return std::to_string(t.x) + " " + std::to_string(t.y) + " " + std::to_string(t.z); }
std::string texelText(std::uint32_t rgba) {
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%08x", rgba);
    return hex;
}

void compareShape(Differ& d, const std::string& f, const Shape& a, const Shape& b) {
    d.check(f + ".name", a.name, b.name);
    d.check(f + ".type", static_cast<long long>(a.type), static_cast<long long>(b.type));
    d.check(f + ".shader", a.shader, b.shader);
    d.check(f + ".center", a.center, b.center);
    d.check(f + ".radius", a.radius, b.radius);
    d.check(f + ".minPt", a.minPt, b.minPt);
    d.check(f + ".maxPt", a.maxPt, b.maxPt);
    d.check(f + ".v0", a.v0, b.v0);
    d.check(f + ".v1", a.v1, b.v1);
    d.check(f + ".v2", a.v2, b.v2);
    d.check(f + ".mesh", a.mesh, b.mesh);
}

void compareSteps(Differ& d, const std::string& f, const std::vector<TransformStep>& a, const std::vector<TransformStep>& b) {
    d.each(f, a, b, [&](const std::string& g, const TransformStep& x, const TransformStep& y) {
        d.check(g + ".kind", static_cast<long long>(x.kind), static_cast<long long>(y.kind));
        d.check(g + ".amount", x.amount, y.amount);
        d.check(g + ".axis", x.axis, y.axis);
    });
}

}  // namespace

std::string SceneDifferences::summary() const {
    std::ostringstream out;
    for (const std::string& line : first) out << line << "\n";
    if (count > first.size()) out << "... and " << count - first.size() << " more\n";
    return out.str();
}

SceneDifferences compareScenes(const Scene& a, const Scene& b, std::size_t limit) {
    Differ d(limit);
    if (a.origin != b.origin) {
        const auto text = [](const glm::dvec3& v) {
            char buffer[96];
            std::snprintf(buffer, sizeof buffer, "%.17g %.17g %.17g", v.x, v.y, v.z);
            return std::string(buffer);
        };
        d.note("origin", text(a.origin), text(b.origin));
    }
    d.check("background", a.background, b.background);
    d.checkPath("envMapPrefix", a.envMapPrefix, b.envMapPrefix);
    d.checkPath("envMapVertCross", a.envMapVertCross, b.envMapVertCross);
    d.check("defaultCamera", a.defaultCamera, b.defaultCamera);
    d.each("cameras", a.cameras, b.cameras, [&](const std::string& f, const Camera& x, const Camera& y) {
        d.check(f + ".name", x.name, y.name);
        d.check(f + ".type", static_cast<long long>(x.type), static_cast<long long>(y.type));
        d.check(f + ".position", x.position, y.position);
        d.check(f + ".gaze", x.gaze, y.gaze);
        d.check(f + ".focalLength", x.focalLength, y.focalLength);
        d.check(f + ".imagePlaneWidth", x.imagePlaneWidth, y.imagePlaneWidth);
        d.check(f + ".focusDistance", x.focusDistance, y.focusDistance);
        d.check(f + ".aperture", x.aperture, y.aperture);
        d.check(f + ".up.given", x.up.has_value(), y.up.has_value());
        if (x.up && y.up) d.check(f + ".up", *x.up, *y.up);
    });
    d.each("lights", a.lights, b.lights, [&](const std::string& f, const Light& x, const Light& y) {
        d.check(f + ".type", static_cast<long long>(x.type), static_cast<long long>(y.type));
        d.check(f + ".position", x.position, y.position);
        d.check(f + ".intensity", x.intensity, y.intensity);
        d.check(f + ".normal", x.normal, y.normal);
        d.check(f + ".width", x.width, y.width);
        d.check(f + ".length", x.length, y.length);
    });
    d.each("shaders", a.shaders, b.shaders, [&](const std::string& f, const Shader& x, const Shader& y) {
        d.check(f + ".name", x.name, y.name);
        d.check(f + ".type", static_cast<long long>(x.type), static_cast<long long>(y.type));
        d.check(f + ".diffuse", x.diffuse, y.diffuse);
        d.check(f + ".specular", x.specular, y.specular);
        d.check(f + ".phongExp", x.phongExp, y.phongExp);
        d.check(f + ".mirrorCoef", x.mirrorCoef, y.mirrorCoef);
        d.check(f + ".roughness", x.roughness, y.roughness);
        d.check(f + ".refractiveIndex", x.refractiveIndex, y.refractiveIndex);
        d.check(f + ".attenuation", x.attenuation, y.attenuation);
        d.check(f + ".diffuseTexture", x.diffuseTexture, y.diffuseTexture);
        d.check(f + ".specularTexture", x.specularTexture, y.specularTexture);
        d.check(f + ".diffuseBounce", x.diffuseBounce, y.diffuseBounce);
        d.check(f + ".emission", x.emission, y.emission);
        d.check(f + ".undefined", x.undefined, y.undefined);
    });
    d.each("textures", a.textures, b.textures, [&](const std::string& f, const Texture& x, const Texture& y) {
        d.check(f + ".name", x.name, y.name);
        d.checkPath(f + ".path", x.path, y.path);
        d.check(f + ".width", x.width, y.width);
        d.check(f + ".height", x.height, y.height);
        d.data(f + ".rgba8", x.rgba8, y.rgba8, std::equal_to<>(), texelText);
    });
    d.each("meshes", a.meshes, b.meshes, [&](const std::string& f, const Mesh& x, const Mesh& y) {
        d.checkPath(f + ".path", x.path, y.path);
        d.data(f + ".positions", x.positions, y.positions, sameVec3, writing::vec3Text);
        d.data(f + ".normals", x.normals, y.normals, sameVec3, writing::vec3Text);
        d.data(f + ".uvs", x.uvs, y.uvs, sameVec2, vec2Text);
        d.data(f + ".triangles", x.triangles, y.triangles, std::equal_to<>(), indexText);
    });
    const auto shape = [&](const std::string& f, const Shape& x, const Shape& y) { compareShape(d, f, x, y); };
    d.each("shapes", a.shapes, b.shapes, shape);
    d.each("prototypes", a.prototypes, b.prototypes, shape);
    d.each("instances", a.instances, b.instances, [&](const std::string& f, const Instance& x, const Instance& y) {
        d.check(f + ".name", x.name, y.name);
        d.check(f + ".prototype", x.prototype, y.prototype);
        d.check(f + ".shaderOverride", x.shaderOverride, y.shaderOverride);
        compareSteps(d, f + ".steps", x.steps, y.steps);
        d.check(f + ".objectToWorld", x.objectToWorld, y.objectToWorld);
        d.check(f + ".ownPrototype", x.ownPrototype, y.ownPrototype);
        d.check(f + ".moving", x.moving, y.moving);
        compareSteps(d, f + ".stepsEnd", x.stepsEnd, y.stepsEnd);
        d.check(f + ".objectToWorldEnd", x.objectToWorldEnd, y.objectToWorldEnd);
    });
    d.each("emitters", a.emitters, b.emitters, [&](const std::string& f, const Emitter& x, const Emitter& y) {
        d.check(f + ".name", x.name, y.name);
        d.check(f + ".radiance", x.radiance, y.radiance);
        compareShape(d, f + ".shape", x.shape, y.shape);
        d.check(f + ".prototype", x.prototype, y.prototype);
        compareSteps(d, f + ".steps", x.steps, y.steps);
        d.check(f + ".objectToWorld", x.objectToWorld, y.objectToWorld);
        d.check(f + ".lightsBefore", x.lightsBefore, y.lightsBefore);
    });
    return d.result;
}

}  // namespace vkrt
