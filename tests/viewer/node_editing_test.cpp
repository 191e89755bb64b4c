// Node editing rules behind the editors: groups are picked and moved whole, moves on the index
// TSTF snap to whole time-steps and stop at the ends without squeezing a group, re-sorting keeps
// track of the moved nodes.
#include <gtest/gtest.h>

#include "viewer/node_editing.h"

namespace {

using namespace tstyles;
using namespace tstyles::viewer;

// The index TSTF of the paper's Figure 1: the focus (group 1) at time-step 3 with faint
// neighbours at 2 and 4, over ten time-steps.
TransferFunction1D figureOneTstf() {
    TransferFunction1D curve;
    curve.opacity = {{0, 0.35, 0}, {1, 0.015, 0}, {2, 0.015, 1}, {3, 1.0, 1}, {4, 0.015, 1}, {8, 0.015, 0}, {9, 0.35, 0}};
    ColorNode blue{0, {0.25, 0.45, 0.95}, "", 0};
    ColorNode grey{1, {0.75, 0.8, 0.9}, "", 0};
    ColorNode focusGrey{2, {0.75, 0.8, 0.9}, "", 1};
    ColorNode yellow{3, {1.0, 0.95, 0.6}, "light", 1};
    ColorNode focusGrey4{4, {0.75, 0.8, 0.9}, "", 1};
    ColorNode orange{9, {1.0, 0.55, 0.1}, "", 0};
    curve.color = {blue, grey, focusGrey, yellow, focusGrey4, orange};
    return curve;
}

constexpr CurveAxis kTenTimeSteps{0.0, 9.0, true};
constexpr CurveAxis kUnitAxis{0.0, 1.0, false};

TEST(NodeEditing, ClickingOneMemberSelectsTheWholeGroup) {
    const TransferFunction1D curve = figureOneTstf();
    const NodeSelection selected = withWholeGroups(curve, {{NodeKind::Color, 3}});
    const NodeSelection expected = {{NodeKind::Opacity, 2}, {NodeKind::Opacity, 3}, {NodeKind::Opacity, 4},
                                    {NodeKind::Color, 2},   {NodeKind::Color, 3},   {NodeKind::Color, 4}};
    EXPECT_EQ(selected, expected);
    EXPECT_EQ(withWholeGroups(curve, {{NodeKind::Opacity, 0}}), (NodeSelection{{NodeKind::Opacity, 0}}));
}

TEST(NodeEditing, MovingTheFocusGroupThreeStepsGivesFigureOneRight) {
    const TransferFunction1D curve = figureOneTstf();
    const NodeSelection group = withWholeGroups(curve, {{NodeKind::Opacity, 3}});
    const EditResult moved = shiftNodes(curve, group, 3.0, kTenTimeSteps);
    EXPECT_EQ(moved.curve.evaluate(6.0).opacity, 1.0);
    EXPECT_EQ(moved.curve.evaluate(3.0).opacity, 0.015);
    EXPECT_EQ(moved.curve.evaluate(6.0).color, glm::dvec3(1.0, 0.95, 0.6));
    // The moved nodes are still the selection after the re-sort, and still group 1.
    ASSERT_EQ(moved.nodes.size(), 6u);
    for (const NodeRef& node : moved.nodes) {
        EXPECT_EQ(groupOf(moved.curve, node), 1);
        EXPECT_GE(positionOf(moved.curve, node), 5.0);
        EXPECT_LE(positionOf(moved.curve, node), 7.0);
    }
    EXPECT_EQ(moved.curve.color[3].style, "light");
}

TEST(NodeEditing, GroupMovesSnapToWholeTimeSteps) {
    const TransferFunction1D curve = figureOneTstf();
    const NodeSelection group = withWholeGroups(curve, {{NodeKind::Opacity, 3}});
    EXPECT_EQ(allowedShift(curve, group, 2.4, kTenTimeSteps), 2.0);
    EXPECT_EQ(allowedShift(curve, group, 2.6, kTenTimeSteps), 3.0);
    EXPECT_EQ(allowedShift(curve, group, -0.4, kTenTimeSteps), 0.0);
    // On a continuous axis nothing snaps.
    TransferFunction1D stf;
    stf.opacity = {{0.2, 0.0, 1}, {0.4, 1.0, 1}};
    EXPECT_DOUBLE_EQ(allowedShift(stf, allNodes(stf), 0.123, kUnitAxis), 0.123);
}

TEST(NodeEditing, GroupsClipAtTheEndsWithoutDeforming) {
    const TransferFunction1D curve = figureOneTstf();
    const NodeSelection group = withWholeGroups(curve, {{NodeKind::Opacity, 3}});
    // The group spans time-steps 2..4: it can go 5 steps later and 2 earlier, no further.
    EXPECT_EQ(allowedShift(curve, group, 7.0, kTenTimeSteps), 5.0);
    EXPECT_EQ(allowedShift(curve, group, -6.0, kTenTimeSteps), -2.0);
    const EditResult atEnd = shiftNodes(curve, group, 100.0, kTenTimeSteps);
    std::vector<double> positions;
    for (const NodeRef& node : atEnd.nodes)
        if (node.kind == NodeKind::Opacity) positions.push_back(positionOf(atEnd.curve, node));
    EXPECT_EQ(positions, (std::vector<double>{7.0, 8.0, 9.0}));

    TransferFunction1D stf;
    stf.opacity = {{0.2, 0.0, 1}, {0.5, 1.0, 1}};
    const EditResult clipped = shiftNodes(stf, allNodes(stf), 0.9, kUnitAxis);
    EXPECT_DOUBLE_EQ(clipped.curve.opacity[0].at, 0.7);
    EXPECT_DOUBLE_EQ(clipped.curve.opacity[1].at, 1.0);
}

TEST(NodeEditing, GroupingTakesTheSmallestUnusedNumber) {
    TransferFunction1D curve = figureOneTstf();
    EXPECT_EQ(unusedGroup(curve), 2);
    const NodeGroup group = groupNodes(curve, {{NodeKind::Opacity, 0}, {NodeKind::Color, 0}});
    EXPECT_EQ(group, 2);
    EXPECT_EQ(curve.opacity[0].group, 2);
    EXPECT_EQ(curve.color[0].group, 2);
    // One node is no group.
    EXPECT_EQ(groupNodes(curve, {{NodeKind::Opacity, 6}}), 0);
    EXPECT_EQ(curve.opacity[6].group, 0);
}

TEST(NodeEditing, UngroupingAndRegroupingRestoresTheGroup) {
    TransferFunction1D curve = figureOneTstf();
    const TransferFunction1D original = curve;
    const NodeSelection focus = withWholeGroups(curve, {{NodeKind::Opacity, 3}});
    ungroupNodes(curve, focus);
    EXPECT_EQ(withWholeGroups(curve, {{NodeKind::Opacity, 3}}).size(), 1u);
    EXPECT_EQ(groupNodes(curve, focus), 1);
    EXPECT_EQ(curve, original);
}

TEST(NodeEditing, DeletingRemovesExactlyTheSelectedNodes) {
    TransferFunction1D curve = figureOneTstf();
    deleteNodes(curve, {{NodeKind::Opacity, 0}, {NodeKind::Opacity, 6}, {NodeKind::Color, 5}});
    ASSERT_EQ(curve.opacity.size(), 5u);
    EXPECT_EQ(curve.opacity.front().at, 1.0);
    EXPECT_EQ(curve.opacity.back().at, 8.0);
    EXPECT_EQ(curve.color.size(), 5u);
}

TEST(NodeEditing, SingleNodesStayInsideTheAxisAndTheUnitRange) {
    const TransferFunction1D curve = figureOneTstf();
    const EditResult placed = placeOpacityNode(curve, 1, 12.0, 1.7, kTenTimeSteps);
    const NodeRef node = *placed.nodes.begin();
    EXPECT_EQ(positionOf(placed.curve, node), 9.0);
    EXPECT_EQ(placed.curve.opacity[node.index].opacity, 1.0);
    // Sorted again, and tracked: of the two nodes now at 9 the moved one came first in the list,
    // and the stable sort keeps it first.
    EXPECT_EQ(node.index, 5u);
    EXPECT_EQ(placed.curve.opacity[6].opacity, 0.35);
}

TEST(NodeEditing, AddedNodesLandInSortedOrder) {
    const TransferFunction1D curve = figureOneTstf();
    const EditResult added = addOpacityNode(curve, 5.5, 0.5, kTenTimeSteps);
    ASSERT_EQ(added.nodes.size(), 1u);
    EXPECT_EQ(added.nodes.begin()->index, 5u);
    EXPECT_EQ(added.curve.opacity[5].at, 5.5);
    EXPECT_EQ(added.curve.opacity[5].group, 0);
    const EditResult colour = addColorNode(curve, 6.0, {0.0, 1.0, 0.0}, kTenTimeSteps);
    EXPECT_EQ(colour.curve.color[colour.nodes.begin()->index].color, glm::dvec3(0.0, 1.0, 0.0));
}

}  // namespace
