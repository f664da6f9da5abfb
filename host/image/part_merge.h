// vkrt merge's reader: the EXR parts of one render (host/app/image_parts.h writes their
// attributes) put back together. Here, beside the image readers, so that the fuzzing build reaches
// it without the rest of the program.
#pragma once

#include <string>
#include <vector>

#include "image.h"

namespace vkrt {

// Reads the parts and copies each one's rows into one image. Throws std::runtime_error naming the
// file for a file that is not a part, parts of different renders or sizes, a part given twice,
// or parts missing (named by number).
Image mergeParts(const std::vector<std::string>& paths);

}  // namespace vkrt
