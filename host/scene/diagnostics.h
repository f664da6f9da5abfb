// What the scene loader says about its input: warnings it recovered from, and the one error that
// stops it. Both carry the same fields so that --strict can turn any warning into an error.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace vkrt {

// One finding about one element of one file, rendered as
//   "<file>:<line>: <element>: <problem> '<value>'; <hint>"            (XML)
//   "<file>:<line>:<column>: <path>: <problem> '<value>'; <hint>"      (JSON: column > 0)
// with the quoted value and the hint only when there are.
struct Issue {
    std::string file;
    int line = 0;          // 1-based; 0 when no line applies (e.g. the file cannot be opened)
    std::string element;   // the XML element, the JSON path ("scene.shape[3].radius"), or
                           // "xml" / "json" / "obj" for whole-file problems
    std::string problem;
    std::string value;     // the offending text, quoted in the message when non-empty
    int column = 0;        // 1-based byte column (JSON); 0: the message names the line only
    std::string hint{};    // what was probably meant ("did you mean 'sphere'?", name_suggestion.h)

    std::string message() const;
};

// Malformed or unusable input. what() is a single line (Issue::message()).
class SceneError : public std::runtime_error {
public:
    explicit SceneError(Issue issue);
    const Issue& issue() const { return issue_; }

private:
    Issue issue_;
};

// Collects the warnings of one load, in the order they were found. With strict on, warn()
// throws the warning as a SceneError instead of recording it.
class Diagnostics {
public:
    explicit Diagnostics(bool strict = false) : strict_(strict) {}

    void warn(Issue issue);

    bool strict() const { return strict_; }
    const std::vector<Issue>& warnings() const { return warnings_; }
    std::vector<std::string> messages() const;  // one "file:line: ..." line per warning
    // One line per distinct warning, in the order they were first found: what vkrt prints. Warnings
    // of one file with the same problem (and hint) at the same kind of element (a JSON path with its
    // indices dropped) are one; the first keeps its place and value and says how many more like it
    // there are and on which lines: "... (and 19 more like it, lines 12-80)". A course file that
    // repeats one oddity 20 times then says so in one line, and a different problem still shows.
    std::vector<std::string> summary() const;

private:
    bool strict_;
    std::vector<Issue> warnings_;
};

}  // namespace vkrt
