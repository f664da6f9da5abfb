// One render split over processes (--part I/N, e.g. a Slurm array job) and put back together
// (vkrt merge, part_merge.h in host/image). Every pixel of a part is computed exactly as in the whole image (samples are keyed
// by the pixel, not by the process), so the merged image is the single process's, byte for byte.
// A part is an EXR of the whole image's size whose other rows are black, carrying its place and
// what was rendered as "vkrt:" attributes; merge refuses parts of different renders.
#pragma once

#include <string>
#include <vector>

#include "command_line.h"
#include "image.h"
#include "part_merge.h"  // mergeParts, which vkrt merge calls

namespace vkrt {

// The attributes a part's EXR carries: vkrt:part "I/N", vkrt:rows "first end", vkrt:render (every
// setting that changes the image, and the device kind that computed it).
ImageAttributes partAttributes(const CommandLine& cl, const std::string& device);


}  // namespace vkrt
