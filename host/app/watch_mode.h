// vkrt --watch scene.xml|json [-o out.png] [--shader-dir DIR] [--progressive N]: one process that
// renders, then renders again whenever the scene, a mesh or texture it reads, or (with --shader-dir,
// on the GPU) a GLSL file changes. The device, its kernel and its pipelines are kept between
// renders: a scene edit costs the load, the trees and the render; a shader edit costs the kernel's
// compile and the render (the scene and its trees are kept). Each render's times or its error are
// printed and the process goes on; images are written atomically (output_file.h), so a viewer never
// reads a half-written file. Ctrl-C stops it.
#pragma once

#include "command_line.h"

namespace vkrt {

int runWatch(CommandLine& cl);

}  // namespace vkrt
