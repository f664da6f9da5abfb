// `vkrt check SCENE IMAGE`: renders the scene on the CPU reference at the image's size, tests the
// image pixel by pixel against it (image_check.h), names the common mistake that explains a
// difference, and writes IMAGE_vkrt_reference.png and IMAGE_vkrt_diff.png beside the image.
#pragma once

#include "command_line.h"

namespace vkrt {

inline constexpr int kExitSamePicture = 0;
inline constexpr int kExitDifferentPicture = 3;

// Returns kExitSamePicture or kExitDifferentPicture; throws std::runtime_error (naming the file)
// when the image or the scene cannot be read or the outputs cannot be written.
int runCheck(CommandLine& cl);

}  // namespace vkrt
