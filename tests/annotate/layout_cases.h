// Scenes with every annotation on, fitted to their series as `tstyles render` fits them, for the
// layout tests: each bundled scene on its dataset, the automatic scene of the realistic files
// (tests/data/realistic_datasets.h), and synthetic series shaped like files users bring (a global
// ocean with a long depth name, a 7-step forecast, a 40-volume fMRI run).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/annotate/scene_annotations.h"
#include "tstyles/scene/automatic_scene.h"

namespace tstyles::testing {

struct LayoutCase {
    std::string name;
    SceneOnSeries fitted;  // the scene (annotations all on) and the display series
    bool bundled = false;  // a bundled scene (data/scenes), not a file or series shaped like users' own
};

// Loaded once per test program.
const std::vector<LayoutCase>& layoutCases();

// The image sizes the layout must hold at.
const std::vector<glm::ivec2>& layoutImageSizes();

// The case's scene at this size, and its annotations planned as a render would draw them (on the
// heap: the plan's drawings refer to the scene and the view beside it).
struct SizedPlan {
    Scene scene;
    View view;  // the camera's; the picture is drawn with plan.view
    AnnotationPlan plan;
};
std::unique_ptr<SizedPlan> planAt(const LayoutCase& layoutCase, glm::ivec2 size, const Font& font);

}  // namespace tstyles::testing
