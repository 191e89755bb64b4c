// OME-TIFF: the OME-XML in the first ImageDescription names the planes' IFDs, sizes and times.
#pragma once

#include <vector>

#include "ome_xml.h"
#include "tiff_layout.h"

namespace tstyles {

// The first Image that is a volume over time (else the first volume), the channel asked for.
TiffLayout omeLayout(TiffFile& tiff, std::vector<TiffPage> pages, const std::vector<OmeImage>& images,
                     const ReadOptions& options);

}  // namespace tstyles
