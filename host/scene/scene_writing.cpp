#include "scene_writing.h"

#include <stdexcept>

#include <charconv>
#include <cstdio>
#include <map>
#include <set>
#include <system_error>

#include "scene_rules.h"

namespace vkrt::writing {

namespace {
// What the loaders do with a number's text (number_text.cpp, nlohmann): parse as double, then
// narrow to float.
bool readsBackAs(const char* begin, const char* end, float value) {
    double parsed = 0.0;
    const auto [ptr, error] = std::from_chars(begin, end, parsed);
    return error == std::errc() && ptr == end && static_cast<float>(parsed) == value &&
           std::signbit(static_cast<float>(parsed)) == std::signbit(value);
}
}  // namespace

std::string floatText(float value) {
    char buffer[64];
    const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
    if (error == std::errc() && readsBackAs(buffer, end, value)) return std::string(buffer, end);
    // The shortest decimal can lie so near the midpoint between two floats that the double it
    // parses to rounds the other way; 9 digits sit well inside the float's interval.
    const int n = std::snprintf(buffer, sizeof buffer, "%.9g", static_cast<double>(value));
    return std::string(buffer, buffer + n);
}

std::string vec3Text(const glm::vec3& v) { return floatText(v.x) + " " + floatText(v.y) + " " + floatText(v.z); }

std::string relativePath(const std::string& path, const std::filesystem::path& outputDirectory) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path target = fs::absolute(path, ec);
    fs::path base = fs::absolute(outputDirectory.empty() ? fs::path(".") : outputDirectory, ec).lexically_normal();
    if (ec) return path;
    // `-o out.json` and `-o ./out.json` give "/cwd/." here, normalised to "/cwd/": without its
    // trailing separator, which weakly_canonical drops, it would pass for a symbolic link below.
    if (!base.has_filename() && base.has_relative_path()) base = base.parent_path();
    // Through a symbolic link, `..` from the output folder leads somewhere else than its spelling
    // says (the loaders resolve paths by spelling): name the file by its real, absolute path then.
    const fs::path real = fs::weakly_canonical(base, ec);
    if (ec || real != base) {
        const fs::path canonical = fs::weakly_canonical(target, ec);
        return (ec ? target.lexically_normal() : canonical).string();
    }
    // A prefix such as .../textures/reef_ names no file: relate its folder, keep its file name.
    const fs::path relative = target.parent_path().lexically_normal().lexically_relative(base);
    if (relative.empty()) return target.lexically_normal().string();
    return (relative / target.filename()).lexically_normal().string();
}

std::string shaderTypeName(const Shader& shader) {
    if (shader.diffuseBounce) return "Diffuse";
    if (shader.emission != glm::vec3(0.0f)) return "Emitter";
    switch (shader.type) {
        case ShaderType::Lambertian: return "Lambertian";
        case ShaderType::BlinnPhong: return "BlinnPhong";
        case ShaderType::Mirror: return "Mirror";
        case ShaderType::Glaze: return "Glaze";
        case ShaderType::BlinnPhongMirrored: return "BlinnPhongMirrored";
        case ShaderType::Dielectric: return "Dielectric";
        case ShaderType::CoolToWarm: return "CoolToWarm";
    }
    return "Lambertian";
}

std::vector<std::string_view> writtenParameters(const Shader& shader) {
    std::vector<std::string_view> written;
    for (std::string_view name : rules::shaderParametersUsedBy(*rules::shaderType(shaderTypeName(shader))))
        if (name != "diffusetex") written.push_back(name);
    return written;
}

void requireFileCoordinates(const Scene& scene) {
    if (scene.origin != glm::dvec3(0.0))
        throw std::logic_error("a scene loaded with a local origin cannot be written: load it without LoadOptions::localOrigin");
}

std::vector<std::string> shaderNames(const Scene& scene) {
    std::set<std::string> taken;
    for (const Shader& shader : scene.shaders) taken.insert(shader.name);
    std::vector<std::string> names;
    int next = 1;
    for (const Shader& shader : scene.shaders) {
        if (!shader.name.empty()) {
            names.push_back(shader.name);
            continue;
        }
        std::string name;
        do name = "unnamed shader " + std::to_string(next++);
        while (taken.count(name));
        taken.insert(name);
        names.push_back(name);
    }
    return names;
}

Scene asWritten(Scene scene) {
    const std::vector<std::string> names = shaderNames(scene);
    for (std::size_t i = 0; i < names.size(); ++i) {
        scene.shaders[i].name = names[i];
        scene.shaders[i].undefined = false;
    }
    return scene;
}

bool isValidUtf8(const std::string& text) {
    std::size_t i = 0;
    const std::size_t n = text.size();
    while (i < n) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        std::size_t length = 0;
        unsigned char lo = 0x80, hi = 0xBF;  // the second byte's range (RFC 3629, table 3-7 of Unicode)
        if (c < 0x80) length = 1;
        else if (c >= 0xC2 && c <= 0xDF) length = 2;
        else if (c == 0xE0) length = 3, lo = 0xA0;
        else if ((c >= 0xE1 && c <= 0xEC) || c == 0xEE || c == 0xEF) length = 3;
        else if (c == 0xED) length = 3, hi = 0x9F;  // no surrogates
        else if (c == 0xF0) length = 4, lo = 0x90;
        else if (c >= 0xF1 && c <= 0xF3) length = 4;
        else if (c == 0xF4) length = 4, hi = 0x8F;
        else return false;
        if (i + length > n) return false;
        for (std::size_t k = 1; k < length; ++k) {
            const unsigned char b = static_cast<unsigned char>(text[i + k]);
            if (b < (k == 1 ? lo : 0x80) || b > (k == 1 ? hi : 0xBF)) return false;
        }
        i += length;
    }
    return true;
}

namespace {

std::string hexEscape(unsigned char byte) {
    static const char digits[] = "0123456789ABCDEF";
    return std::string("\\x") + digits[byte >> 4] + digits[byte & 15];
}

// The length of the valid UTF-8 sequence at text[i], 0 when there is none.
std::size_t utf8SequenceAt(const std::string& text, std::size_t i) {
    for (std::size_t length = 1; length <= 4 && i + length <= text.size(); ++length)
        if (isValidUtf8(text.substr(i, length))) return length;
    return 0;
}

}  // namespace

std::string writableName(const std::string& name, NameFormat format) {
    std::string out;
    out.reserve(name.size());
    for (std::size_t i = 0; i < name.size();) {
        const unsigned char c = static_cast<unsigned char>(name[i]);
        if (format == NameFormat::Xml) {
            const bool allowed = c >= 0x20 || c == '\t' || c == '\n' || c == '\r';
            out += allowed ? std::string(1, name[i]) : hexEscape(c);
            ++i;
            continue;
        }
        const std::size_t length = utf8SequenceAt(name, i);
        if (length == 0) {
            out += hexEscape(c);
            ++i;
        } else {
            out.append(name, i, length);
            i += length;
        }
    }
    return out;
}

namespace {

// A name as an error message shows it: a backslash doubled, and what JSON or XML cannot hold as
// \xNN, so that two names an escape makes equal still read differently (and a NUL does not end
// the message).
std::string shownName(const std::string& name) {
    std::string doubled;
    for (char c : name) doubled += c == '\\' ? std::string("\\\\") : std::string(1, c);
    return writableName(writableName(doubled, NameFormat::Json), NameFormat::Xml);
}

// Rewrites the names of one kind, refusing a rewrite that makes two of them equal.
template <class Items, class NameOf>
void rewriteNames(Items& items, const char* kind, NameFormat format, std::size_t* changed, NameOf nameOf) {
    std::map<std::string, std::string> written;  // written name -> original
    for (auto& item : items) {
        std::string& name = nameOf(item);
        const std::string original = name;
        name = writableName(original, format);
        if (name != original) ++*changed;
        if (name.empty()) continue;
        const auto [at, inserted] = written.emplace(name, original);
        if (!inserted && at->second != original)
            throw std::runtime_error(std::string(kind) + " names '" + shownName(at->second) + "' and '" + shownName(original) +
                                     "' would both be written as '" + name + "'; rename one of them");
    }
}

}  // namespace

Scene withWritableNames(Scene scene, NameFormat format, std::size_t* changed) {
    std::size_t count = 0;
    rewriteNames(scene.cameras, "camera", format, &count, [](Camera& c) -> std::string& { return c.name; });
    rewriteNames(scene.shaders, "shader", format, &count, [](Shader& s) -> std::string& { return s.name; });
    rewriteNames(scene.textures, "texture", format, &count, [](Texture& t) -> std::string& { return t.name; });
    rewriteNames(scene.prototypes, "prototype", format, &count, [](Shape& p) -> std::string& { return p.name; });
    // Shape, instance and shape-light names are labels nothing refers to: equal ones are allowed.
    auto rewrite = [&](std::string& name) {
        std::string written = writableName(name, format);
        if (written != name) ++count;
        name = std::move(written);
    };
    for (Shape& shape : scene.shapes) rewrite(shape.name);
    for (Instance& instance : scene.instances) rewrite(instance.name);
    for (Emitter& emitter : scene.emitters) {
        rewrite(emitter.name);
        rewrite(emitter.shape.name);
    }
    if (changed) *changed = count;
    return scene;
}

std::string_view shapeTypeName(ShapeType type) {
    switch (type) {
        case ShapeType::Sphere: return "sphere";
        case ShapeType::Box: return "box";
        case ShapeType::Triangle: return "triangle";
        case ShapeType::Mesh: return "mesh";
    }
    return "sphere";
}

std::string_view cameraTypeName(CameraType type) { return type == CameraType::Orthographic ? "orthographic" : "perspective"; }

std::string_view axisName(int axis) { return axis == 0 ? "X" : axis == 1 ? "Y" : "Z"; }

std::vector<bool> namedPrototypes(const Scene& scene) {
    std::vector<bool> named(scene.prototypes.size(), true);
    for (const Instance& instance : scene.instances)
        if (instance.ownPrototype) named.at(static_cast<std::size_t>(instance.prototype)) = false;
    return named;
}

std::vector<ShapeSlot> shapeOrder(const Scene& scene) {
    std::vector<bool> seen(scene.meshes.size(), false);
    const auto use = [&](const Shape& shape) {
        if (shape.type == ShapeType::Mesh && shape.mesh >= 0) seen.at(static_cast<std::size_t>(shape.mesh)) = true;
    };
    const std::vector<bool> named = namedPrototypes(scene);
    for (std::size_t i = 0; i < scene.prototypes.size(); ++i)
        if (named[i]) use(scene.prototypes[i]);
    for (const Emitter& emitter : scene.emitters)
        if (emitter.prototype < 0) use(emitter.shape);
    // The mesh an entry would load first, or -1 when it loads none.
    const auto firstUse = [&](const Shape& shape) {
        return shape.type == ShapeType::Mesh && shape.mesh >= 0 && !seen.at(static_cast<std::size_t>(shape.mesh)) ? shape.mesh : -1;
    };
    const auto plainMesh = [&](std::size_t i) { return firstUse(scene.shapes[i]); };
    const auto instanceMesh = [&](std::size_t j) {
        const Instance& instance = scene.instances[j];
        return instance.ownPrototype ? firstUse(scene.prototypes.at(static_cast<std::size_t>(instance.prototype))) : -1;
    };
    std::vector<ShapeSlot> order;
    std::size_t i = 0, j = 0;
    while (i < scene.shapes.size() || j < scene.instances.size()) {
        const int p = i < scene.shapes.size() ? plainMesh(i) : -2;
        const int q = j < scene.instances.size() ? instanceMesh(j) : -2;
        // An entry that loads no new mesh goes first; of two that do, the one whose mesh comes first.
        const bool takePlain = p == -1 || (p >= 0 && (q == -2 || (q >= 0 && p < q)));
        if (takePlain) {
            if (p >= 0) seen[static_cast<std::size_t>(p)] = true;
            order.push_back({false, i++});
        } else {
            if (q >= 0) seen[static_cast<std::size_t>(q)] = true;
            order.push_back({true, j++});
        }
    }
    return order;
}

void forEachLightInFileOrder(const Scene& scene, const std::function<void(const Light&)>& light,
                             const std::function<void(const Emitter&)>& emitter) {
    std::size_t e = 0;
    for (std::size_t l = 0; l <= scene.lights.size(); ++l) {
        for (; e < scene.emitters.size() && static_cast<std::size_t>(scene.emitters[e].lightsBefore) <= l; ++e)
            emitter(scene.emitters[e]);
        if (l < scene.lights.size()) light(scene.lights[l]);
    }
}

}  // namespace vkrt::writing
