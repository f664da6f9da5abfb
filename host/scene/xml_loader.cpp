#include "xml_loader.h"

#include <algorithm>
#include <map>
#include <optional>
#include <string_view>
#include <tuple>
#include <vector>

#include <pugixml.hpp>

#include "camera_parsing.h"
#include "environment_loading.h"
#include "light_parsing.h"
#include "local_origin.h"
#include "missing_shaders.h"
#include "name_suggestion.h"
#include "parse_context.h"
#include "scene_rules.h"
#include "shader_parsing.h"
#include "shape_parsing.h"
#include "texture_loading.h"
#include "transform_parsing.h"
#include "value_parsing.h"
#include "xml_source.h"

namespace vkrt {

namespace {

bool isElement(pugi::xml_node node, std::string_view name) {
    return node.type() == pugi::node_element && name == node.name();
}

// What <scene> may hold; anything else is warned about with the closest of these.
const std::vector<std::string_view> kSceneChildren = {"camera", "light", "shader", "texture", "instance", "shape",
                                                      "sceneParameters"};

// Two passes over the document (docs/XML_FORMAT.md §7.2), so that child and element order never matter:
//   1. definitions by name: textures, shaders (top-level and inline in shapes), prototypes;
//   2. everything placed in the scene: cameras (and which one is the default: its eye is the local
//      origin, local_origin.h), lights, then shapes and instances, then scene parameters.
class SceneBuilder {
public:
    SceneBuilder(const ParseContext& context, Scene& scene, NegZRule negZ, bool environmentTexels)
        : context_(context), scene_(scene), meshes_(scene.meshes), negZ_(negZ), environmentTexels_(environmentTexels) {}

    void build(pugi::xml_node root) {
        checkAttributes(context_, root, {"bgColor", "envmapPrefix", "envMapPrefix"});
        for (pugi::xml_node node : root.children("texture")) defineTexture(node);
        for (pugi::xml_node node : root.children()) {
            if (isElement(node, "shader")) defineShader(node, /*inlineInShape=*/false);
            if (isElement(node, "shape") || isElement(node, "instance")) defineInlineShaders(node);
            if (isElement(node, "light"))  // a shape light's shape (vkrt's XML addition, §3.4)
                for (pugi::xml_node shape : node.children("shape")) defineInlineShaders(shape);
        }
        for (pugi::xml_node node : root.children("instance")) definePrototype(node);

        placeCameras(root);

        pugi::xml_node parameters;
        for (pugi::xml_node node : root.children()) {
            if (node.type() != pugi::node_element) continue;
            const std::string_view name = node.name();
            if (name == "light") {
                if (std::string_view(node.attribute("type").value()) == "shape") placeShapeLight(node);
                else if (auto light = parseLight(context_, node)) scene_.lights.push_back(*light);
            } else if (name == "sceneParameters") {
                if (parameters) context_.warn(node, "repeated inside <scene>, the first one is used");
                else parameters = node;
            } else if (std::find(kSceneChildren.begin(), kSceneChildren.end(), name) == kSceneChildren.end()) {
                context_.warn(node, "unknown element inside <scene>, ignored", "", didYouMean(name, kSceneChildren));
            }
        }
        // Shapes after every light, as JSON reads them: a shape light's mesh then takes the same
        // place in Scene::meshes (the order of first use) whichever format the scene comes from.
        for (pugi::xml_node node : root.children("shape")) placeShape(node);
        if (scene_.cameras.empty()) context_.fail(root, "the scene has no <camera>");
        readSceneParameters(root, parameters);
    }

private:
    // Cameras first, so that the default one is known before anything is placed: under
    // LoadOptions::localOrigin its eye is the origin every world position is measured from.
    void placeCameras(pugi::xml_node root) {
        std::vector<glm::dvec3> eyes;
        std::vector<pugi::xml_node> nodes;
        for (pugi::xml_node node : root.children("camera")) {
            glm::dvec3 eye;
            scene_.cameras.push_back(parseCamera(context_, node, &eye));
            eyes.push_back(eye);
            nodes.push_back(node);
        }
        if (const pugi::xml_node camera = root.child("sceneParameters").child("camera")) selectCamera(camera);
        if (!context_.localOrigin || eyes.empty()) return;
        context_.origin = scene_.origin = eyes[static_cast<std::size_t>(scene_.defaultCamera)];
        for (std::size_t i = 0; i < eyes.size(); ++i) {
            const std::optional<glm::vec3> local = rules::localPosition(eyes[i], scene_.origin);
            if (!local) context_.fail(nodes[i].child("position"), rules::kBeyondFloatLocally, elementText(nodes[i].child("position")));
            scene_.cameras[i].position = *local;
        }
    }

    void defineTexture(pugi::xml_node node) {
        checkAttributes(context_, node, {"type"});
        checkChildren(context_, node, {"sourcefile"});
        const std::string name = requireAttribute(context_, node, "name");
        const std::string_view type = node.attribute("type").value();
        if (!type.empty() && type != "image")
            context_.warn(node, "unknown texture type, read as an image file", std::string(type), didYouMean(type, {"image"}));
        const pugi::xml_node source = requireChild(context_, node, "sourcefile");
        const std::string relative = trimmed(elementText(source));
        if (relative.empty()) context_.fail(source, "empty texture file name");
        const std::string path = rules::resolveScenePath(context_.sceneDirectory, relative);
        const TextureDefinition defined =
            vkrt::defineTexture(scene_, textures_, name, path, {context_.source.path(), context_.source.lineOf(node)});
        if (defined.outcome == TextureDefinition::Duplicate) context_.warn(node, defined.problem, name);
        if (defined.outcome == TextureDefinition::Missing) context_.warn(source, defined.problem, path);
    }

    // Inline definitions (a full <shader name type> inside a shape) are registered globally like
    // top-level ones (LIB-2012, LIB-boost) and may be nameless, used only by their shape.
    void defineShader(pugi::xml_node node, bool inlineInShape) {
        const std::string name = node.attribute("name").value();
        if (name.empty() && !inlineInShape) context_.fail(node, "missing required attribute name");
        Shader shader = parseShader(context_, node, textures_);
        if (!name.empty()) {
            if (const auto found = shaderByName_.find(name); found != shaderByName_.end()) {
                const int kept = found->second;
                context_.warn(node, "duplicate shader name, the first definition (line " +
                                        std::to_string(scene_.shaders[kept].where.line) + ") is kept", name);
                if (inlineInShape) inlineShaders_[node.internal_object()] = kept;
                return;
            }
            shaderByName_[name] = static_cast<int>(scene_.shaders.size());
        }
        if (inlineInShape) inlineShaders_[node.internal_object()] = static_cast<int>(scene_.shaders.size());
        scene_.shaders.push_back(std::move(shader));
    }

    void defineInlineShaders(pugi::xml_node shape) {
        for (pugi::xml_node child : shape.children("shader"))
            if (child.attribute("type")) defineShader(child, /*inlineInShape=*/true);
    }

    // The shader a shape (or prototype, or instance) names: -1 when it has no <shader> child.
    int shaderOf(pugi::xml_node shape) {
        const pugi::xml_node reference = shape.child("shader");
        if (!reference) return -1;
        if (reference.attribute("type")) return inlineShaders_.at(reference.internal_object());
        checkAttributes(context_, reference, {"ref"});
        const std::string name = requireAttribute(context_, reference, "ref");
        if (const auto found = shaderByName_.find(name); found != shaderByName_.end()) return found->second;
        context_.warn(reference, rules::kUnresolvedShader, name);
        return missingShaders_.placeholderFor(scene_, name, {context_.source.path(), context_.source.lineOf(reference)});
    }

    // Geometry with its shader, as a loose shape or a prototype; `world`: placed as it stands
    // (parseGeometry).
    Shape parseShape(pugi::xml_node node, ShapeType type, bool world, bool shaderRequired = true) {
        std::vector<std::string_view> allowed = rules::geometryKeys(type);
        allowed.push_back("shader");
        if (isElement(node, "shape")) {
            allowed.push_back("transform");
            allowed.push_back("transformEnd");
        }
        checkChildren(context_, node, allowed);
        Shape shape;
        shape.name = node.attribute("name").value();
        shape.type = type;
        shape.where = {context_.source.path(), context_.source.lineOf(node)};
        parseGeometry(context_, node, shape, meshes_, world);
        shape.shader = shaderOf(node);
        if (shape.shader < 0 && shaderRequired) context_.fail(node, "missing required element <shader>", shape.name);
        return shape;
    }

    void definePrototype(pugi::xml_node node) {
        checkAttributes(context_, node, {"type"});
        const std::string name = requireAttribute(context_, node, "name");
        const std::string typeName = requireAttribute(context_, node, "type");
        const std::optional<ShapeType> type = rules::shapeType(typeName);
        const int next = static_cast<int>(scene_.prototypes.size());
        switch (rules::definePrototypeName(prototypeByName_, name, type, next)) {
            case rules::PrototypeDefinition::Duplicate: return context_.warn(node, rules::kDuplicatePrototype, name);
            case rules::PrototypeDefinition::UnknownType: return context_.warn(node, rules::kUnknownPrototype, typeName, didYouMean(typeName, rules::shapeTypeNames(false)));
            case rules::PrototypeDefinition::Added: scene_.prototypes.push_back(parseShape(node, *type, /*world=*/false));
        }
    }

    void placeShape(pugi::xml_node node) {
        const std::string typeName = requireAttribute(context_, node, "type");
        const std::string name = node.attribute("name").value();
        if (typeName == "instance") {
            checkAttributes(context_, node, {"type", "id"});
            checkChildren(context_, node, {"shader", "transform", "transformEnd"});
            const std::optional<int> prototype = prototypeOf(node);
            if (!prototype) return;
            Instance instance;
            instance.name = name;
            instance.prototype = *prototype;
            instance.shaderOverride = shaderOf(node);
            rules::placeInstance(instance, placementOf(node));
            instance.where = {context_.source.path(), context_.source.lineOf(node)};
            scene_.instances.push_back(instance);
            return;
        }
        checkAttributes(context_, node, {"type"});
        const std::optional<ShapeType> type = rules::shapeType(typeName);
        if (!type) {
            context_.warn(node, rules::kUnknownShapeType, typeName, didYouMean(typeName, rules::shapeTypeNames(true)));
            return;
        }
        const bool placed = node.child("transform") || node.child("transformEnd");
        Shape shape = parseShape(node, *type, /*world=*/!placed);
        if (placed) {
            const rules::Placement placement = placementOf(node);
            rules::addPlainShape(scene_, std::move(shape), &placement);
        } else {
            rules::addPlainShape(scene_, std::move(shape), nullptr);
        }
    }

    // A shape's <transform> and, for motion blur, its <transformEnd> (the pose at the end of the
    // motion; docs/XML_FORMAT.md §3.9).
    rules::Placement placementOf(pugi::xml_node node) {
        rules::Placement placement = parseTransform(context_, node.child("transform"));
        if (const pugi::xml_node end = node.child("transformEnd")) {
            rules::Placement last = parseTransform(context_, end);
            if (const std::string p = rules::motionProblem(placement.objectToWorld, last.objectToWorld); !p.empty())
                context_.fail(end, p);
            placement.moving = true;
            placement.stepsEnd = std::move(last.steps);
            placement.objectToWorldEnd = last.objectToWorld;
        }
        return placement;
    }

    // The prototype an instance's `id` names; nullopt (after a warning) for a skipped one.
    std::optional<int> prototypeOf(pugi::xml_node instance) {
        const std::string id = requireAttribute(context_, instance, "id");
        const auto found = prototypeByName_.find(id);
        if (found == prototypeByName_.end()) context_.fail(instance, "unresolved instance id", id);
        if (found->second < 0) {
            context_.warn(instance, "instance of a skipped prototype, skipped", id);
            return std::nullopt;
        }
        return found->second;
    }

    // <light type="shape"><intensity>c</intensity><shape ...>any shape, an instance with its
    // <transform> included</shape></light>: the JSON shape light in XML (vkrt's addition,
    // docs/XML_FORMAT.md §3.4, so that vkrt convert keeps it). The shape's shader is optional.
    void placeShapeLight(pugi::xml_node node) {
        checkAttributes(context_, node, {"type"});
        checkChildren(context_, node, {"intensity", "shape"});
        Emitter emitter;
        emitter.radiance = parseColour(context_, requireChild(context_, node, "intensity"));
        emitter.where = {context_.source.path(), context_.source.lineOf(node)};
        const pugi::xml_node shape = requireChild(context_, node, "shape");
        const std::string typeName = requireAttribute(context_, shape, "type");
        if (typeName == "instance") {
            checkAttributes(context_, shape, {"type", "id"});
            checkChildren(context_, shape, {"shader", "transform"});
            const std::optional<int> prototype = prototypeOf(shape);
            if (!prototype) return;
            emitter.prototype = *prototype;
            emitter.shape.name = shape.attribute("name").value();
            emitter.shape.shader = shaderOf(shape);
        } else {
            checkAttributes(context_, shape, {"type"});
            const std::optional<ShapeType> type = rules::shapeType(typeName);
            if (!type) {
                context_.warn(shape, rules::kUnknownShapeType, typeName, didYouMean(typeName, rules::shapeTypeNames(true)));
                return;
            }
            emitter.shape = parseShape(shape, *type, /*world=*/!shape.child("transform"), /*shaderRequired=*/false);
            if (const pugi::xml_node end = shape.child("transformEnd"))
                context_.warn(end, "ignored: shape lights do not move (motion blur moves instances only)");
        }
        emitter.name = emitter.shape.name;
        // A plain shape without a transform stands in world space (identity); an instance, or a
        // shape with a transform, is placed by it.
        if (const pugi::xml_node transform = shape.child("transform"); transform || emitter.prototype >= 0) {
            rules::Placement placement = parseTransform(context_, transform);
            emitter.steps = std::move(placement.steps);
            emitter.objectToWorld = placement.objectToWorld;
        }
        emitter.lightsBefore = static_cast<int>(scene_.lights.size());
        scene_.emitters.push_back(emitter);
    }

    // Background and environment map: <sceneParameters> children win over the root attributes
    // (docs/XML_FORMAT.md §7.3). The environment map's files resolve against the scene file and are
    // loaded (environment_loading.h): the cube faces when a prefix is given, else the vertical cross.
    void readSceneParameters(pugi::xml_node root, pugi::xml_node parameters) {
        if (const pugi::xml_attribute bg = root.attribute("bgColor")) {
            scene_.background = parseVec3Text(context_, root, "scene bgColor", bg.value());
            if (const std::string p = rules::negativeColourProblem(scene_.background); !p.empty()) {
                Issue issue = context_.issueAt(root, p, bg.value());
                issue.element = "scene bgColor";
                context_.warn(std::move(issue));
            }
        }
        pugi::xml_node prefixNode = root, crossNode;
        std::string prefix, cross;
        for (const char* spelling : {"envmapPrefix", "envMapPrefix"})
            if (const pugi::xml_attribute a = root.attribute(spelling)) prefix = trimmed(a.value());

        if (parameters) {
            checkAttributes(context_, parameters, {});
            checkChildren(context_, parameters, {"bgColor", "envMapPrefix", "envmapPrefix", "envMapVertCross", "camera"});
            if (const pugi::xml_node bg = parameters.child("bgColor")) scene_.background = parseColour(context_, bg);
            for (const char* spelling : {"envmapPrefix", "envMapPrefix"}) {
                if (const pugi::xml_node e = parameters.child(spelling)) {
                    prefixNode = e;
                    prefix = trimmed(elementText(e));
                }
            }
            if (const pugi::xml_node e = parameters.child("envMapVertCross")) {
                crossNode = e;
                cross = trimmed(elementText(e));
            }
        }
        // The cube faces' prefix and the vertical-cross image are separate fields, as in JSON.
        for (const auto& [text, field] : {std::pair{&prefix, &scene_.envMapPrefix}, std::pair{&cross, &scene_.envMapVertCross}})
            if (!text->empty()) *field = rules::resolveScenePath(context_.sceneDirectory, *text);
        EnvironmentProblem problem;
        std::optional<Environment> environment;
        pugi::xml_node named = prefixNode;
        if (!prefix.empty()) {
            if (!cross.empty()) context_.warn(crossNode, kIgnoredVertCross, cross);
            if (!environmentTexels_) return;
            environment = loadCubeFaceEnvironment(scene_.envMapPrefix, negZ_, problem);
        } else if (!cross.empty()) {
            named = crossNode;
            if (!environmentTexels_) return;
            environment = loadVerticalCrossEnvironment(scene_.envMapVertCross, problem);
        } else {
            return;
        }
        if (!environment) context_.fail(named, problem.problem, problem.value);
        scene_.environment = std::move(*environment);
        scene_.environment.where = {context_.source.path(), context_.source.lineOf(named)};
    }

    void selectCamera(pugi::xml_node camera) {
        const std::string name = trimmed(elementText(camera));
        const std::optional<int> index = rules::cameraByName(scene_, name);
        if (!index) context_.fail(camera, rules::kUnknownCameraName, name);
        scene_.defaultCamera = *index;
    }

    ParseContext context_;  // a copy: the origin is set once the cameras are read
    Scene& scene_;
    MeshLibrary meshes_;
    TextureTable textures_;
    std::map<std::string, int> shaderByName_;
    MissingShaders missingShaders_;
    std::map<const void*, int> inlineShaders_;   // inline <shader> node -> index into Scene::shaders
    std::map<std::string, int> prototypeByName_; // -1: a skipped (unknown-type) prototype
    NegZRule negZ_;
    bool environmentTexels_;  // LoadOptions::environmentTexels
};

}  // namespace

Scene loadXmlScene(const std::string& path, const std::string& text, const LoadOptions& options, Diagnostics& diagnostics) {
    const XmlSource source(path, text);
    const ParseContext context{source, diagnostics, options.strict, std::filesystem::path(path).parent_path(),
                               options.localOrigin};
    const pugi::xml_node root = source.root();
    if (std::string_view(root.name()) != "scene") context.fail(root, "the root element must be <scene>", root.name());

    Scene scene;
    scene.path = path;
    SceneBuilder(context, scene, options.environmentNegZ, options.environmentTexels).build(root);
    return scene;
}

}  // namespace vkrt
