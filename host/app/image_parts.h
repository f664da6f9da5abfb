// One render split over processes (--part I/N, e.g. a Slurm array job) and put back together
// (vkrt merge). Every pixel of a part is computed exactly as in the whole image (samples are keyed
// by the pixel, not by the process), so the merged image is the single process's, byte for byte.
// A part is an EXR of the whole image's size whose other rows are black, carrying its place and
// what was rendered as "vkrt:" attributes; merge refuses parts of different renders.
#pragma once

#include <string>
#include <vector>

#include "command_line.h"
#include "image.h"

namespace vkrt {

// The attributes a part's EXR carries: vkrt:part "I/N", vkrt:rows "first end", vkrt:render (every
// setting that changes the image, and the device kind that computed it).
ImageAttributes partAttributes(const CommandLine& cl, const std::string& device);

// Reads the parts and copies each one's rows into one image. Throws std::runtime_error naming the
// file for a file that is not a part, parts of different renders or sizes, a part given twice,
// or parts missing (named by number).
Image mergeParts(const std::vector<std::string>& paths);

}  // namespace vkrt
