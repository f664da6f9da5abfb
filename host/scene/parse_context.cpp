#include "parse_context.h"

#include <algorithm>
#include <set>

#include "name_suggestion.h"

namespace vkrt {

namespace {
template <typename Names>
bool contains(const Names& names, std::string_view name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}
}  // namespace

Issue ParseContext::issueAt(pugi::xml_node node, std::string problem, std::string value) const {
    return Issue{source.path(), source.lineOf(node), node.name(), std::move(problem), std::move(value)};
}

void ParseContext::warn(Issue issue) const {
    if (strict) throw SceneError(std::move(issue));
    diagnostics.warn(std::move(issue));
}

void ParseContext::warn(pugi::xml_node node, std::string problem, std::string value, std::string hint) const {
    Issue issue = issueAt(node, std::move(problem), std::move(value));
    issue.hint = std::move(hint);
    warn(std::move(issue));
}

void ParseContext::fail(pugi::xml_node node, std::string problem, std::string value) const {
    throw SceneError(issueAt(node, std::move(problem), std::move(value)));
}

std::string elementText(pugi::xml_node node) {
    std::string text;
    for (pugi::xml_node child : node.children())
        if (child.type() == pugi::node_pcdata || child.type() == pugi::node_cdata) text += child.value();
    return text;
}

std::string trimmed(const std::string& text) {
    const auto begin = text.find_first_not_of(" \t\r\n");
    if (begin == std::string::npos) return {};
    return text.substr(begin, text.find_last_not_of(" \t\r\n") - begin + 1);
}

void checkChildren(const ParseContext& context, pugi::xml_node node, const std::vector<std::string_view>& allowed,
                   const std::vector<std::string_view>& repeatable) {
    std::set<std::string_view> seen;
    for (pugi::xml_node child : node.children()) {
        if (child.type() != pugi::node_element) continue;  // text and comments are harmless
        const std::string_view name = child.name();
        if (contains(repeatable, name)) continue;
        if (!contains(allowed, name)) {
            std::vector<std::string_view> known = allowed;
            known.insert(known.end(), repeatable.begin(), repeatable.end());
            context.warn(child, std::string("unknown element inside <") + node.name() + ">, ignored", "", didYouMean(name, known));
        } else if (!seen.insert(name).second) {
            context.warn(child, std::string("repeated inside <") + node.name() + ">, the first one is used");
        }
    }
}

void checkAttributes(const ParseContext& context, pugi::xml_node node, std::initializer_list<std::string_view> allowed) {
    for (pugi::xml_attribute attribute : node.attributes()) {
        const std::string_view name = attribute.name();
        if (name == "name" || contains(allowed, name)) continue;
        std::vector<std::string_view> known = allowed;
        known.push_back("name");
        context.warn(node, "unknown attribute ignored", attribute.name(), didYouMean(name, known));
    }
}

pugi::xml_node requireChild(const ParseContext& context, pugi::xml_node node, const char* name) {
    pugi::xml_node child = node.child(name);
    if (!child) context.fail(node, std::string("missing required element <") + name + ">");
    return child;
}

std::string requireAttribute(const ParseContext& context, pugi::xml_node node, const char* name) {
    const pugi::xml_attribute attribute = node.attribute(name);
    if (!attribute || std::string_view(attribute.value()).empty())
        context.fail(node, std::string("missing required attribute ") + name);
    return attribute.value();
}

}  // namespace vkrt
