#include "diagnostics.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <tuple>
#include <utility>

namespace vkrt {

namespace {

// A value may be element text spanning lines, or a whole paragraph of garbage, and a problem may
// quote a library's multi-line message: keep the message on one line. Values are also shortened
// past kMaxChars, which is long enough for any real path but not for a pasted paragraph.
std::string oneLine(const std::string& value, std::size_t kMaxChars) {
    std::string flat;
    bool lastWasSpace = false;
    for (char c : value) {
        const bool space = c == '\n' || c == '\r' || c == '\t' || c == ' ';
        if (space && lastWasSpace) continue;
        flat += space ? ' ' : c;
        lastWasSpace = space;
    }
    while (!flat.empty() && flat.back() == ' ') flat.pop_back();
    if (!flat.empty() && flat.front() == ' ') flat.erase(0, 1);  // runs were collapsed to one space
    if (flat.size() > kMaxChars) flat = flat.substr(0, kMaxChars) + "...";
    return flat;
}

// The kind of element a warning is about: a JSON path without its indices
// ("scene.shape[3].radius" -> "scene.shape[].radius"); an XML element name as it is.
std::string elementKind(const std::string& element) {
    std::string kind;
    bool inIndex = false;
    for (char c : element) {
        if (inIndex && std::isdigit(static_cast<unsigned char>(c))) continue;
        inIndex = c == '[';
        kind += c;
    }
    return kind;
}

// The warnings summary() folds into the first of their group.
struct Group {
    std::size_t first = 0;  // index into the warnings
    int more = 0;
    int lowestLine = 0, highestLine = 0;  // of the `more` (0: none has a line)
};

std::string moreLikeIt(const Group& group) {
    std::string text = " (and " + std::to_string(group.more) + " more like it";
    if (group.lowestLine > 0) {
        text += group.lowestLine == group.highestLine ? ", line " + std::to_string(group.lowestLine)
                                                      : ", lines " + std::to_string(group.lowestLine) + "-" +
                                                            std::to_string(group.highestLine);
    }
    return text + ")";
}

}  // namespace

std::string Issue::message() const {
    std::string text = file + ":" + std::to_string(line);
    if (column > 0) text += ":" + std::to_string(column);
    text += ": " + element + ": " + oneLine(problem, std::string::npos);
    if (!value.empty()) text += " '" + oneLine(value, 240) + "'";
    if (!hint.empty()) text += "; " + hint;
    return text;
}

SceneError::SceneError(Issue issue) : std::runtime_error(issue.message()), issue_(std::move(issue)) {}

void Diagnostics::warn(Issue issue) {
    if (strict_) throw SceneError(std::move(issue));
    warnings_.push_back(std::move(issue));
}

std::vector<std::string> Diagnostics::messages() const {
    std::vector<std::string> lines;
    lines.reserve(warnings_.size());
    for (const Issue& issue : warnings_) lines.push_back(issue.message());
    return lines;
}

std::vector<std::string> Diagnostics::summary() const {
    using Key = std::tuple<std::string, std::string, std::string, std::string>;  // file, kind, problem, hint
    std::map<Key, std::size_t> groupOf;
    std::vector<Group> groups;
    for (std::size_t i = 0; i < warnings_.size(); ++i) {
        const Issue& issue = warnings_[i];
        const auto [found, added] = groupOf.emplace(Key{issue.file, elementKind(issue.element), issue.problem, issue.hint},
                                                    groups.size());
        if (added) {
            groups.push_back(Group{i});
            continue;
        }
        Group& group = groups[found->second];
        ++group.more;
        if (issue.line <= 0) continue;
        group.lowestLine = group.lowestLine > 0 ? std::min(group.lowestLine, issue.line) : issue.line;
        group.highestLine = std::max(group.highestLine, issue.line);
    }
    std::vector<std::string> lines;
    lines.reserve(groups.size());
    for (const Group& group : groups)
        lines.push_back(warnings_[group.first].message() + (group.more > 0 ? moreLikeIt(group) : ""));
    return lines;
}

}  // namespace vkrt
