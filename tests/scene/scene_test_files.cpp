#include "scene_test_files.h"

#include <algorithm>
#include <fstream>

#include <unistd.h>

#include <OpenImageIO/imageio.h>

namespace vkrt::test {

std::string sceneWith(const std::string& body, const std::string& rootAttributes) {
    return "<?xml version=\"1.0\" encoding=\"UTF-8\" ?>\n<scene" + rootAttributes +
           ">\n"
           "<camera name=\"main\" type=\"perspective\"><position>0 0 0</position><viewDir>0 0 -1</viewDir></camera>\n" +
           body + "\n</scene>\n";
}

int lineOf(const std::string& text, const std::string& needle) {
    const std::size_t at = text.find(needle);
    EXPECT_NE(at, std::string::npos) << "test bug: '" << needle << "' not in the XML";
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

int columnOf(const std::string& text, const std::string& needle) {
    const std::size_t at = text.find(needle);
    EXPECT_NE(at, std::string::npos) << "test bug: '" << needle << "' not in the text";
    const std::size_t lineStart = text.rfind('\n', at == 0 ? 0 : at - 1);
    return static_cast<int>(lineStart == std::string::npos || at == 0 ? at + 1 : at - lineStart);
}

std::string jsonWith(const std::string& members) {
    return "{\n\"scene\": {\n\"camera\": [{\"position\": \"0 0 0\", \"viewDir\": \"0 0 -1\", \"_name\": \"main\"}]" +
           (members.empty() ? std::string() : ",\n" + members) + "\n}\n}\n";
}

void expectConsistent(const Scene& scene) {
    ASSERT_FALSE(scene.cameras.empty());
    EXPECT_GE(scene.defaultCamera, 0);
    EXPECT_LT(scene.defaultCamera, static_cast<int>(scene.cameras.size()));
    const int shaders = static_cast<int>(scene.shaders.size());
    const auto checkShape = [&](const Shape& shape, bool shaderRequired) {
        if (shaderRequired) EXPECT_GE(shape.shader, 0) << shape.name;
        EXPECT_GE(shape.shader, -1) << shape.name;
        EXPECT_LT(shape.shader, shaders) << shape.name;
        if (shape.type == ShapeType::Mesh) {
            ASSERT_GE(shape.mesh, 0);
            ASSERT_LT(shape.mesh, static_cast<int>(scene.meshes.size()));
        }
    };
    for (const Shape& shape : scene.shapes) checkShape(shape, true);
    for (const Shape& shape : scene.prototypes) checkShape(shape, true);
    for (const Instance& instance : scene.instances) {
        EXPECT_GE(instance.prototype, 0);
        EXPECT_LT(instance.prototype, static_cast<int>(scene.prototypes.size()));
        EXPECT_GE(instance.shaderOverride, -1);
        EXPECT_LT(instance.shaderOverride, shaders);
    }
    for (const Emitter& emitter : scene.emitters) {
        EXPECT_GE(emitter.prototype, -1);
        EXPECT_LT(emitter.prototype, static_cast<int>(scene.prototypes.size()));
        if (emitter.prototype < 0) checkShape(emitter.shape, false);
    }
    int lightsBefore = 0;  // the emitters' places among the lights: in range, in file order
    for (const Emitter& emitter : scene.emitters) {
        EXPECT_GE(emitter.lightsBefore, lightsBefore);
        EXPECT_LE(emitter.lightsBefore, static_cast<int>(scene.lights.size()));
        lightsBefore = emitter.lightsBefore;
    }
    for (const Shader& shader : scene.shaders) {
        EXPECT_GE(shader.diffuseTexture, kNoTexture);
        EXPECT_LT(shader.diffuseTexture, static_cast<int>(scene.textures.size()));
        EXPECT_LT(shader.specularTexture, static_cast<int>(scene.textures.size()));
    }
    for (const Texture& texture : scene.textures)
        EXPECT_EQ(texture.rgba8.size(), static_cast<std::size_t>(texture.width) * texture.height);
    for (const Mesh& mesh : scene.meshes) {
        EXPECT_EQ(mesh.normals.size(), mesh.positions.size());
        EXPECT_FALSE(mesh.triangles.empty());
    }
}

void SceneFiles::SetUp() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir = std::filesystem::temp_directory_path() /
          ("vkrt_scene_" + std::to_string(getpid()) + "_" + info->test_suite_name() + "_" + info->name());
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    scenePath = (dir / "scene.xml").string();
    jsonPath = (dir / "scene.json").string();
}

void SceneFiles::TearDown() { std::filesystem::remove_all(dir); }

std::string SceneFiles::write(const std::string& name, const std::string& text) const {
    const std::filesystem::path path = dir / name;
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
}

void SceneFiles::writeCubeFaces(const std::string& prefix) const {
    for (const char* face : {"posX", "negX", "posY", "negY", "posZ", "negZ"}) {
        const std::filesystem::path path = dir / (prefix + face + ".png");
        std::filesystem::create_directories(path.parent_path());
        const unsigned char grey[2 * 2 * 3] = {90, 90, 90, 90, 90, 90, 90, 90, 90, 90, 90, 90};
        auto out = OIIO::ImageOutput::create(path.string());
        ASSERT_TRUE(out && out->open(path.string(), OIIO::ImageSpec(2, 2, 3, OIIO::TypeDesc::UINT8))) << path;
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, grey)) << path;
        out->close();
    }
}

Scene SceneFiles::load(const std::string& xml, Diagnostics& diagnostics, bool strict) const {
    write("scene.xml", xml);
    LoadOptions options;
    options.strict = strict;
    return loadScene(scenePath, options, diagnostics);
}

Scene SceneFiles::loadJson(const std::string& json, Diagnostics& diagnostics, bool strict) const {
    write("scene.json", json);
    LoadOptions options;
    options.strict = strict;
    return loadScene(jsonPath, options, diagnostics);
}

Scene SceneFiles::loadJsonClean(const std::string& json) const {
    Diagnostics diagnostics;
    Scene scene = loadJson(json, diagnostics);
    EXPECT_TRUE(diagnostics.warnings().empty()) << "first warning: " << diagnostics.messages().front();
    return scene;
}

Issue SceneFiles::jsonErrorOf(const std::string& json, bool strict) const {
    Diagnostics diagnostics;
    try {
        loadJson(json, diagnostics, strict);
    } catch (const SceneError& error) {
        return error.issue();
    }
    ADD_FAILURE() << "expected a SceneError";
    return {};
}

void SceneFiles::expectJsonIssue(const Issue& issue, int line, int column, const std::string& element,
                                 const std::string& value) const {
    EXPECT_EQ(issue.file, jsonPath);
    EXPECT_EQ(issue.line, line);
    EXPECT_EQ(issue.column, column);
    EXPECT_EQ(issue.element, element);
    EXPECT_EQ(issue.value, value);
    const std::string message = issue.message();
    const std::string head = jsonPath + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + element + ": ";
    EXPECT_EQ(message.rfind(head, 0), 0u) << message;
    if (!value.empty()) {
        const std::string tail = " '" + value + "'" + (issue.hint.empty() ? "" : "; " + issue.hint);
        EXPECT_TRUE(message.size() >= tail.size() && message.compare(message.size() - tail.size(), tail.size(), tail) == 0)
            << message;
    }
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

void SceneFiles::expectJsonIssueAt(const Issue& issue, const std::string& json, const std::string& needle,
                                   const std::string& element, const std::string& value) const {
    expectJsonIssue(issue, lineOf(json, needle), columnOf(json, needle), element, value);
}

Scene SceneFiles::loadClean(const std::string& xml) const {
    Diagnostics diagnostics;
    Scene scene = load(xml, diagnostics);
    EXPECT_TRUE(diagnostics.warnings().empty()) << "first warning: " << diagnostics.messages().front();
    return scene;
}

Issue SceneFiles::errorOf(const std::string& xml, bool strict) const {
    Diagnostics diagnostics;
    try {
        load(xml, diagnostics, strict);
    } catch (const SceneError& error) {
        return error.issue();
    }
    ADD_FAILURE() << "expected a SceneError";
    return {};
}

void SceneFiles::expectIssue(const Issue& issue, int line, const std::string& element, const std::string& value) const {
    EXPECT_EQ(issue.file, scenePath);
    EXPECT_EQ(issue.line, line);
    EXPECT_EQ(issue.element, element);
    EXPECT_EQ(issue.value, value);
    const std::string message = issue.message();
    const std::string head = scenePath + ":" + std::to_string(line) + ": " + element + ": ";
    EXPECT_EQ(message.rfind(head, 0), 0u) << message;
    if (!value.empty()) {
        const std::string tail = " '" + value + "'" + (issue.hint.empty() ? "" : "; " + issue.hint);
        EXPECT_TRUE(message.size() >= tail.size() && message.compare(message.size() - tail.size(), tail.size(), tail) == 0)
            << message;
    }
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

}  // namespace vkrt::test
