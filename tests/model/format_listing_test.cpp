// The lists of formats the desktop, the MIME database and the package see are made from the format
// table (tstyles/data/format_listing.h): every format's name and the MIME types of its files are in
// them, and each type of ours is defined with its extensions as globs.
#include <string>

#include <gtest/gtest.h>

#include "tstyles/data/format_listing.h"

namespace tstyles {
namespace {

std::string lineStartingWith(const std::string& text, const std::string& start) {
    const std::size_t at = text.find("\n" + start);
    if (at == std::string::npos) return {};
    return text.substr(at + 1, text.find('\n', at + 1) - at - 1);
}

TEST(FormatListing, TheDesktopEntryOffersTheProgramForEveryFormatsFiles) {
    const std::string entry = desktopEntryText();
    const std::string types = lineStartingWith(entry, "MimeType=");
    const std::string keywords = lineStartingWith(entry, "Keywords=");
    for (const FormatListing& format : seriesFormatListings()) {
        EXPECT_NE(keywords.find(format.name + ";"), std::string::npos) << format.name << " is not a keyword";
        for (const FormatMimeType& mime : format.mimeTypes)
            EXPECT_NE((";" + types.substr(9)).find(";" + mime.type + ";"), std::string::npos)
                << format.name << "'s " << mime.type << " is not in " << types;
    }
    // The files users double-click most, which the entry lacked before it was made from the table.
    for (const char* type : {"image/tiff;", "application/dicom;", "application/x-vtk-xml;", "application/x-netcdf;",
                             "application/x-nifti;", "application/x-tstyles-series;", "application/x-tstyles-scene;"})
        EXPECT_NE(types.find(type), std::string::npos) << type;
    EXPECT_NE(keywords.find("TIFF;"), std::string::npos);
    EXPECT_NE(keywords.find("OME-Zarr;"), std::string::npos);
}

TEST(FormatListing, TheMimePackageDefinesOurTypesWithTheirExtensions) {
    const std::string package = mimePackageText();
    for (const FormatListing& format : seriesFormatListings())
        for (const FormatMimeType& mime : format.mimeTypes) {
            const bool ours = !mime.comment.empty();
            EXPECT_EQ(package.find("type=\"" + mime.type + "\"") != std::string::npos, ours)
                << mime.type << (ours ? " is not defined" : " is the desktop's own and must not be redefined");
            if (!ours) continue;
            for (const std::string& extension : format.extensions)
                EXPECT_NE(package.find("<glob pattern=\"*" + extension + "\"/>"), std::string::npos) << extension;
        }
    EXPECT_NE(package.find("<match type=\"string\" offset=\"344\" value=\"n+1\"/>"), std::string::npos) << "NIfTI's magic";
}

TEST(FormatListing, TheDescriptionNamesEveryFormatInLinesOfAtMost79Characters) {
    const std::string description = packageDescriptionText();
    std::string flat = description;
    for (char& c : flat)
        if (c == '\n') c = ' ';
    for (const FormatListing& format : seriesFormatListings())
        EXPECT_NE(flat.find(format.name), std::string::npos) << format.name;
    std::size_t start = 0;
    for (std::size_t end = description.find('\n'); end != std::string::npos; end = description.find('\n', start)) {
        EXPECT_LE(end - start, 79u) << description.substr(start, end - start);
        start = end + 1;
    }
    EXPECT_EQ(seriesFormatNames().substr(0, 14), "NetCDF, NIfTI,");
}

}  // namespace
}  // namespace tstyles
