// The super-ellipsoid itself: its implicit function, the smooth density shell around its surface,
// and how far it reaches below its centre when turned about z (for the floor contact).
#pragma once

#include <glm/glm.hpp>

namespace superellipsoid {

struct SuperEllipsoidShape {
    // Half-sizes along the object's own axes: about half a metre across, a rounded box.
    glm::dvec3 halfAxes{0.25, 0.18, 0.20};
    // Squareness exponents of the classic form: e1 shapes the z profile, e2 the xy cross-section.
    // 0.5 gives flat faces with well-rounded edges, clearly neither a box nor an ellipsoid.
    double e1 = 0.5;
    double e2 = 0.5;
    // The density falls from 1 to 0 between these values of the gauge, so the 0.5 iso-surface is
    // the super-ellipsoid's surface and the falloff spans several voxels (smooth gradients).
    double shellInner = 0.85;
    double shellOuter = 1.15;

    // 1 on the surface, 0 at the centre, and linear along every ray from the centre (the implicit
    // function raised to e1/2), so shell widths are proportional to the object's size.
    double gauge(const glm::dvec3& local) const;

    // 1 inside, smooth falloff across the shell, exactly 0 from the shell's outer edge on.
    double density(const glm::dvec3& local) const;

    // Half-size of the object-local box outside which the density is exactly 0.
    glm::dvec3 nonZeroHalfExtents() const { return shellOuter * halfAxes; }

    // How far the surface reaches below the centre when the object is turned by `angle` radians
    // about z: the support function of the xy cross-section, which is the widest one.
    double depthBelowCentre(double angle) const;
};

}  // namespace superellipsoid
