// OME-TIFF: the OME-XML in the first ImageDescription names the planes' IFDs, sizes and times.
#pragma once

#include <cstdint>
#include <vector>

#include "ome_xml.h"
#include "tiff_layout.h"

namespace tstyles {

// The first Image that is a volume over time (else the first volume), the channel asked for. Planes
// that the TiffData put in other files beside `tiff` are read from there; `cap` bounds each file's
// allocations as `tiff`'s.
TiffLayout omeLayout(TiffFile& tiff, std::vector<TiffPage> pages, const std::vector<OmeImage>& images,
                     const ReadOptions& options, std::uint64_t cap);

}  // namespace tstyles
