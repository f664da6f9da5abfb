#include "scene_test_files.h"

#include <algorithm>
#include <fstream>

#include <unistd.h>

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

void SceneFiles::SetUp() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir = std::filesystem::temp_directory_path() /
          ("vkrt_scene_" + std::to_string(getpid()) + "_" + info->test_suite_name() + "_" + info->name());
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    scenePath = (dir / "scene.xml").string();
}

void SceneFiles::TearDown() { std::filesystem::remove_all(dir); }

std::string SceneFiles::write(const std::string& name, const std::string& text) const {
    const std::filesystem::path path = dir / name;
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
}

Scene SceneFiles::load(const std::string& xml, Diagnostics& diagnostics, bool strict) const {
    write("scene.xml", xml);
    LoadOptions options;
    options.strict = strict;
    return loadScene(scenePath, options, diagnostics);
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
        const std::string tail = " '" + value + "'";
        EXPECT_TRUE(message.size() >= tail.size() && message.compare(message.size() - tail.size(), tail.size(), tail) == 0)
            << message;
    }
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

}  // namespace vkrt::test
