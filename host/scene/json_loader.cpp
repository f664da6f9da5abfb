#include "json_loader.h"

#include <algorithm>
#include <map>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "camera_basis.h"
#include "environment_loading.h"
#include "json_context.h"
#include "json_source.h"
#include "local_origin.h"
#include "mesh_library.h"
#include "missing_shaders.h"
#include "name_suggestion.h"
#include "scene_rules.h"
#include "texture_loading.h"

// Sections (§) are docs/JSON_FORMAT.md's.
namespace vkrt {

namespace {

using Keys = std::vector<std::string_view>;

// Shader keys: XML's parameters except the 2012 <diffusetex>, which JSON files never had.
const Keys& jsonShaderParameters() {
    static const Keys keys = [] {
        Keys all;
        for (std::string_view name : rules::shaderParameters())
            if (name != "diffusetex") all.push_back(name);
        return all;
    }();
    return keys;
}

bool contains(const Keys& keys, std::string_view key) { return std::find(keys.begin(), keys.end(), key) != keys.end(); }

// What a shape object is for: its shader is required (loose shapes; prototypes, where a
// dangling reference is only a warning, §3.5) or optional (an emitter's, replaced by its
// radiance); prototypes take no transform.
enum class ShapeRole { Loose, Prototype, Emitter };

// Two passes, as XML (§1), so that key and array order never matter:
//   1. definitions by name: textures, shaders, prototypes (`instance[]`);
//   2. cameras, lights (shape lights included), shapes and instances, background.
class JsonSceneBuilder {
public:
    JsonSceneBuilder(const JsonContext& context, Scene& scene, NegZRule negZ, bool environmentTexels)
        : context_(context), scene_(scene), meshes_(scene.meshes), negZ_(negZ), environmentTexels_(environmentTexels) {}

    void build(const JsonNode& root) {
        requireObject(context_, root);
        for (const JsonSource::RepeatedKey& repeated : context_.source.repeatedKeys())
            context_.warn(context_.issueAtOffset(repeated.key, repeated.path, "repeated key, the first value is used"));
        // J26: the document's "scene" member, or the document itself (§1).
        JsonNode scene = root;
        if (JsonNode wrapped = member(root, "scene")) {
            checkKeys(context_, root, {"scene"});
            requireObject(context_, wrapped);
            scene = wrapped;
        }
        checkKeys(context_, scene,
                  {"camera", "light", "shader", "shape", "texture", "instance", "sceneParameters", "_bgColor", "bgColor"});

        for (const JsonNode& node : objectsOf(context_, member(scene, "texture"))) defineTexture(node);
        for (const JsonNode& node : objectsOf(context_, member(scene, "shader"))) defineShader(node);
        for (const JsonNode& node : objectsOf(context_, member(scene, "instance"))) definePrototype(node);

        placeCameras(scene);
        for (const JsonNode& node : objectsOf(context_, member(scene, "light"))) placeLight(node);
        for (const JsonNode& node : objectsOf(context_, member(scene, "shape"))) placeShape(node);
        if (scene_.cameras.empty()) context_.fail(scene, "the scene has no camera");
        readBackground(scene);
    }

private:
    // --- pass 1 ---
    void defineTexture(const JsonNode& node) {
        checkKeys(context_, node, {"sourcefile"}, {"name", "type"});
        const std::string name = readString(context_, requireAttribute(context_, node, "name"));
        if (const JsonNode type = attributeMember(context_, node, "type")) {
            const std::string typeText = readText(context_, type);
            if (typeText != "image")
                context_.warn(type, "unknown texture type, read as an image file", typeText, didYouMean(typeText, {"image"}));
        }
        const JsonNode source = requireMember(context_, node, "sourcefile");
        const std::string relative = readString(context_, source);
        const std::string path = rules::resolveScenePath(context_.sceneDirectory, relative);
        const TextureDefinition defined = vkrt::defineTexture(scene_, textures_, name, path, context_.locationOf(node));
        if (defined.outcome == TextureDefinition::Duplicate) context_.warn(node, defined.problem, name);
        if (defined.outcome == TextureDefinition::Missing) context_.warn(source, defined.problem, path);
    }

    void defineShader(const JsonNode& node) {
        checkKeys(context_, node, jsonShaderParameters(), {"name", "type"});
        const JsonNode nameNode = attributeMember(context_, node, "name");
        if (!nameNode) {
            // sd20200409_mirroredScene.json's `"_name=": "green1"`: nothing can refer to it, and
            // the shapes that meant it get the placeholder (with their own warnings).
            context_.warn(node, "a shader without _name (or name) cannot be referred to, skipped");
            return;
        }
        const std::string name = readString(context_, nameNode);
        const JsonNode typeNode = requireAttribute(context_, node, "type");
        const std::string typeText = readString(context_, typeNode);
        const std::optional<rules::ShaderTypeName> known = rules::shaderType(typeText);
        if (!known) context_.warn(typeNode, rules::kUnknownShaderType, typeText, didYouMean(typeText, rules::shaderTypeNames()));
        const rules::ShaderTypeName type = known.value_or(rules::ShaderTypeName{});

        Shader shader;
        shader.name = name;
        shader.type = type.type;
        shader.diffuseBounce = type.diffuseBounce;
        shader.where = context_.locationOf(node);
        // As XML: an unknown type's parameters are covered by its one warning; a known type's
        // parameter it does not read is a warning each (§3.3).
        const Keys used = rules::shaderParametersUsedBy(type);
        if (known)
            for (const auto& item : node->items())
                if (contains(jsonShaderParameters(), item.key()) && !contains(used, item.key()))
                    context_.warnAtKey(member(node, item.key()), rules::unusedParameterProblem(type));
        auto parameter = [&](std::string_view key) { return contains(used, key) ? member(node, key) : JsonNode{}; };

        if (const JsonNode e = parameter("diffuse")) {
            shader.diffuse = readColour(e, shader.diffuseTexture);
        } else if (contains(used, "diffuse")) {
            shader.diffuse = glm::vec3(rules::kMissingDiffuseGrey);
            if (known) context_.warn(node, "no diffuse colour, using grey 0.5", name);
        }
        if (const JsonNode e = parameter("specular")) shader.specular = readColour(e, shader.specularTexture);
        if (const JsonNode e = parameter("phongExp")) shader.phongExp = readChecked(e, rules::nonNegativeProblem);
        if (const JsonNode e = parameter("mirrorCoef")) {
            shader.mirrorCoef = readScalar(context_, e);
            if (const std::string p = rules::mirrorCoefProblem(shader.mirrorCoef); !p.empty()) context_.warn(e, p, quoted(context_, e));
        }
        if (const JsonNode e = parameter("roughness")) shader.roughness = readChecked(e, rules::nonNegativeProblem);
        if (const JsonNode e = parameter("refractiveIndex")) shader.refractiveIndex = readChecked(e, rules::refractiveIndexProblem);
        if (const JsonNode e = parameter("attenuationCoef")) {
            shader.attenuation = readVec3(context_, e);
            if (const std::string p = rules::attenuationProblem(shader.attenuation); !p.empty())
                context_.fail(e, p, quoted(context_, e));
        }
        if (type.emitter) {
            shader.diffuse = glm::vec3(0.0f);  // an emitter reflects nothing (shader_emitters.h)
            if (const JsonNode e = parameter("emission")) shader.emission = readColourValue(e);
        }
        rules::resolveLegacyShaderType(shader);

        if (const auto found = shaderByName_.find(name); found != shaderByName_.end()) {
            context_.warn(node, "duplicate shader name, the first definition (line " +
                                    std::to_string(scene_.shaders[found->second].where.line) + ") is kept", name);
            return;
        }
        shaderByName_[name] = static_cast<int>(scene_.shaders.size());
        scene_.shaders.push_back(std::move(shader));
    }

    // A colour: a vec3, or {"tex": T, "data": c} (G2), or {"_tex": T, "__text": c} (the first
    // conversion); an object without a colour is white (J26), so its texture shows as it is (§3.3).
    glm::vec3 readColour(const JsonNode& node, int& texture) {
        if (!node->is_object()) return readColourValue(node);
        checkKeys(context_, node, {"data", "__text"}, {"tex"});
        const JsonNode data = member(node, "data");
        const JsonNode text = member(node, "__text");
        if (data && text) context_.warnAtKey(text, "both data and __text given, data is used");
        if (const JsonNode tex = attributeMember(context_, node, "tex")) {
            const std::string name = readString(context_, tex);
            const auto found = textures_.find(name);
            if (found == textures_.end()) context_.fail(tex, "unresolved texture reference", name);
            texture = found->second;
        }
        const JsonNode colour = data ? data : text;
        return colour ? readColourValue(colour) : glm::vec3(1.0f);
    }

    // A colour vector, with a warning for a negative component (rules::negativeColourProblem).
    glm::vec3 readColourValue(const JsonNode& node) {
        const glm::vec3 colour = readVec3(context_, node);
        if (const std::string p = rules::negativeColourProblem(colour); !p.empty()) context_.warn(node, p, quoted(context_, node));
        return colour;
    }

    float readChecked(const JsonNode& node, std::string (*rule)(float)) {
        const float value = readScalar(context_, node);
        if (const std::string p = rule(value); !p.empty()) context_.fail(node, p, quoted(context_, node));
        return value;
    }

    void definePrototype(const JsonNode& node) {
        const std::string name = readString(context_, requireAttribute(context_, node, "name"));
        const JsonNode typeNode = requireAttribute(context_, node, "type");
        const std::string typeName = readString(context_, typeNode);
        const std::optional<ShapeType> type = rules::shapeType(typeName);
        const int next = static_cast<int>(scene_.prototypes.size());
        switch (rules::definePrototypeName(prototypeByName_, name, type, next)) {
            case rules::PrototypeDefinition::Duplicate: return context_.warn(node, rules::kDuplicatePrototype, name);
            case rules::PrototypeDefinition::UnknownType: return context_.warn(typeNode, rules::kUnknownPrototype, typeName,
                                                                            didYouMean(typeName, rules::shapeTypeNames(false)));
            case rules::PrototypeDefinition::Added: scene_.prototypes.push_back(parseShape(node, *type, ShapeRole::Prototype));
        }
    }

    // --- shaders named by shapes ---
    // The index `{"_ref": name}` names; a grey placeholder (after a warning) when it names nothing.
    int shaderOf(const JsonNode& reference, ShapeRole role) {
        requireObject(context_, reference);
        checkKeys(context_, reference, {}, {"ref"});
        const JsonNode nameNode = requireAttribute(context_, reference, "ref");
        const std::string name = readString(context_, nameNode);
        if (const auto found = shaderByName_.find(name); found != shaderByName_.end()) return found->second;
        // The corpus's prototypes name shaders that do not exist while every instance names its
        // own (§3.5), so a prototype's warning says so; an instance that would render with the
        // placeholder is an error (placeInstance).
        if (role == ShapeRole::Prototype)
            context_.warn(nameNode, "unresolved shader reference on a prototype, each of its instances must name a shader", name);
        else
            context_.warn(nameNode, rules::kUnresolvedShader, name);
        return missingShaders_.placeholderFor(scene_, name, context_.locationOf(nameNode));
    }

    // --- geometry ---
    Shape parseShape(const JsonNode& node, ShapeType type, ShapeRole role) {
        Keys allowed = rules::geometryKeys(type);
        allowed.push_back("shader");
        if (role != ShapeRole::Prototype) {
            allowed.push_back("xform");
            allowed.push_back("transform");
        }
        if (role == ShapeRole::Loose) allowed.push_back("xformEnd");
        checkKeys(context_, node, allowed, {"name", "type"});
        Shape shape;
        if (const JsonNode name = attributeMember(context_, node, "name")) shape.name = readText(context_, name);
        shape.type = type;
        shape.where = context_.locationOf(node);
        // Placed as it stands (no prototype, no transform): its points are world positions.
        // An emitter's xformEnd is refused (a warning: shape lights do not move) and places nothing.
        const bool world = role == ShapeRole::Loose ? !placed(node)
                                                    : role == ShapeRole::Emitter && !member(node, "xform") && !member(node, "transform");
        parseGeometry(node, shape, world);
        const JsonNode reference = member(node, "shader");
        if (reference) {
            shape.shader = shaderOf(reference, role);
        } else if (role != ShapeRole::Emitter) {
            context_.fail(node, "missing required key shader", shape.name);
        } else {
            shape.shader = -1;
        }
        return shape;
    }

    void parseGeometry(const JsonNode& node, Shape& shape, bool world) {
        switch (shape.type) {
            case ShapeType::Sphere: {
                shape.center = readPosition(context_, requireMember(context_, node, "center"), world);
                shape.radius = readChecked(requireMember(context_, node, "radius"), rules::radiusProblem);
                break;
            }
            case ShapeType::Box: {
                const JsonNode minPt = requireMember(context_, node, "minPt");
                const JsonNode maxPt = requireMember(context_, node, "maxPt");
                shape.minPt = readPosition(context_, minPt, world);
                shape.maxPt = readPosition(context_, maxPt, world);
                if (const std::string p = rules::orderBoxCorners(shape.minPt, shape.maxPt); !p.empty())
                    context_.warn(minPt, p, quoted(context_, minPt) + " > " + quoted(context_, maxPt));
                break;
            }
            case ShapeType::Triangle: {
                shape.v0 = readPosition(context_, requireMember(context_, node, "v0"), world);
                shape.v1 = readPosition(context_, requireMember(context_, node, "v1"), world);
                shape.v2 = readPosition(context_, requireMember(context_, node, "v2"), world);
                if (rules::isDegenerateTriangle(shape.v0, shape.v1, shape.v2)) context_.warn(node, rules::kDegenerateTriangle, shape.name);
                break;
            }
            case ShapeType::Mesh: {
                const JsonNode file = requireMember(context_, node, "file");
                const std::string path = rules::resolveScenePath(context_.sceneDirectory, readString(context_, file));
                try {
                    shape.mesh = meshes_.meshFor(path);
                } catch (const std::runtime_error& error) {
                    context_.fail(file, error.what(), path);
                }
                break;
            }
        }
    }

    // --- transforms (§5) ---
    // No transform: no steps, the identity (moved to the local origin under localOrigin).
    rules::Placement transformOf(const JsonNode& node) {
        const JsonNode xform = member(node, "xform");
        const JsonNode object = member(node, "transform");
        if (xform && object) context_.warnAtKey(object, "ignored, the shape's xform is used");
        const JsonNode& used = xform ? xform : object;
        rules::Placement placement;
        std::vector<glm::dvec3> exactTranslations;  // one per step, read by translate steps
        if (used) placement.steps = xform ? parseXform(xform, exactTranslations) : parseTransformObject(object, exactTranslations);
        placement.objectToWorld = context_.localOrigin
                                      ? rules::placeRelativeTo(placement.steps, exactTranslations, context_.origin)
                                      : rules::composeTransform(placement.steps);
        const std::string problem = used ? rules::composedTransformProblem(placement.objectToWorld) : "";
        if (!problem.empty()) context_.fail(used, problem);
        return placement;
    }

    // Whether a loose shape is placed by a transform (else its points are world positions).
    static bool placed(const JsonNode& node) {
        return member(node, "xform") || member(node, "transform") || member(node, "xformEnd");
    }

    // transformOf, and for motion blur the shape's xformEnd (the pose at the end of the motion,
    // an ordered array like xform; docs/JSON_FORMAT.md §5).
    rules::Placement movingTransformOf(const JsonNode& node) {
        rules::Placement placement = transformOf(node);
        const JsonNode end = member(node, "xformEnd");
        if (!end) return placement;
        std::vector<glm::dvec3> exactTranslations;
        placement.stepsEnd = parseXform(end, exactTranslations);
        placement.objectToWorldEnd = context_.localOrigin
                                         ? rules::placeRelativeTo(placement.stepsEnd, exactTranslations, context_.origin)
                                         : rules::composeTransform(placement.stepsEnd);
        if (const std::string problem = rules::composedTransformProblem(placement.objectToWorldEnd); !problem.empty())
            context_.fail(end, problem);
        if (const std::string problem = rules::motionProblem(placement.objectToWorld, placement.objectToWorldEnd); !problem.empty())
            context_.fail(end, problem);
        placement.moving = true;
        return placement;
    }

    // The ordered array: M = T0 * T1 * ... * Tn-1, the last listed acting first (as XML).
    std::vector<TransformStep> parseXform(const JsonNode& node, std::vector<glm::dvec3>& exactTranslations) {
        if (!node->is_array()) context_.fail(node, std::string("expected an array, found ") + typeName(*node), quoted(context_, node));
        std::vector<TransformStep> steps;
        for (std::size_t i = 0; i < node->size(); ++i) {
            const JsonNode step{&(*node)[i], elementPath(node.path, i)};
            requireObject(context_, step);
            checkKeys(context_, step, {"amount", "axis"}, {"type"});
            const JsonNode typeNode = requireAttribute(context_, step, "type");
            std::string kind = readString(context_, typeNode);
            if (kind == "rotate") {
                context_.warn(typeNode, "read as rotation (the course's parser ignores this spelling)", kind);
                kind = "rotation";
            }
            glm::dvec3 exact(0.0);
            if (kind == "translate") {
                steps.push_back({TransformKind::Translate, readVec3(context_, requireMember(context_, step, "amount"), &exact), 0});
            } else if (kind == "scale") {
                steps.push_back({TransformKind::Scale, readScale(requireMember(context_, step, "amount")), 0});
            } else if (kind == "rotation") {
                const int axis = readAxis(requireMember(context_, step, "axis"));
                const float degrees = readScalar(context_, requireMember(context_, step, "amount"));
                steps.push_back({TransformKind::Rotate, glm::vec3(degrees, 0.0f, 0.0f), axis});
            } else {
                context_.warn(typeNode, "unknown transform type, ignored", kind, didYouMean(kind, {"translate", "scale", "rotation"}));
                continue;
            }
            exactTranslations.push_back(exact);
        }
        return steps;
    }

    // The 2019 object {"translate", "rotate": {..} or [{..}, ..], "scale"}: xml2json kept one key
    // per kind, so the order between kinds is lost. Composed as M = T * R0 * R1 * ... * S, the
    // order of the XML files these came from (threeEggs.xml, metallicDragons.xml; §5).
    std::vector<TransformStep> parseTransformObject(const JsonNode& node, std::vector<glm::dvec3>& exactTranslations) {
        requireObject(context_, node);
        checkKeys(context_, node, {"translate", "rotate", "scale"}, {"name"});
        std::vector<TransformStep> steps;
        int kinds = 0;
        if (const JsonNode e = member(node, "translate")) {
            glm::dvec3 exact;
            steps.push_back({TransformKind::Translate, readVec3(context_, e, &exact), 0});
            exactTranslations.push_back(exact);
            ++kinds;
        }
        if (const JsonNode e = member(node, "rotate")) {
            for (const JsonNode& rotation : objectsOf(context_, e)) {
                checkKeys(context_, rotation, {}, {"axis", "angle"});
                const int axis = readAxis(requireAttribute(context_, rotation, "axis"));
                const float degrees = readScalar(context_, requireAttribute(context_, rotation, "angle"));
                steps.push_back({TransformKind::Rotate, glm::vec3(degrees, 0.0f, 0.0f), axis});
                exactTranslations.emplace_back(0.0);
            }
            ++kinds;
        }
        if (const JsonNode e = member(node, "scale")) {
            steps.push_back({TransformKind::Scale, readScale(e), 0});
            exactTranslations.emplace_back(0.0);
            ++kinds;
        }
        if (kinds > 1)
            context_.warn(node, "a transform object does not keep the order of its operations, composed as translate * rotate * scale");
        return steps;
    }

    glm::vec3 readScale(const JsonNode& node) {
        const glm::vec3 s = readVec3(context_, node);
        if (const std::string p = rules::scaleProblem(s); !p.empty()) context_.fail(node, p, quoted(context_, node));
        return s;
    }

    int readAxis(const JsonNode& node) {
        const std::string name = readString(context_, node);
        const std::optional<int> axis = rules::rotationAxis(name);
        if (!axis) context_.fail(node, rules::kBadRotationAxis, name);
        return *axis;
    }

    // --- pass 2 ---
    // Cameras first, so that the default one is known before anything is placed: under
    // LoadOptions::localOrigin its eye is the origin every world position is measured from.
    void placeCameras(const JsonNode& scene) {
        std::vector<glm::dvec3> eyes;
        std::vector<JsonNode> positions;
        for (const JsonNode& node : objectsOf(context_, member(scene, "camera"))) {
            glm::dvec3 eye;
            scene_.cameras.push_back(parseCamera(node, eye));
            eyes.push_back(eye);
            positions.push_back(member(node, "position"));
        }
        // The camera to render by name, as XML's <sceneParameters><camera> (vkrt's addition, §3.1).
        const JsonNode parameters = member(scene, "sceneParameters");
        if (parameters) requireObject(context_, parameters);
        if (const JsonNode camera = member(parameters, "camera")) {
            const std::string name = readText(context_, camera);  // "" names a nameless camera, as in XML
            const std::optional<int> index = rules::cameraByName(scene_, name);
            if (!index) context_.fail(camera, rules::kUnknownCameraName, name);
            scene_.defaultCamera = *index;
        }
        if (!context_.localOrigin || eyes.empty()) return;
        context_.origin = scene_.origin = eyes[static_cast<std::size_t>(scene_.defaultCamera)];
        for (std::size_t i = 0; i < eyes.size(); ++i) {
            const std::optional<glm::vec3> local = rules::localPosition(eyes[i], scene_.origin);
            if (!local) context_.fail(positions[i], rules::kBeyondFloatLocally, quoted(context_, positions[i]));
            scene_.cameras[i].position = *local;
        }
    }

    Camera parseCamera(const JsonNode& node, glm::dvec3& eye) {
        checkKeys(context_, node, {"position", "viewDir", "lookatPoint", "focalLength", "imagePlaneWidth", "focusDistance", "aperture", "up"},
                  {"name", "type"});
        Camera camera;
        if (const JsonNode name = attributeMember(context_, node, "name")) camera.name = readText(context_, name);
        camera.where = context_.locationOf(node);
        if (const JsonNode type = attributeMember(context_, node, "type")) {
            const std::string typeText = readText(context_, type);
            const std::optional<CameraType> known = rules::cameraType(typeText);
            if (!known) context_.warn(type, rules::kUnknownCameraType, typeText, didYouMean(typeText, rules::cameraTypeNames()));
            camera.type = known.value_or(CameraType::Perspective);
        }
        camera.position = readVec3(context_, requireMember(context_, node, "position"), &eye);
        const JsonNode viewDir = member(node, "viewDir");
        const JsonNode lookatPoint = member(node, "lookatPoint");
        if (!viewDir && !lookatPoint) context_.fail(node, "missing required key viewDir (or lookatPoint)");
        // viewDir is read even when lookatPoint overrides it (J26, §3.1), so garbage in it is reported.
        const glm::vec3 direction = viewDir ? readVec3(context_, viewDir) : glm::vec3(0.0f);
        if (lookatPoint) {
            glm::dvec3 target;
            camera.gaze = readVec3(context_, lookatPoint, &target) - camera.position;
            // Under localOrigin the gaze is the difference of the file's numbers, taken in double.
            if (context_.localOrigin) {
                const std::optional<glm::vec3> gaze = rules::localPosition(target, eye);
                if (!gaze) context_.fail(lookatPoint, rules::kBeyondFloatLocally, quoted(context_, lookatPoint));
                camera.gaze = *gaze;
            }
            if (const std::string p = rules::lookatProblem(camera.gaze); !p.empty()) context_.fail(lookatPoint, p, quoted(context_, lookatPoint));
        } else {
            camera.gaze = direction;
            if (const std::string p = rules::viewDirProblem(camera.gaze); !p.empty()) context_.fail(viewDir, p, quoted(context_, viewDir));
        }
        // vkrt's addition, after the gaze it must not be parallel to (camera_basis.h).
        if (const JsonNode up = member(node, "up")) {
            camera.up = readVec3(context_, up);
            if (const std::string p = upProblem(*camera.up, camera.gaze); !p.empty()) context_.fail(up, p, quoted(context_, up));
        }
        if (const JsonNode f = member(node, "focalLength")) {
            camera.focalLength = readScalar(context_, f);
            if (const std::string p = rules::focalLengthProblem(camera.type, camera.focalLength); !p.empty())
                context_.fail(f, p, quoted(context_, f));
        }
        if (const JsonNode w = member(node, "imagePlaneWidth")) camera.imagePlaneWidth = readChecked(w, rules::imagePlaneWidthProblem);
        const JsonNode focus = member(node, "focusDistance");
        if (focus) camera.focusDistance = readChecked(focus, rules::focusDistanceProblem);
        const JsonNode aperture = member(node, "aperture");
        if (aperture) camera.aperture = readChecked(aperture, rules::apertureProblem);
        if ((camera.focusDistance > 0.0f) != (camera.aperture > 0.0f))
            context_.warn(camera.aperture > 0.0f ? aperture : focus, rules::kLensWithoutBoth, camera.name);
        rules::conditionCamera(camera);
        if (const std::string p = rules::narrowFieldProblem(camera); !p.empty()) context_.warn(node, p, camera.name);
        return camera;
    }

    void placeLight(const JsonNode& node) {
        const JsonNode typeNode = attributeMember(context_, node, "type");
        const std::string type = typeNode ? readString(context_, typeNode) : "point";  // J26's default (§3.2)
        if (type == "shape") return placeShapeLight(node);
        const std::optional<LightType> known = rules::lightType(type);
        if (!known) {
            context_.warn(typeNode, rules::kUnknownLightType, type, didYouMean(type, rules::lightTypeNames()));
            return;
        }
        // A point light's normal, width and length are ignored without a warning, as in XML
        // (sd20210301_solarSystem.json carries them).
        checkKeys(context_, node, {"position", "intensity", "normal", "width", "length"}, {"name", "type"});
        Light light;
        light.type = *known;
        light.where = context_.locationOf(node);
        light.position = readPosition(context_, requireMember(context_, node, "position"), /*world=*/true);
        light.intensity = readColourValue(requireMember(context_, node, "intensity"));
        if (light.type == LightType::Area) {
            const JsonNode normal = requireMember(context_, node, "normal");
            const std::optional<glm::vec3> n = rules::unitNormal(readVec3(context_, normal));
            if (!n) context_.fail(normal, rules::kZeroNormal, quoted(context_, normal));
            light.normal = *n;
            light.width = readChecked(requireMember(context_, node, "width"), rules::lightSizeProblem);
            light.length = readChecked(requireMember(context_, node, "length"), rules::lightSizeProblem);
        }
        scene_.lights.push_back(light);
    }

    // {"_type": "shape", "intensity": c, "shape": {any shape, an instance with its xform included}}
    // (§3.2); an emitter, rendered as emitting geometry (docs/RENDERING.md §4).
    void placeShapeLight(const JsonNode& node) {
        checkKeys(context_, node, {"intensity", "shape"}, {"name", "type"});
        Emitter emitter;
        emitter.radiance = readColourValue(requireMember(context_, node, "intensity"));
        emitter.where = context_.locationOf(node);
        const JsonNode shape = requireMember(context_, node, "shape");
        requireObject(context_, shape);
        const JsonNode typeNode = requireAttribute(context_, shape, "type");
        const std::string typeName = readString(context_, typeNode);
        if (typeName == "instance") {
            checkKeys(context_, shape, {"shader", "xform", "transform"}, {"name", "type", "id"});
            const std::optional<int> prototype = prototypeOf(shape);
            if (!prototype) return;
            emitter.prototype = *prototype;
            if (const JsonNode name = attributeMember(context_, shape, "name")) emitter.shape.name = readText(context_, name);
            if (const JsonNode reference = member(shape, "shader")) emitter.shape.shader = shaderOf(reference, ShapeRole::Emitter);
            else emitter.shape.shader = -1;
        } else {
            const std::optional<ShapeType> type = rules::shapeType(typeName);
            if (!type) {
                context_.warn(typeNode, rules::kUnknownShapeType, typeName, didYouMean(typeName, rules::shapeTypeNames(true)));
                return;
            }
            emitter.shape = parseShape(shape, *type, ShapeRole::Emitter);
        }
        emitter.name = emitter.shape.name;
        // A plain shape without a transform stands in world space (identity); an instance, or a
        // shape with a transform, is placed by it.
        if (emitter.prototype >= 0 || member(shape, "xform") || member(shape, "transform")) {
            rules::Placement placement = transformOf(shape);
            emitter.steps = std::move(placement.steps);
            emitter.objectToWorld = placement.objectToWorld;
        }
        emitter.lightsBefore = static_cast<int>(scene_.lights.size());
        scene_.emitters.push_back(emitter);
    }

    // The prototype an instance's `_id` names; nullopt (after a warning) for a skipped one.
    std::optional<int> prototypeOf(const JsonNode& instance) {
        const JsonNode idNode = requireAttribute(context_, instance, "id");
        const std::string id = readString(context_, idNode);
        const auto found = prototypeByName_.find(id);
        if (found == prototypeByName_.end()) context_.fail(idNode, "unresolved instance id", id);
        if (found->second < 0) {
            context_.warn(idNode, "instance of a skipped prototype, skipped", id);
            return std::nullopt;
        }
        return found->second;
    }

    void placeShape(const JsonNode& node) {
        const JsonNode typeNode = requireAttribute(context_, node, "type");
        const std::string typeName = readString(context_, typeNode);
        if (typeName == "instance") return placeInstance(node);
        const std::optional<ShapeType> type = rules::shapeType(typeName);
        if (!type) {
            context_.warn(typeNode, rules::kUnknownShapeType, typeName, didYouMean(typeName, rules::shapeTypeNames(true)));
            return;
        }
        Shape shape = parseShape(node, *type, ShapeRole::Loose);
        if (placed(node)) {
            const rules::Placement placement = movingTransformOf(node);
            rules::addPlainShape(scene_, std::move(shape), &placement);
        } else {
            rules::addPlainShape(scene_, std::move(shape), nullptr);
        }
    }

    void placeInstance(const JsonNode& node) {
        checkKeys(context_, node, {"shader", "xform", "transform", "xformEnd"}, {"name", "type", "id"});
        const std::optional<int> prototype = prototypeOf(node);
        if (!prototype) return;
        Instance instance;
        if (const JsonNode name = attributeMember(context_, node, "name")) instance.name = readText(context_, name);
        instance.prototype = *prototype;
        if (const JsonNode reference = member(node, "shader")) instance.shaderOverride = shaderOf(reference, ShapeRole::Loose);
        const Shape& shape = scene_.prototypes[static_cast<std::size_t>(instance.prototype)];
        if (instance.shaderOverride < 0 && missingShaders_.isPlaceholder(shape.shader))
            context_.fail(node, "no shader: the prototype's shader reference is unresolved and the instance names none",
                          scene_.shaders[static_cast<std::size_t>(shape.shader)].name);
        rules::placeInstance(instance, movingTransformOf(node));
        instance.where = context_.locationOf(node);
        scene_.instances.push_back(instance);
    }

    // Three spellings of the background, in this precedence (§4): sceneParameters.bgColor (J26),
    // the scene's _bgColor (J22), the scene's bgColor (read by no course parser). Every one given
    // is read; one that disagrees with the one used is a warning. The environment map's files
    // resolve against the scene file and are loaded (environment_loading.h): the cube faces when a
    // prefix is given, else the vertical cross.
    void readBackground(const JsonNode& scene) {
        const JsonNode parameters = member(scene, "sceneParameters");
        if (parameters) {
            requireObject(context_, parameters);
            checkKeys(context_, parameters, {"bgColor", "envMapPrefix", "envMapVertCross", "camera"});
        }
        const JsonNode* used = nullptr;
        const JsonNode spellings[] = {member(parameters, "bgColor"), member(scene, "_bgColor"), member(scene, "bgColor")};
        for (const JsonNode& spelling : spellings) {
            if (!spelling) continue;
            const glm::vec3 colour = readColourValue(spelling);
            if (!used) {
                scene_.background = colour;
                used = &spelling;
            } else if (colour != scene_.background) {
                context_.warn(spelling, "ignored, the background is " + used->path, quoted(context_, spelling));
            }
        }
        const JsonNode prefix = member(parameters, "envMapPrefix");
        const JsonNode cross = member(parameters, "envMapVertCross");
        std::string texts[2];
        for (const auto& [node, text, field] : {std::tuple{&prefix, &texts[0], &scene_.envMapPrefix},
                                                std::tuple{&cross, &texts[1], &scene_.envMapVertCross}}) {
            if (!*node) continue;
            *text = readText(context_, *node);
            if (!text->empty()) *field = rules::resolveScenePath(context_.sceneDirectory, *text);  // empty: J26's default, no map
        }
        EnvironmentProblem problem;
        std::optional<Environment> environment;
        const JsonNode* named = &prefix;
        if (!texts[0].empty()) {
            if (!texts[1].empty()) context_.warn(cross, kIgnoredVertCross, texts[1]);
            if (!environmentTexels_) return;
            environment = loadCubeFaceEnvironment(scene_.envMapPrefix, negZ_, problem);
        } else if (!texts[1].empty()) {
            named = &cross;
            if (!environmentTexels_) return;
            environment = loadVerticalCrossEnvironment(scene_.envMapVertCross, problem);
        } else {
            return;
        }
        if (!environment) context_.fail(*named, problem.problem, problem.value);
        scene_.environment = std::move(*environment);
        scene_.environment.where = context_.locationOf(*named);
    }

    JsonContext context_;  // a copy: the origin is set once the cameras are read
    Scene& scene_;
    MeshLibrary meshes_;
    TextureTable textures_;
    std::map<std::string, int> shaderByName_;
    MissingShaders missingShaders_;
    std::map<std::string, int> prototypeByName_;    // -1: a skipped (unknown-type) prototype
    NegZRule negZ_;
    bool environmentTexels_;  // LoadOptions::environmentTexels
};

}  // namespace

Scene loadJsonScene(const std::string& path, const std::string& text, const LoadOptions& options, Diagnostics& diagnostics) {
    const JsonSource source(path, text);
    const JsonContext context{source, diagnostics, options.strict, std::filesystem::path(path).parent_path(), options.localOrigin};
    Scene scene;
    scene.path = path;
    JsonSceneBuilder(context, scene, options.environmentNegZ, options.environmentTexels).build(JsonNode{&source.root(), ""});
    return scene;
}

}  // namespace vkrt
