// What the desktop, the package and the docs say of the formats the opener reads, made from the
// format table itself (src/data/readers/format_table.cpp), so that a format added there is offered
// for its files by the desktop, named in the package's description and listed everywhere without
// another change: the desktop entry (its MIME types and keywords), the MIME package that defines
// the types the desktop's own database lacks, and the package's description. The build writes them
// with the hidden `tstyles packaging-file` (tools/cmake/Install.cmake).
#pragma once

#include <string>
#include <vector>

namespace tstyles {

// A MIME type of a format's files. One that shared-mime-info already defines (image/tiff) has no
// comment; one of ours (application/x-nifti) has the comment our MIME package gives it, the
// format's extensions as its globs, and optionally shared-mime-info <match> elements that
// recognise the content.
struct FormatMimeType {
    std::string type;
    std::string comment;  // empty: the desktop's database defines the type
    std::string magic;    // for a type of ours: <match .../> elements, or empty
};

struct FormatListing {
    std::string name;                     // "NetCDF", "VTK"
    std::vector<std::string> extensions;  // lower case, with the dot
    std::vector<FormatMimeType> mimeTypes;
    std::string spelling;  // how its files look: ".nii .nii.gz", "a .zarr store folder, or its zarr.json"
};

// Every format of the table, in its order.
std::vector<FormatListing> seriesFormatListings();

// "NetCDF, NIfTI, ..., TIFF and Plot3D": every format's name, in the table's order.
std::string seriesFormatNames();

// What a command's dataset may be, for its help: a manifest, or each format's files as they look,
// or several files of one series.
std::string datasetKindsText();

// The desktop entry (share/applications/tstyles.desktop): every format's MIME types and name.
std::string desktopEntryText();
// The MIME package (share/mime/packages/tstyles.xml): the types of ours, the manifest's and the
// scene's among them.
std::string mimePackageText();
// The package's long description.
std::string packageDescriptionText();

}  // namespace tstyles
