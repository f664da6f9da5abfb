// What the scene loader says about its input: warnings it recovered from, and the one error that
// stops it. Both carry the same fields so that --strict can turn any warning into an error.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace vkrt {

// One finding about one element of one file, rendered as
//   "<file>:<line>: <element>: <problem> '<value>'"            (XML)
//   "<file>:<line>:<column>: <path>: <problem> '<value>'"      (JSON: column > 0)
// with the quoted value only when there is one.
struct Issue {
    std::string file;
    int line = 0;          // 1-based; 0 when no line applies (e.g. the file cannot be opened)
    std::string element;   // the XML element, the JSON path ("scene.shape[3].radius"), or
                           // "xml" / "json" / "obj" for whole-file problems
    std::string problem;
    std::string value;     // the offending text, quoted in the message when non-empty
    int column = 0;        // 1-based byte column (JSON); 0: the message names the line only

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

private:
    bool strict_;
    std::vector<Issue> warnings_;
};

}  // namespace vkrt
