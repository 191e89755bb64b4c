// Editing transfer-function nodes as the editors do it: selections, groups, deletes and moves that
// keep a group's shape. No ImGui and no OpenGL here, so every rule is unit-tested on plain curves.
#pragma once

#include <compare>
#include <cstddef>
#include <set>

#include <glm/glm.hpp>

#include "tstyles/scene/transfer_function.h"

namespace tstyles::viewer {

enum class NodeKind { Opacity, Color };

// One node of a curve: which list, which index (indices follow the sorted order of the curve).
struct NodeRef {
    NodeKind kind = NodeKind::Opacity;
    std::size_t index = 0;
    auto operator<=>(const NodeRef&) const = default;
};

using NodeSelection = std::set<NodeRef>;

// The axis a curve lives on. An index TSTF's axis counts time-steps (0 .. n-1) and moves of
// several nodes snap to whole time-steps there, so that moving a group moves the focus in time.
struct CurveAxis {
    double min = 0.0;
    double max = 1.0;
    bool timeSteps = false;
};

double positionOf(const TransferFunction1D& curve, NodeRef node);
NodeGroup groupOf(const TransferFunction1D& curve, NodeRef node);
bool isValid(const TransferFunction1D& curve, NodeRef node);

// Every node of the curve, opacity nodes first.
NodeSelection allNodes(const TransferFunction1D& curve);

// The selection plus every node that shares a group with a selected node: a group is picked,
// moved and deleted as a whole.
NodeSelection withWholeGroups(const TransferFunction1D& curve, const NodeSelection& selection);

// The smallest group number no node of the curve uses.
NodeGroup unusedGroup(const TransferFunction1D& curve);

// Puts the nodes into one new group and returns its number (0 if fewer than two nodes were given:
// a group of one would only be a marker). Nodes leave whatever group they were in.
NodeGroup groupNodes(TransferFunction1D& curve, const NodeSelection& nodes);
void ungroupNodes(TransferFunction1D& curve, const NodeSelection& nodes);
void deleteNodes(TransferFunction1D& curve, const NodeSelection& nodes);

// A curve after an edit, and where the edited nodes are in it now (edits re-sort the nodes).
struct EditResult {
    TransferFunction1D curve;
    NodeSelection nodes;
};

// The shift a set of nodes may make along the axis: on a time-step axis rounded to whole
// time-steps first; then limited so that the set stops at the axis ends instead of being squeezed
// (a group clips at the first and last time-step without deforming).
double allowedShift(const TransferFunction1D& curve, const NodeSelection& nodes, double shift,
                    const CurveAxis& axis);

// Moves the nodes by allowedShift(shift) along the axis; their values (opacity, colour) stay.
EditResult shiftNodes(const TransferFunction1D& curve, const NodeSelection& nodes, double shift,
                      const CurveAxis& axis);

// Places one opacity node at (at, opacity), clamped to the axis and to [0, 1].
EditResult placeOpacityNode(const TransferFunction1D& curve, std::size_t index, double at, double opacity,
                            const CurveAxis& axis);
// Places one colour node at `at` (clamped to the axis).
EditResult placeColorNode(const TransferFunction1D& curve, std::size_t index, double at, const CurveAxis& axis);

// New nodes (in no group), placed in sorted order; returns the curve and the new node.
EditResult addOpacityNode(const TransferFunction1D& curve, double at, double opacity, const CurveAxis& axis);
EditResult addColorNode(const TransferFunction1D& curve, double at, const glm::dvec3& color, const CurveAxis& axis);

}  // namespace tstyles::viewer
