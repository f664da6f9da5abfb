// vkrt --version: what a student quotes in a bug report.
#pragma once

#include <string>

namespace vkrt {

// "vkrt 0.1.0" (the project()'s VERSION in CMakeLists.txt), with " (git 66847b8c01)" when the build
// was configured in a git checkout: the commit as of that cmake run, not of later commits built
// without re-running it.
std::string versionLine();

}  // namespace vkrt
