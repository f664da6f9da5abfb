#include "json_context.h"

#include <algorithm>
#include <optional>

#include "local_origin.h"
#include "name_suggestion.h"
#include "number_text.h"

namespace vkrt {

namespace {

bool listed(const std::vector<std::string_view>& names, std::string_view name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

// Every spelling checkKeys accepts: the keys, and the attributes plain and underscored.
std::vector<std::string> knownKeys(const std::vector<std::string_view>& allowed, const std::vector<std::string_view>& attributes) {
    std::vector<std::string> keys(allowed.begin(), allowed.end());
    for (std::string_view name : attributes) {
        keys.emplace_back(name);
        keys.push_back("_" + std::string(name));
    }
    return keys;
}

}  // namespace

Issue JsonContext::issueAtOffset(std::ptrdiff_t offset, const std::string& path, std::string problem, std::string value) const {
    return Issue{source.path(), source.lineOf(offset), path.empty() ? "json" : path, std::move(problem), std::move(value),
                 source.columnOf(offset)};
}

Issue JsonContext::issueAt(const JsonNode& node, std::string problem, std::string value) const {
    const JsonSource::Span* span = source.spanOf(node.path);
    return issueAtOffset(span ? span->begin : 0, node.path, std::move(problem), std::move(value));
}

Issue JsonContext::issueAtKey(const JsonNode& node, std::string problem, std::string value) const {
    const JsonSource::Span* span = source.spanOf(node.path);
    const std::ptrdiff_t at = span ? (span->key >= 0 ? span->key : span->begin) : 0;
    return issueAtOffset(at, node.path, std::move(problem), std::move(value));
}

void JsonContext::warn(Issue issue) const {
    if (strict) throw SceneError(std::move(issue));
    diagnostics.warn(std::move(issue));
}

void JsonContext::warn(const JsonNode& node, std::string problem, std::string value, std::string hint) const {
    Issue issue = issueAt(node, std::move(problem), std::move(value));
    issue.hint = std::move(hint);
    warn(std::move(issue));
}

void JsonContext::warnAtKey(const JsonNode& node, std::string problem, std::string value, std::string hint) const {
    Issue issue = issueAtKey(node, std::move(problem), std::move(value));
    issue.hint = std::move(hint);
    warn(std::move(issue));
}

void JsonContext::fail(const JsonNode& node, std::string problem, std::string value) const {
    throw SceneError(issueAt(node, std::move(problem), std::move(value)));
}

SourceLocation JsonContext::locationOf(const JsonNode& node) const {
    const Issue issue = issueAt(node, "");
    return {issue.file, issue.line, issue.column};
}

JsonNode member(const JsonNode& object, std::string_view key) {
    JsonNode node{nullptr, memberPath(object.path, std::string(key))};
    if (object && object->is_object()) {
        const auto found = object->find(key);
        if (found != object->end()) node.value = &*found;
    }
    return node;
}

JsonNode attributeMember(const JsonContext& context, const JsonNode& object, std::string_view name) {
    std::string underscoredKey(1, '_');  // (not "_" + name: GCC 12 warns falsely about that)
    underscoredKey += name;
    const JsonNode plain = member(object, name);
    const JsonNode underscored = member(object, underscoredKey);
    if (plain && underscored)
        context.warnAtKey(underscored, "both " + std::string(name) + " and " + underscoredKey + " given, " +
                                           std::string(name) + " is used");
    return plain ? plain : underscored;
}

void checkKeys(const JsonContext& context, const JsonNode& object, const std::vector<std::string_view>& allowed,
               const std::vector<std::string_view>& attributes) {
    if (!object || !object->is_object()) return;
    for (const auto& [key, value] : object->items()) {
        const std::string_view name = key;
        const bool attribute = listed(attributes, name) || (name.size() > 1 && name[0] == '_' && listed(attributes, name.substr(1)));
        if (attribute || listed(allowed, name)) continue;
        const std::vector<std::string> known = knownKeys(allowed, attributes);
        context.warnAtKey(member(object, key), "unknown key, ignored", "",
                          didYouMean(name, std::vector<std::string_view>(known.begin(), known.end())));
    }
}

void requireObject(const JsonContext& context, const JsonNode& node) {
    if (!node->is_object()) context.fail(node, std::string("expected an object, found ") + typeName(*node), quoted(context, node));
}

JsonNode requireMember(const JsonContext& context, const JsonNode& object, std::string_view key) {
    JsonNode node = member(object, key);
    if (!node) context.fail(object, "missing required key " + std::string(key));
    return node;
}

JsonNode requireAttribute(const JsonContext& context, const JsonNode& object, std::string_view name) {
    JsonNode node = attributeMember(context, object, name);
    if (!node) {
        std::string problem = "missing required key _";
        problem += name;
        context.fail(object, problem + " (or " + std::string(name) + ")");
    }
    return node;
}

std::vector<JsonNode> objectsOf(const JsonContext& context, const JsonNode& list) {
    std::vector<JsonNode> objects;
    if (!list) return objects;
    if (list->is_object()) {
        objects.push_back(list);
    } else if (list->is_array()) {
        for (std::size_t i = 0; i < list->size(); ++i) {
            JsonNode element{&(*list)[i], elementPath(list.path, i)};
            requireObject(context, element);
            objects.push_back(std::move(element));
        }
    } else {
        context.fail(list, std::string("expected an array of objects, found ") + typeName(*list), quoted(context, list));
    }
    return objects;
}

const char* typeName(const Json& value) {
    switch (value.type()) {
        case Json::value_t::object: return "an object";
        case Json::value_t::array: return "an array";
        case Json::value_t::string: return "a string";
        case Json::value_t::boolean: return "a boolean";
        case Json::value_t::null: return "null";
        case Json::value_t::number_integer:
        case Json::value_t::number_unsigned:
        case Json::value_t::number_float: return "a number";
        default: return "a value";
    }
}

std::string quoted(const JsonContext& context, const JsonNode& node) {
    if (!node) return "";
    if (node->is_string()) return node->get<std::string>();
    const std::string written = context.source.textOf(node.path);
    return written.empty() ? node->dump() : written;
}

std::string readText(const JsonContext& context, const JsonNode& node) {
    if (!node->is_string()) context.fail(node, std::string("expected a string, found ") + typeName(*node), quoted(context, node));
    return node->get<std::string>();
}

std::string readString(const JsonContext& context, const JsonNode& node) {
    std::string text = readText(context, node);
    if (text.empty()) context.fail(node, "empty string");
    return text;
}

float readScalar(const JsonContext& context, const JsonNode& node, double* exact) {
    if (node->is_number()) {
        const double number = node->get<double>();
        const std::optional<float> value = finiteFloat(number);
        if (!value) context.fail(node, kNotAFiniteFloat, quoted(context, node));
        if (exact) *exact = number;
        return *value;
    }
    if (node->is_string()) {
        const std::string text = node->get<std::string>();
        const NumberText number = readNumberText(text, 1);
        if (!number.error.empty()) context.fail(node, number.error, number.errorValue);
        context.warn(node, "a number written as a string, read as a number", text);
        if (number.irregular) context.warn(node, irregularNumberProblem(number, 1), text);
        if (exact) *exact = number.exact[0];
        return number.values[0];
    }
    context.fail(node, std::string("expected a number, found ") + typeName(*node), quoted(context, node));
}

glm::vec3 readVec3(const JsonContext& context, const JsonNode& node, glm::dvec3* exact) {
    if (node->is_string()) {
        const std::string text = node->get<std::string>();
        const NumberText numbers = readNumberText(text, 3);
        if (!numbers.error.empty()) context.fail(node, numbers.error, numbers.errorValue);
        if (numbers.irregular) context.warn(node, irregularNumberProblem(numbers, 3), text);
        if (exact) *exact = {numbers.exact[0], numbers.exact[1], numbers.exact[2]};
        return {numbers.values[0], numbers.values[1], numbers.values[2]};
    }
    if (node->is_array()) {
        if (node->size() != 3) context.fail(node, "expected 3 numbers, found " + std::to_string(node->size()), quoted(context, node));
        glm::vec3 v;
        glm::dvec3 d;
        for (std::size_t i = 0; i < 3; ++i) {
            const int c = static_cast<int>(i);
            v[c] = readScalar(context, {&(*node)[i], elementPath(node.path, i)}, &d[c]);
        }
        if (exact) *exact = d;
        return v;
    }
    context.fail(node, std::string("expected 3 numbers (a string or an array), found ") + typeName(*node), quoted(context, node));
}

glm::vec3 readPosition(const JsonContext& context, const JsonNode& node, bool world) {
    if (!world || !context.localOrigin) return readVec3(context, node);
    glm::dvec3 exact;
    readVec3(context, node, &exact);
    const std::optional<glm::vec3> local = rules::localPosition(exact, context.origin);
    if (!local) context.fail(node, rules::kBeyondFloatLocally, quoted(context, node));
    return *local;
}

}  // namespace vkrt
