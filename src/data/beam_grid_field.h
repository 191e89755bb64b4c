// Reading a beam (sonar) grid from a manifest's "grid" object, with every check a bad grid needs.
#pragma once

#include "grid_dims_field.h"
#include "tstyles/data/series.h"

namespace tstyles {

// `field` is the grid object (its type already known to be "beam"). Fails on a missing or unknown
// key, fewer than two samples along an axis, zero or negative extents, beam angles that do not
// increase strictly, a list whose length differs from dims, angles outside (-80, 80) degrees, or a
// range that does not satisfy 0 <= minimum < maximum.
BeamGrid readBeamGrid(const JsonField& field);

}  // namespace tstyles
