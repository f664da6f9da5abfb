// Numbers written as text ("0 3.0 4.0", ".8", "1.", "-0.0"), read the way the course's C++ read
// them (istream >> float, one after the other), for both formats: XML element text and JSON
// strings ("position": "0 1 2", and the G0 files' "focalLength": "1.0").
#pragma once

#include <array>
#include <optional>
#include <string>

namespace vkrt {

// The result of reading `count` (1..3) numbers. Errors: a missing component, a non-number,
// NaN/Inf, a value outside float range. `irregular` (a warning): a number running into the next
// one ("2.5.0" reads as 2.5 then .0) or extra tokens after the expected count; the values are
// then what istream would have read.
struct NumberText {
    std::array<float, 3> values{};
    std::array<double, 3> exact{};  // the same numbers in double, before rounding to float (the
                                    // text's nearest double): positions rebased to a local origin
    std::string error;       // empty when the text holds `count` numbers
    std::string errorValue;  // the offending token (or the whole text), for the message
    bool irregular = false;
};
NumberText readNumberText(const std::string& text, int count);

// The warning for an irregular list: "malformed number list, read as '0 2.5 0' like ...".
std::string irregularNumberProblem(const NumberText& numbers, int count);

// A number that must fit a 32-bit float (JSON numbers are read as double): nullopt for NaN, Inf
// and anything that rounds to infinity as a float.
std::optional<float> finiteFloat(double value);
inline constexpr const char* kNotAFiniteFloat = "not a finite 32-bit number";

}  // namespace vkrt
