// Rendering a bundled scene on a bundled dataset in two ways and requiring the same image: the
// equivalence tests of the speed-ups (skipping against naive, packed against general path).
#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>

#include "tstyles/render/renderer.h"

namespace tstyles::testing {

// data/scenes/<scene>.json rendered on data/<dataset>/series.json.
struct BundledScene {
    std::string scene;
    std::string dataset;
    std::string compositor;  // a compositor's name (as in scene files) in place of the scene's; empty: the scene's
};

// What ctest lists and gtest reports as the parameter (instead of the struct's bytes).
void PrintTo(const BundledScene& bundled, std::ostream* out);
// "<scene>_on_<dataset>" with '-' as '_': a test-name suffix.
std::string testNameOf(const BundledScene& bundled);
std::filesystem::path manifestOf(const BundledScene& bundled);

struct SameImageTolerance {
    int pixelThreshold;         // a pixel fails above this many 1/255 steps in any channel
    double maxFailingFraction;  // share of failing pixels allowed
    double maxMeanDelta;        // mean difference allowed, in 1/255 steps
};

// One way to render: its name (for messages and the files written on failure), its options and the
// walk it must take (none: any).
struct RenderingWay {
    const char* name;
    FrameOptions options;
    std::optional<TimeStepWalk> walk;
};

// Renders the bundled scene at size x size both ways (the dataset must be there) and expects the
// same image within `tolerance`; on failure both renders and their difference go to the test
// output folder. Prints the difference either way. One variable per comparison: where neither way
// chooses the gradient method, both take six fetches (by default the first styled frame after an
// upload takes six and the next the gradient atlas). Every path a way forces (naive, general,
// caches, empty-brick test, precomputed gradients on a styled scene, its walk) is asserted taken.
void expectSameImage(const BundledScene& bundled, int size, const RenderingWay& first, const RenderingWay& second,
                     const SameImageTolerance& tolerance);

}  // namespace tstyles::testing
