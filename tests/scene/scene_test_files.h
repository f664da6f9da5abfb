// A scratch directory per test for small XML/JSON/OBJ/image files, and helpers to load them.
#pragma once

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "diagnostics.h"
#include "scene.h"
#include "scene_loader.h"

namespace vkrt::test {

// `<scene>` holding one default camera followed by `body` (one line each for the declaration,
// the root and the camera, so `body` starts on line 4).
std::string sceneWith(const std::string& body, const std::string& rootAttributes = "");

// 1-based line of the first occurrence of `needle` in `text` (computed independently of the
// loader, from the text the test wrote).
int lineOf(const std::string& text, const std::string& needle);
// 1-based byte column of the first occurrence of `needle` in `text`.
int columnOf(const std::string& text, const std::string& needle);

// A JSON scene: {"scene": {"camera": [one camera], <members>}} with one member per line, so the
// first of `members` starts on line 4. `members` is a comma-separated list of "key": value.
std::string jsonWith(const std::string& members);

// Every index in the scene points at something that exists (both formats' loads end with this).
void expectConsistent(const Scene& scene);

class SceneFiles : public ::testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;

    // Writes `text` to dir/name and returns the path.
    std::string write(const std::string& name, const std::string& text) const;
    // Writes an environment map's six faces dir/<prefix>posX.png ... negZ.png (2 x 2 grey PNGs):
    // scenes that name one load it (environment_loading.h).
    void writeCubeFaces(const std::string& prefix) const;
    Scene load(const std::string& xml, Diagnostics& diagnostics, bool strict = false) const;
    // The same for JSON text, written to dir/scene.json (jsonPath).
    Scene loadJson(const std::string& json, Diagnostics& diagnostics, bool strict = false) const;
    Scene loadJsonClean(const std::string& json) const;
    Issue jsonErrorOf(const std::string& json, bool strict = false) const;
    // The issue is about jsonPath at line:column, names the JSON path `element` and quotes
    // `value`; its message reads "<file>:<line>:<column>: <element>: <problem> '<value>'".
    void expectJsonIssue(const Issue& issue, int line, int column, const std::string& element, const std::string& value) const;
    // ... at the first occurrence of `needle` in `json`.
    void expectJsonIssueAt(const Issue& issue, const std::string& json, const std::string& needle, const std::string& element,
                           const std::string& value) const;
    // Loads and expects no warnings at all.
    Scene loadClean(const std::string& xml) const;
    // Loads expecting a SceneError; returns its issue (a failed expectation when none is thrown).
    Issue errorOf(const std::string& xml, bool strict = false) const;

    // The issue is about scenePath at `line`, names `element` and quotes `value`, and its one-line
    // message reads "<file>:<line>: <element>: <problem> '<value>'" (then "; <hint>" when it has one).
    void expectIssue(const Issue& issue, int line, const std::string& element, const std::string& value) const;

    std::filesystem::path dir;
    std::string scenePath;  // where load()/errorOf() write the XML
    std::string jsonPath;   // where loadJson()/jsonErrorOf() write the JSON
};

}  // namespace vkrt::test
