// A parsed JSON scene file that can say where any value sits. nlohmann::json keeps no positions,
// so the document is built through its SAX interface from an input that counts the bytes the
// parser has consumed; each value's byte span (and its key's offset) is recorded under its path,
// "scene.shape[3].radius", and offsets become line:column through LineIndex.
#pragma once

#include <cstddef>
#include <string>
#include <unordered_map>
#include <vector>

#include <nlohmann/json.hpp>

#include "source_text.h"

namespace vkrt {

// Object members keep the order of the file (a repeated key keeps its first value).
using Json = nlohmann::ordered_json;

// The path of a member or an element, as messages print them: "scene", "scene.shape[3]".
std::string memberPath(const std::string& object, const std::string& key);
std::string elementPath(const std::string& array, std::size_t index);

class JsonSource {
public:
    struct Span {
        std::ptrdiff_t key = -1;   // offset of the member's key (its opening quote), -1 for elements
        std::ptrdiff_t begin = 0;  // the value's first byte
        std::ptrdiff_t end = 0;    // one past its last byte
    };
    struct RepeatedKey {
        std::string path;          // the member's path (the first value is the one kept)
        std::ptrdiff_t key = 0;    // offset of the repeated key
    };

    // `text` is the file's content (readSourceFile). Malformed JSON is a SceneError at the line
    // and column nlohmann reports (the last byte it read), element "json"; a number beyond double
    // range (nlohmann refuses it) names the value's path like any number beyond float range.
    JsonSource(std::string path, const std::string& text);

    const std::string& path() const { return path_; }
    const Json& root() const { return root_; }
    // The span of the value at `path` (nullptr when nothing was recorded there).
    const Span* spanOf(const std::string& path) const;
    const std::vector<RepeatedKey>& repeatedKeys() const { return repeated_; }
    int lineOf(std::ptrdiff_t offset) const { return lines_.lineOf(offset); }
    int columnOf(std::ptrdiff_t offset) const { return lines_.columnOf(offset); }
    // The value's text as written in the file (numbers keep their spelling: "1e39", "0.50").
    std::string textOf(const std::string& path) const;

private:
    std::string path_;
    std::string text_;
    LineIndex lines_;
    Json root_;
    std::unordered_map<std::string, Span> spans_;
    std::vector<RepeatedKey> repeated_;
};

}  // namespace vkrt
