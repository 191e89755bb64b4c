// The viewer's compositor list: every compositor of the table by name, and the scene's own code
// as one more entry only when the scene has some.
#include <algorithm>

#include <gtest/gtest.h>

#include "tstyles/scene/temporal_compositors.h"
#include "viewer/side_panel.h"

namespace tstyles::viewer {
namespace {

TEST(CompositorChoices, ListEveryCompositorOfTheTable) {
    const Scene scene;
    const std::vector<std::string> choices = compositorChoices(scene);
    for (std::size_t line = 0; line < temporalCompositors().size(); ++line) {
        const char* name = temporalCompositors()[line].name;
        const bool listed = std::find(choices.begin(), choices.end(), name) != choices.end();
        EXPECT_EQ(listed, TemporalCompositor(line) != kCustomCompositor) << name;
    }
    EXPECT_EQ(choices.size(), temporalCompositors().size() - 1);
}

TEST(CompositorChoices, OfferTheScenesOwnCodeWhileTheSceneKeepsIt) {
    Scene scene;
    scene.compositor = kCustomCompositor;
    scene.compositorOptions.custom = CustomCompositor{"return 0.0;", "scene.json", false, CompositorReads::IndexTstf};
    EXPECT_EQ(compositorChoices(scene).back(), kCustomCompositorChoice);
    // Another compositor chosen: the code stays, and so does the entry to choose it again.
    scene.compositor = compositorNamed("linear-trend");
    EXPECT_EQ(compositorChoices(scene).back(), kCustomCompositorChoice);
}

}  // namespace
}  // namespace tstyles::viewer
