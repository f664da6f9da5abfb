// `vkrt scene.xml --target-error E` / `--time SECONDS`: adaptive sampling (adaptive_render.h) on the
// device --device picks, with a line per round, the error and sample-count maps, and the summary.
#pragma once

#include "command_line.h"

namespace vkrt {

int runAdaptiveRender(CommandLine& cl);

}  // namespace vkrt
