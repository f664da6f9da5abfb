// What every part of the JSON loader needs: the source (for positions), the warning sink, a view
// of one value with its path, and the checks and value readers that report through them, in the
// XML side's conventions (parse_context.h, value_parsing.h). Sections cited are docs/JSON_FORMAT.md's.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "diagnostics.h"
#include "json_source.h"
#include "scene.h"

namespace vkrt {

// One value of the document and its path ("scene.shape[3].radius"). An absent member keeps the
// path it would have had, and `value` is null.
struct JsonNode {
    const Json* value = nullptr;
    std::string path;

    explicit operator bool() const { return value != nullptr; }
    const Json& operator*() const { return *value; }
    const Json* operator->() const { return value; }
};

struct JsonContext {
    const JsonSource& source;
    Diagnostics& diagnostics;
    bool strict = false;                   // LoadOptions::strict: every warning becomes a SceneError
    std::filesystem::path sceneDirectory;  // mesh, texture and env-map paths are relative to it
    bool localOrigin = false;              // LoadOptions::localOrigin (local_origin.h)
    glm::dvec3 origin{0.0};                // set once the default camera is known

    // An issue at the value's first byte, or at its key (for a key that is the problem), or at
    // any byte offset (element `path`; "json" when the path is the document's root).
    Issue issueAtOffset(std::ptrdiff_t offset, const std::string& path, std::string problem, std::string value = {}) const;
    Issue issueAt(const JsonNode& node, std::string problem, std::string value = {}) const;
    Issue issueAtKey(const JsonNode& node, std::string problem, std::string value = {}) const;
    // `hint`: Issue::hint.
    void warn(const JsonNode& node, std::string problem, std::string value = {}, std::string hint = {}) const;
    void warnAtKey(const JsonNode& node, std::string problem, std::string value = {}, std::string hint = {}) const;
    [[noreturn]] void fail(const JsonNode& node, std::string problem, std::string value = {}) const;
    void warn(Issue issue) const;
    SourceLocation locationOf(const JsonNode& node) const;
};

// --- structure ---
JsonNode member(const JsonNode& object, std::string_view key);
// The member `name` written plain or with the xml2json underscore ("name" / "_name"); the plain
// spelling wins, with a warning at the other when both are given (§2).
JsonNode attributeMember(const JsonContext& context, const JsonNode& object, std::string_view name);
// Warns about every key not in `allowed` ("unknown key, ignored", at the key, with the allowed key
// it is probably a typo of: name_suggestion.h). Attribute-like
// names are listed once, plain: "name" allows "_name" too.
void checkKeys(const JsonContext& context, const JsonNode& object, const std::vector<std::string_view>& allowed,
               const std::vector<std::string_view>& attributes = {});
void requireObject(const JsonContext& context, const JsonNode& node);
JsonNode requireMember(const JsonContext& context, const JsonNode& object, std::string_view key);
JsonNode requireAttribute(const JsonContext& context, const JsonNode& object, std::string_view name);
// The objects of a list key: an array of objects, or one object on its own (the G0 files write
// `"camera": {...}`, xml2json's form of a single element). Absent: none.
std::vector<JsonNode> objectsOf(const JsonContext& context, const JsonNode& list);

// --- values (errors as XML's: wrong type, missing component, non-finite or beyond float) ---
// "an array", "a string", ... for messages.
const char* typeName(const Json& value);
// The value as a message quotes it: a string's text, a number as written, else compact JSON.
std::string quoted(const JsonContext& context, const JsonNode& node);
std::string readString(const JsonContext& context, const JsonNode& node);  // a non-empty string
std::string readText(const JsonContext& context, const JsonNode& node);    // any string (names)
// A JSON number, or a string holding one (accepted with a warning: the G0 files, §2).
// `exact`, when given, receives the number in double before its rounding to float.
float readScalar(const JsonContext& context, const JsonNode& node, double* exact = nullptr);
// "x y z" (read like XML element text, number_text.h) or [x, y, z].
glm::vec3 readVec3(const JsonContext& context, const JsonNode& node, glm::dvec3* exact = nullptr);
// A point: in world space (`world`) under LoadOptions::localOrigin, read in double and stored
// relative to context.origin (local_origin.h); otherwise readVec3.
glm::vec3 readPosition(const JsonContext& context, const JsonNode& node, bool world);

}  // namespace vkrt
