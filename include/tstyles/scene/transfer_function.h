// Transfer functions as data: an opacity curve and a colour curve over one axis (density for the
// STF, time-step index for the index TSTF, change for the gradient-magnitude TSTF). GL-free; the
// renderer bakes them into lookup tables.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace tstyles {

// Nodes that share a group number (> 0) move together in the editor; 0 is no group.
using NodeGroup = int;

struct OpacityNode {
    double at = 0.0;
    double opacity = 0.0;
    NodeGroup group = 0;
    bool operator==(const OpacityNode&) const = default;
};

// A colour node is a flat colour, or a lit-sphere style (by built-in name or image path) whose
// lookup is tinted by `color`.
struct ColorNode {
    double at = 0.0;
    glm::dvec3 color{1.0};
    std::string style;  // empty: a flat colour
    NodeGroup group = 0;
    bool operator==(const ColorNode&) const = default;
};

struct ColorOpacity {
    glm::dvec3 color{0.0};
    double opacity = 0.0;
};

// Piecewise-linear colour and opacity; nodes kept sorted by `at`. Outside the first and last node
// the end values hold. With no opacity node the opacity is 0; with no colour node the colour is white.
struct TransferFunction1D {
    std::vector<OpacityNode> opacity;
    std::vector<ColorNode> color;

    ColorOpacity evaluate(double x) const;
    void sortNodes();
    bool operator==(const TransferFunction1D&) const = default;
};

// Time-invariant style transfer function over density in [0,1].
struct Stf {
    TransferFunction1D curve;
    bool operator==(const Stf&) const = default;
};

// Time-step index TSTF: node positions are in time-step units (0 .. n-1), so that moving a node
// by 1 moves it by one time-step; time-step i takes the curve's value at i.
struct IndexTstf {
    TransferFunction1D curve;
    ColorOpacity atStep(int step) const { return curve.evaluate(double(step)); }
    bool operator==(const IndexTstf&) const = default;
};

// Gradient-magnitude TSTF: the temporal change (max - min density) is mapped from `range` to [0,1]
// (clamped) and the curve is read there.
struct GradientTstf {
    TransferFunction1D curve;
    double rangeLow = 0.0;
    double rangeHigh = 1.0;
    // Scene value "auto": the range is fitted to the change present in the data each time the scene
    // meets a series (resolveAutomaticParts, tstyles/scene/automatic_scene.h).
    bool automaticRange = false;
    double normalize(double change) const;
    bool operator==(const GradientTstf&) const = default;
};

// The defaults a scene starts from (docs/scene-format.md): the STF is an opacity ramp from
// (0, 0) to (1, 1) in white; both TSTFs are opacity 1 and white everywhere, which leaves the STF
// unchanged under modulation.
Stf defaultStf();
IndexTstf defaultIndexTstf();
GradientTstf defaultGradientTstf();

}  // namespace tstyles
