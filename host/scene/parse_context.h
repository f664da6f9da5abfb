// What every element parser needs: the file (for lines), the warning sink, and small checks on an
// element's children and attributes that report through them.
#pragma once

#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <pugixml.hpp>

#include "diagnostics.h"
#include "xml_source.h"

namespace vkrt {

struct ParseContext {
    const XmlSource& source;
    Diagnostics& diagnostics;
    bool strict = false;                  // LoadOptions::strict: every warning becomes a SceneError
    std::filesystem::path sceneDirectory; // `file` and `sourcefile` paths are relative to it
    bool localOrigin = false;             // LoadOptions::localOrigin (local_origin.h)
    glm::dvec3 origin{0.0};               // set once the default camera is known

    // An issue about `node` (its element name and line). `hint`: Issue::hint.
    Issue issueAt(pugi::xml_node node, std::string problem, std::string value = {}) const;
    void warn(pugi::xml_node node, std::string problem, std::string value = {}, std::string hint = {}) const;
    [[noreturn]] void fail(pugi::xml_node node, std::string problem, std::string value = {}) const;
    void warn(Issue issue) const;
};

// All character data of an element (comments inside a value are skipped, not a terminator).
std::string elementText(pugi::xml_node node);

// `text` without leading and trailing whitespace (names and paths written as element text).
std::string trimmed(const std::string& text);

// Warns about element children whose names are not in `allowed` ("unknown element ... ignored",
// with the allowed name it is probably a typo of: name_suggestion.h) and about a repeated child of a name in `allowed` (the first one is used). `repeatable` names
// may appear any number of times.
void checkChildren(const ParseContext& context, pugi::xml_node node, const std::vector<std::string_view>& allowed,
                   const std::vector<std::string_view>& repeatable = {});

// Warns about attributes not in `allowed` (with the probable one, as above). `name` is informational on every element and is
// always accepted (one student file names its light).
void checkAttributes(const ParseContext& context, pugi::xml_node node, std::initializer_list<std::string_view> allowed);

// The child element `name`, or a SceneError naming the parent's line.
pugi::xml_node requireChild(const ParseContext& context, pugi::xml_node node, const char* name);

// The attribute `name` with non-empty value, or a SceneError.
std::string requireAttribute(const ParseContext& context, pugi::xml_node node, const char* name);

}  // namespace vkrt
