// Node edits on plain curves: groups, deletes and shape-keeping moves with stable re-sorting.
#include "node_editing.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

namespace tstyles::viewer {
namespace {

// Stable-sorts one node list by position and tells where each old index went, so a selection
// survives the re-sort (two nodes at one position keep their order: it says which side of a step
// each is on).
template <typename Node>
std::vector<std::size_t> sortAndTrack(std::vector<Node>& nodes) {
    std::vector<std::size_t> order(nodes.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return nodes[a].at < nodes[b].at; });
    std::vector<Node> sorted;
    sorted.reserve(nodes.size());
    std::vector<std::size_t> newIndexOf(nodes.size());
    for (std::size_t position = 0; position < order.size(); ++position) {
        sorted.push_back(nodes[order[position]]);
        newIndexOf[order[position]] = position;
    }
    nodes = std::move(sorted);
    return newIndexOf;
}

EditResult sortKeepingSelection(TransferFunction1D curve, const NodeSelection& nodes) {
    const std::vector<std::size_t> opacityMap = sortAndTrack(curve.opacity);
    const std::vector<std::size_t> colorMap = sortAndTrack(curve.color);
    EditResult result{std::move(curve), {}};
    for (const NodeRef& node : nodes) {
        const auto& map = node.kind == NodeKind::Opacity ? opacityMap : colorMap;
        if (node.index < map.size()) result.nodes.insert({node.kind, map[node.index]});
    }
    return result;
}

double& positionRef(TransferFunction1D& curve, NodeRef node) {
    return node.kind == NodeKind::Opacity ? curve.opacity[node.index].at : curve.color[node.index].at;
}

NodeGroup& groupRef(TransferFunction1D& curve, NodeRef node) {
    return node.kind == NodeKind::Opacity ? curve.opacity[node.index].group : curve.color[node.index].group;
}

}  // namespace

bool isValid(const TransferFunction1D& curve, NodeRef node) {
    return node.index < (node.kind == NodeKind::Opacity ? curve.opacity.size() : curve.color.size());
}

double positionOf(const TransferFunction1D& curve, NodeRef node) {
    return node.kind == NodeKind::Opacity ? curve.opacity.at(node.index).at : curve.color.at(node.index).at;
}

NodeGroup groupOf(const TransferFunction1D& curve, NodeRef node) {
    return node.kind == NodeKind::Opacity ? curve.opacity.at(node.index).group : curve.color.at(node.index).group;
}

NodeSelection allNodes(const TransferFunction1D& curve) {
    NodeSelection all;
    for (std::size_t i = 0; i < curve.opacity.size(); ++i) all.insert({NodeKind::Opacity, i});
    for (std::size_t i = 0; i < curve.color.size(); ++i) all.insert({NodeKind::Color, i});
    return all;
}

NodeSelection withWholeGroups(const TransferFunction1D& curve, const NodeSelection& selection) {
    std::set<NodeGroup> groups;
    for (const NodeRef& node : selection)
        if (isValid(curve, node) && groupOf(curve, node) > 0) groups.insert(groupOf(curve, node));
    NodeSelection result;
    for (const NodeRef& node : selection)
        if (isValid(curve, node)) result.insert(node);
    if (groups.empty()) return result;
    for (const NodeRef& node : allNodes(curve))
        if (groups.contains(groupOf(curve, node))) result.insert(node);
    return result;
}

NodeGroup unusedGroup(const TransferFunction1D& curve) {
    std::set<NodeGroup> used;
    for (const NodeRef& node : allNodes(curve)) used.insert(groupOf(curve, node));
    NodeGroup candidate = 1;
    while (used.contains(candidate)) ++candidate;
    return candidate;
}

NodeGroup groupNodes(TransferFunction1D& curve, const NodeSelection& nodes) {
    NodeSelection valid;
    for (const NodeRef& node : nodes)
        if (isValid(curve, node)) valid.insert(node);
    if (valid.size() < 2) return 0;
    const NodeGroup group = unusedGroup(curve);
    for (const NodeRef& node : valid) groupRef(curve, node) = group;
    return group;
}

void ungroupNodes(TransferFunction1D& curve, const NodeSelection& nodes) {
    for (const NodeRef& node : nodes)
        if (isValid(curve, node)) groupRef(curve, node) = 0;
}

void deleteNodes(TransferFunction1D& curve, const NodeSelection& nodes) {
    // From the back, so the indices still to be erased stay valid.
    for (auto node = nodes.rbegin(); node != nodes.rend(); ++node) {
        if (!isValid(curve, *node)) continue;
        if (node->kind == NodeKind::Opacity)
            curve.opacity.erase(curve.opacity.begin() + std::ptrdiff_t(node->index));
        else
            curve.color.erase(curve.color.begin() + std::ptrdiff_t(node->index));
    }
}

double allowedShift(const TransferFunction1D& curve, const NodeSelection& nodes, double shift,
                    const CurveAxis& axis) {
    double lowest = std::numeric_limits<double>::infinity();
    double highest = -std::numeric_limits<double>::infinity();
    for (const NodeRef& node : nodes) {
        if (!isValid(curve, node)) continue;
        lowest = std::min(lowest, positionOf(curve, node));
        highest = std::max(highest, positionOf(curve, node));
    }
    if (lowest > highest) return 0.0;
    double down = axis.min - lowest;  // the most the set may move toward the start (<= 0)
    double up = axis.max - highest;   // the most it may move toward the end (>= 0)
    if (axis.timeSteps) {
        shift = std::round(shift);
        down = std::ceil(down - 1e-9);
        up = std::floor(up + 1e-9);
    }
    // A set already wider than the axis (a hand-edited file) may not move at all.
    if (down > up) return 0.0;
    return std::clamp(shift, std::min(down, 0.0), std::max(up, 0.0));
}

EditResult shiftNodes(const TransferFunction1D& curve, const NodeSelection& nodes, double shift,
                      const CurveAxis& axis) {
    const double allowed = allowedShift(curve, nodes, shift, axis);
    TransferFunction1D moved = curve;
    for (const NodeRef& node : nodes)
        if (isValid(moved, node)) positionRef(moved, node) += allowed;
    return sortKeepingSelection(std::move(moved), nodes);
}

EditResult placeOpacityNode(const TransferFunction1D& curve, std::size_t index, double at, double opacity,
                            const CurveAxis& axis) {
    TransferFunction1D moved = curve;
    OpacityNode& node = moved.opacity.at(index);
    node.at = std::clamp(at, axis.min, axis.max);
    node.opacity = std::clamp(opacity, 0.0, 1.0);
    return sortKeepingSelection(std::move(moved), {{NodeKind::Opacity, index}});
}

EditResult placeColorNode(const TransferFunction1D& curve, std::size_t index, double at, const CurveAxis& axis) {
    TransferFunction1D moved = curve;
    moved.color.at(index).at = std::clamp(at, axis.min, axis.max);
    return sortKeepingSelection(std::move(moved), {{NodeKind::Color, index}});
}

EditResult addOpacityNode(const TransferFunction1D& curve, double at, double opacity, const CurveAxis& axis) {
    TransferFunction1D added = curve;
    added.opacity.push_back({std::clamp(at, axis.min, axis.max), std::clamp(opacity, 0.0, 1.0), 0});
    const NodeRef newNode{NodeKind::Opacity, added.opacity.size() - 1};
    return sortKeepingSelection(std::move(added), {newNode});
}

EditResult addColorNode(const TransferFunction1D& curve, double at, const glm::dvec3& color, const CurveAxis& axis) {
    TransferFunction1D added = curve;
    ColorNode node;
    node.at = std::clamp(at, axis.min, axis.max);
    node.color = glm::clamp(color, glm::dvec3(0.0), glm::dvec3(1.0));
    added.color.push_back(node);
    const NodeRef newNode{NodeKind::Color, added.color.size() - 1};
    return sortKeepingSelection(std::move(added), {newNode});
}

}  // namespace tstyles::viewer
