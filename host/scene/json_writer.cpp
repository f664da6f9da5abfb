#include "json_writer.h"

#include <charconv>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene_writing.h"

namespace vkrt {

namespace {

using Json = nlohmann::ordered_json;  // keys in the order written, like the course's files

// A JSON number that prints as floatText's decimal (the double nearest a 9-digit decimal prints
// back as that decimal) and loads back as the same float.
Json number(float value) {
    const std::string text = writing::floatText(value);
    double parsed = 0.0;
    std::from_chars(text.data(), text.data() + text.size(), parsed);
    return parsed;
}

Json vec3(const glm::vec3& v) { return writing::vec3Text(v); }

class JsonSceneWriter {
public:
    JsonSceneWriter(const Scene& scene, std::filesystem::path outputDirectory)
        : scene_(scene), directory_(std::move(outputDirectory)), shaderNames_(writing::shaderNames(scene)),
          named_(writing::namedPrototypes(scene)) {}

    Json write() const {
        Json s = Json::object();
        s["camera"] = list(scene_.cameras, [&](const Camera& c) { return camera(c); });
        Json lights = Json::array();
        writing::forEachLightInFileOrder(
            scene_, [&](const Light& l) { lights.push_back(light(l)); }, [&](const Emitter& e) { lights.push_back(emitter(e)); });
        s["light"] = lights;
        if (!scene_.textures.empty())
            s["texture"] = list(scene_.textures, [&](const Texture& t) {
                return Json{{"_name", t.name}, {"_type", "image"}, {"sourcefile", path(t.path)}};
            });
        Json shaders = Json::array();
        for (std::size_t i = 0; i < scene_.shaders.size(); ++i) shaders.push_back(shader(scene_.shaders[i], shaderNames_[i]));
        s["shader"] = shaders;
        Json prototypes = Json::array();
        for (std::size_t i = 0; i < scene_.prototypes.size(); ++i)
            if (named_[i]) prototypes.push_back(shape(scene_.prototypes[i]));
        if (!prototypes.empty()) s["instance"] = prototypes;
        Json shapes = Json::array();
        for (const writing::ShapeSlot& slot : writing::shapeOrder(scene_))
            shapes.push_back(slot.instance ? instance(scene_.instances[slot.index]) : shape(scene_.shapes[slot.index]));
        s["shape"] = shapes;
        s["sceneParameters"] = parameters();
        return Json{{"scene", s}};
    }

private:
    template <typename T, typename F>
    static Json list(const std::vector<T>& items, F each) {
        Json out = Json::array();
        for (const T& item : items) out.push_back(each(item));
        return out;
    }

    std::string path(const std::string& p) const { return writing::relativePath(p, directory_); }

    Json camera(const Camera& c) const {
        Json out = Json::object();
        if (!c.name.empty()) out["_name"] = c.name;
        out["_type"] = writing::cameraTypeName(c.type);
        out["position"] = vec3(c.position);
        out["viewDir"] = vec3(c.gaze);  // conditioned already: loading it back changes nothing
        out["focalLength"] = number(c.focalLength);
        out["imagePlaneWidth"] = number(c.imagePlaneWidth);
        if (c.focusDistance != 0.0f) out["focusDistance"] = number(c.focusDistance);
        if (c.aperture != 0.0f) out["aperture"] = number(c.aperture);
        if (c.up) out["up"] = vec3(*c.up);
        return out;
    }

    Json light(const Light& l) const {
        Json out = Json::object();
        out["_type"] = l.type == LightType::Area ? "area" : "point";
        out["position"] = vec3(l.position);
        out["intensity"] = vec3(l.intensity);
        if (l.type == LightType::Area) {
            out["normal"] = vec3(l.normal);
            out["width"] = number(l.width);
            out["length"] = number(l.length);
        }
        return out;
    }

    Json emitter(const Emitter& e) const {
        Json shapeObject;
        if (e.prototype >= 0) {
            shapeObject = Json::object();
            if (!e.shape.name.empty()) shapeObject["_name"] = e.shape.name;
            shapeObject["_type"] = "instance";
            shapeObject["_id"] = scene_.prototypes.at(static_cast<std::size_t>(e.prototype)).name;
            if (e.shape.shader >= 0) shapeObject["shader"] = reference(e.shape.shader);
        } else {
            shapeObject = shape(e.shape);
        }
        if (!e.steps.empty()) shapeObject["xform"] = xform(e.steps);
        return Json{{"_type", "shape"}, {"intensity", vec3(e.radiance)}, {"shape", shapeObject}};
    }

    Json colour(const glm::vec3& c, int texture) const {
        if (texture < 0) return vec3(c);
        return Json{{"tex", scene_.textures.at(static_cast<std::size_t>(texture)).name}, {"data", vec3(c)}};
    }

    Json shader(const Shader& sh, const std::string& name) const {
        Json out = Json::object();
        out["_name"] = name;
        out["_type"] = writing::shaderTypeName(sh);
        for (std::string_view p : writing::writtenParameters(sh)) {
            const std::string key(p);
            if (p == "diffuse") out[key] = colour(sh.diffuse, sh.diffuseTexture);
            else if (p == "specular") out[key] = colour(sh.specular, sh.specularTexture);
            else if (p == "phongExp") out[key] = number(sh.phongExp);
            else if (p == "mirrorCoef") out[key] = number(sh.mirrorCoef);
            else if (p == "roughness") out[key] = number(sh.roughness);
            else if (p == "refractiveIndex") out[key] = number(sh.refractiveIndex);
            else if (p == "attenuationCoef") out[key] = vec3(sh.attenuation);
            else if (p == "emission") out[key] = vec3(sh.emission);
        }
        return out;
    }

    Json reference(int shader) const { return Json{{"_ref", shaderNames_.at(static_cast<std::size_t>(shader))}}; }

    Json shape(const Shape& sh) const {
        Json out = Json::object();
        if (!sh.name.empty()) out["_name"] = sh.name;
        out["_type"] = writing::shapeTypeName(sh.type);
        if (sh.shader >= 0) out["shader"] = reference(sh.shader);
        switch (sh.type) {
            case ShapeType::Sphere:
                out["center"] = vec3(sh.center);
                out["radius"] = number(sh.radius);
                break;
            case ShapeType::Box:
                out["minPt"] = vec3(sh.minPt);
                out["maxPt"] = vec3(sh.maxPt);
                break;
            case ShapeType::Triangle:
                out["v0"] = vec3(sh.v0);
                out["v1"] = vec3(sh.v1);
                out["v2"] = vec3(sh.v2);
                break;
            case ShapeType::Mesh: out["file"] = path(scene_.meshes.at(static_cast<std::size_t>(sh.mesh)).path); break;
        }
        return out;
    }

    static Json xform(const std::vector<TransformStep>& steps) {
        Json out = Json::array();
        for (const TransformStep& step : steps) {
            switch (step.kind) {
                case TransformKind::Translate: out.push_back({{"type", "translate"}, {"amount", vec3(step.amount)}}); break;
                case TransformKind::Scale: out.push_back({{"type", "scale"}, {"amount", vec3(step.amount)}}); break;
                case TransformKind::Rotate:
                    out.push_back({{"type", "rotation"}, {"amount", number(step.amount.x)}, {"axis", writing::axisName(step.axis)}});
                    break;
            }
        }
        return out;
    }

    // A transformed plain shape is written back as one (its own prototype with an xform); an
    // instance of a named prototype as "_type": "instance".
    Json instance(const Instance& placed) const {
        if (placed.ownPrototype) {
            Json out = shape(scene_.prototypes.at(static_cast<std::size_t>(placed.prototype)));
            out["xform"] = xform(placed.steps);
            if (placed.moving) out["xformEnd"] = xform(placed.stepsEnd);
            return out;
        }
        Json out = Json::object();
        if (!placed.name.empty()) out["_name"] = placed.name;
        out["_type"] = "instance";
        out["_id"] = scene_.prototypes.at(static_cast<std::size_t>(placed.prototype)).name;
        if (placed.shaderOverride >= 0) out["shader"] = reference(placed.shaderOverride);
        if (!placed.steps.empty()) out["xform"] = xform(placed.steps);
        if (placed.moving) out["xformEnd"] = xform(placed.stepsEnd);
        return out;
    }

    Json parameters() const {
        Json out = Json::object();
        out["bgColor"] = vec3(scene_.background);
        if (!scene_.envMapPrefix.empty()) out["envMapPrefix"] = path(scene_.envMapPrefix);
        if (!scene_.envMapVertCross.empty()) out["envMapVertCross"] = path(scene_.envMapVertCross);
        if (scene_.defaultCamera != 0) out["camera"] = scene_.cameras.at(static_cast<std::size_t>(scene_.defaultCamera)).name;
        return out;
    }

    const Scene& scene_;
    std::filesystem::path directory_;
    std::vector<std::string> shaderNames_;
    std::vector<bool> named_;
};

}  // namespace

std::string jsonSceneText(const Scene& scene, const std::filesystem::path& outputDirectory) {
    writing::requireFileCoordinates(scene);
    // A name that is not UTF-8 (XML text can hold one) is written with U+FFFD in its place instead of
    // throwing; the written file then names it differently, and vkrt convert's check says so.
    return JsonSceneWriter(scene, outputDirectory).write().dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace vkrt
