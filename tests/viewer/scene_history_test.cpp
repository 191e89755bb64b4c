// Undo and redo restore earlier scenes exactly; a new edit drops what could be redone.
#include <gtest/gtest.h>

#include "viewer/scene_history.h"

namespace {

using tstyles::Scene;
using tstyles::viewer::SceneHistory;

Scene withTermination(double termination) {
    Scene scene;
    scene.raycast.termination = termination;
    return scene;
}

TEST(SceneHistory, RecordsOnlyChanges) {
    SceneHistory history(withTermination(0.9));
    EXPECT_FALSE(history.record(withTermination(0.9)));
    EXPECT_FALSE(history.canUndo());
    EXPECT_TRUE(history.record(withTermination(0.8)));
    EXPECT_TRUE(history.canUndo());
}

TEST(SceneHistory, UndoAndRedoWalkTheRecordedScenes) {
    SceneHistory history(withTermination(0.9));
    history.record(withTermination(0.8));
    history.record(withTermination(0.7));
    EXPECT_EQ(history.undo(), withTermination(0.8));
    EXPECT_EQ(history.undo(), withTermination(0.9));
    EXPECT_FALSE(history.canUndo());
    EXPECT_EQ(history.redo(), withTermination(0.8));
    EXPECT_EQ(history.redo(), withTermination(0.7));
    EXPECT_FALSE(history.canRedo());
}

TEST(SceneHistory, ANewEditDropsTheRedoSteps) {
    SceneHistory history(withTermination(0.9));
    history.record(withTermination(0.8));
    history.undo();
    history.record(withTermination(0.5));
    EXPECT_FALSE(history.canRedo());
    EXPECT_EQ(history.undo(), withTermination(0.9));
}

TEST(SceneHistory, KeepsAtMostItsLimit) {
    SceneHistory history(withTermination(0.0), 3);
    for (int i = 1; i <= 10; ++i) history.record(withTermination(i / 10.0));
    EXPECT_EQ(history.undoDepth(), 3u);
    history.undo();
    history.undo();
    EXPECT_EQ(history.undo(), withTermination(0.7));
}

TEST(SceneHistory, ResetForgetsEverything) {
    SceneHistory history(withTermination(0.9));
    history.record(withTermination(0.8));
    history.reset(withTermination(0.4));
    EXPECT_FALSE(history.canUndo());
    EXPECT_FALSE(history.canRedo());
    EXPECT_EQ(history.latest(), withTermination(0.4));
}

}  // namespace
