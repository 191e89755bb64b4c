// Time in colour for the automatic scene: the index TSTF gives each time-step its own colour from a
// perceptually ordered map, the gradient TSTF the paper's green-to-orange scale. `probe -o` colours
// its markers with the same index TSTF.
#pragma once

#include <cstddef>
#include <string>

#include "tstyles/scene/scene.h"

namespace tstyles {

void applyTimeColours(Scene& scene, std::size_t stepCount);
std::string timeColoursText(std::size_t stepCount);

}  // namespace tstyles
