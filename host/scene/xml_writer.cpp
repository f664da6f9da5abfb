#include "xml_writer.h"

#include <sstream>
#include <vector>

#include <pugixml.hpp>

#include "scene_writing.h"

namespace vkrt {

namespace {

class XmlSceneWriter {
public:
    XmlSceneWriter(const Scene& scene, std::filesystem::path outputDirectory)
        : scene_(scene), directory_(std::move(outputDirectory)), shaderNames_(writing::shaderNames(scene)),
          named_(writing::namedPrototypes(scene)) {}

    void write(pugi::xml_node root) const {
        writeParameters(root.append_child("sceneParameters"));
        for (const Camera& c : scene_.cameras) writeCamera(root.append_child("camera"), c);
        writing::forEachLightInFileOrder(
            scene_, [&](const Light& l) { writeLight(root.append_child("light"), l); },
            [&](const Emitter& e) { writeEmitter(root.append_child("light"), e); });
        for (const Texture& t : scene_.textures) {
            pugi::xml_node node = root.append_child("texture");
            node.append_attribute("name") = t.name.c_str();
            node.append_attribute("type") = "image";
            text(node, "sourcefile", path(t.path));
        }
        for (std::size_t i = 0; i < scene_.shaders.size(); ++i) writeShader(root.append_child("shader"), scene_.shaders[i], shaderNames_[i]);
        for (std::size_t i = 0; i < scene_.prototypes.size(); ++i)
            if (named_[i]) writeShape(root.append_child("instance"), scene_.prototypes[i]);
        for (const writing::ShapeSlot& slot : writing::shapeOrder(scene_)) {
            if (slot.instance) writeInstance(root.append_child("shape"), scene_.instances[slot.index]);
            else writeShape(root.append_child("shape"), scene_.shapes[slot.index]);
        }
    }

private:
    std::string path(const std::string& p) const { return writing::relativePath(p, directory_); }

    static pugi::xml_node text(pugi::xml_node parent, const char* name, const std::string& value) {
        pugi::xml_node child = parent.append_child(name);
        child.text() = value.c_str();
        return child;
    }
    static void vec3(pugi::xml_node parent, const char* name, const glm::vec3& v) { text(parent, name, writing::vec3Text(v)); }
    static void scalar(pugi::xml_node parent, const char* name, float v) { text(parent, name, writing::floatText(v)); }

    void writeParameters(pugi::xml_node node) const {
        vec3(node, "bgColor", scene_.background);
        if (!scene_.envMapPrefix.empty()) text(node, "envMapPrefix", path(scene_.envMapPrefix));
        if (!scene_.envMapVertCross.empty()) text(node, "envMapVertCross", path(scene_.envMapVertCross));
        if (scene_.defaultCamera != 0) text(node, "camera", scene_.cameras.at(static_cast<std::size_t>(scene_.defaultCamera)).name);
    }

    static void writeCamera(pugi::xml_node node, const Camera& c) {
        if (!c.name.empty()) node.append_attribute("name") = c.name.c_str();
        node.append_attribute("type") = std::string(writing::cameraTypeName(c.type)).c_str();
        vec3(node, "position", c.position);
        vec3(node, "viewDir", c.gaze);  // conditioned already: loading it back changes nothing
        scalar(node, "focalLength", c.focalLength);
        scalar(node, "imagePlaneWidth", c.imagePlaneWidth);
        if (c.focusDistance != 0.0f) scalar(node, "focusDistance", c.focusDistance);
        if (c.aperture != 0.0f) scalar(node, "aperture", c.aperture);
        if (c.up) vec3(node, "up", *c.up);
    }

    void writeLight(pugi::xml_node node, const Light& l) const {
        node.append_attribute("type") = l.type == LightType::Area ? "area" : "point";
        vec3(node, "position", l.position);
        vec3(node, "intensity", l.intensity);
        if (l.type != LightType::Area) return;
        vec3(node, "normal", l.normal);
        scalar(node, "width", l.width);
        scalar(node, "length", l.length);
    }

    void writeEmitter(pugi::xml_node node, const Emitter& e) const {
        node.append_attribute("type") = "shape";
        vec3(node, "intensity", e.radiance);
        pugi::xml_node shape = node.append_child("shape");
        if (e.prototype >= 0) {
            if (!e.shape.name.empty()) shape.append_attribute("name") = e.shape.name.c_str();
            shape.append_attribute("type") = "instance";
            shape.append_attribute("id") = scene_.prototypes.at(static_cast<std::size_t>(e.prototype)).name.c_str();
            if (e.shape.shader >= 0) reference(shape, e.shape.shader);
        } else {
            writeShape(shape, e.shape);
        }
        if (!e.steps.empty()) writeTransform(shape.append_child("transform"), e.steps);
    }

    void colour(pugi::xml_node shader, const char* name, const glm::vec3& c, int texture) const {
        pugi::xml_node node = text(shader, name, writing::vec3Text(c));
        if (texture >= 0) node.append_attribute("tex") = scene_.textures.at(static_cast<std::size_t>(texture)).name.c_str();
    }

    void writeShader(pugi::xml_node node, const Shader& sh, const std::string& name) const {
        node.append_attribute("name") = name.c_str();
        node.append_attribute("type") = writing::shaderTypeName(sh).c_str();
        for (std::string_view p : writing::writtenParameters(sh)) {
            const std::string key(p);
            if (p == "diffuse") colour(node, "diffuse", sh.diffuse, sh.diffuseTexture);
            else if (p == "specular") colour(node, "specular", sh.specular, sh.specularTexture);
            else if (p == "phongExp") scalar(node, "phongExp", sh.phongExp);
            else if (p == "mirrorCoef") scalar(node, "mirrorCoef", sh.mirrorCoef);
            else if (p == "roughness") scalar(node, "roughness", sh.roughness);
            else if (p == "refractiveIndex") scalar(node, "refractiveIndex", sh.refractiveIndex);
            else if (p == "attenuationCoef") vec3(node, "attenuationCoef", sh.attenuation);
            else if (p == "emission") vec3(node, "emission", sh.emission);
        }
    }

    void reference(pugi::xml_node shape, int shader) const {
        shape.append_child("shader").append_attribute("ref") = shaderNames_.at(static_cast<std::size_t>(shader)).c_str();
    }

    void writeShape(pugi::xml_node node, const Shape& sh) const {
        if (!sh.name.empty()) node.append_attribute("name") = sh.name.c_str();
        node.append_attribute("type") = std::string(writing::shapeTypeName(sh.type)).c_str();
        if (sh.shader >= 0) reference(node, sh.shader);
        switch (sh.type) {
            case ShapeType::Sphere:
                vec3(node, "center", sh.center);
                scalar(node, "radius", sh.radius);
                break;
            case ShapeType::Box:
                vec3(node, "minPt", sh.minPt);
                vec3(node, "maxPt", sh.maxPt);
                break;
            case ShapeType::Triangle:
                vec3(node, "v0", sh.v0);
                vec3(node, "v1", sh.v1);
                vec3(node, "v2", sh.v2);
                break;
            case ShapeType::Mesh: text(node, "file", path(scene_.meshes.at(static_cast<std::size_t>(sh.mesh)).path)); break;
        }
    }

    static void writeTransform(pugi::xml_node node, const std::vector<TransformStep>& steps) {
        for (const TransformStep& step : steps) {
            switch (step.kind) {
                case TransformKind::Translate: vec3(node, "translate", step.amount); break;
                case TransformKind::Scale: vec3(node, "scale", step.amount); break;
                case TransformKind::Rotate: {
                    pugi::xml_node rotate = text(node, "rotate", writing::floatText(step.amount.x));
                    rotate.append_attribute("axis") = std::string(writing::axisName(step.axis)).c_str();
                    break;
                }
            }
        }
    }

    // A transformed plain shape is written back as one; an instance of a named prototype as
    // type="instance" id=...
    void writeInstance(pugi::xml_node node, const Instance& placed) const {
        if (placed.ownPrototype) {
            writeShape(node, scene_.prototypes.at(static_cast<std::size_t>(placed.prototype)));
        } else {
            if (!placed.name.empty()) node.append_attribute("name") = placed.name.c_str();
            node.append_attribute("type") = "instance";
            node.append_attribute("id") = scene_.prototypes.at(static_cast<std::size_t>(placed.prototype)).name.c_str();
            if (placed.shaderOverride >= 0) reference(node, placed.shaderOverride);
        }
        if (placed.ownPrototype || !placed.steps.empty()) writeTransform(node.append_child("transform"), placed.steps);
        if (placed.moving) writeTransform(node.append_child("transformEnd"), placed.stepsEnd);
    }

    const Scene& scene_;
    std::filesystem::path directory_;
    std::vector<std::string> shaderNames_;
    std::vector<bool> named_;
};

}  // namespace

std::string xmlSceneText(const Scene& scene, const std::filesystem::path& outputDirectory) {
    writing::requireFileCoordinates(scene);
    pugi::xml_document document;
    pugi::xml_node declaration = document.append_child(pugi::node_declaration);
    declaration.append_attribute("version") = "1.0";
    declaration.append_attribute("encoding") = "UTF-8";
    XmlSceneWriter(scene, outputDirectory).write(document.append_child("scene"));
    std::ostringstream out;
    document.save(out, "  ", pugi::format_default, pugi::encoding_utf8);
    return out.str();
}

}  // namespace vkrt
