// The lists of formats the desktop, the MIME database and the package see are made from the format
// table (tstyles/data/format_listing.h): every format's name and the MIME types of its files are in
// them, and each type of ours is defined with its extensions as globs.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

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

// How prose names a format: "Isabel" for "Hurricane Isabel raw", and "VTK" (the row's own name).
std::string shortName(const std::string& name) {
    if (name.find("Isabel") != std::string::npos) return "Isabel";
    if (name.rfind("VTK", 0) == 0) return "VTK";
    return name;
}

// The paragraphs of a Markdown file (blank lines apart).
std::vector<std::string> paragraphsOf(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::vector<std::string> paragraphs{""};
    for (std::string line; std::getline(in, line);) {
        if (line.find_first_not_of(" \t") == std::string::npos) {
            if (!paragraphs.back().empty()) paragraphs.emplace_back();
        } else {
            paragraphs.back() += line + "\n";
        }
    }
    return paragraphs;
}

// The runs of format names in `text` that read as one enumeration: each name follows the one before
// after a short qualifier and a separator ("NetCDF, NIfTI, NRRD, Plot3D and Hurricane Isabel",
// "TIFF (ImageJ, OME-TIFF), OME-Zarr"), with no table cell, sentence or clause between them.
std::vector<std::vector<std::string>> enumerationsIn(const std::string& text, const std::vector<std::string>& names) {
    std::vector<std::pair<std::size_t, std::string>> found;
    for (const std::string& name : names)
        for (std::size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + 1))
            found.emplace_back(at, name);
    std::sort(found.begin(), found.end());
    std::vector<std::vector<std::string>> runs;
    for (std::size_t i = 0; i < found.size(); ++i) {
        bool continues = false;
        if (i > 0 && found[i].first >= found[i - 1].first + found[i - 1].second.size()) {
            const std::size_t gapStart = found[i - 1].first + found[i - 1].second.size();
            const std::string gap = text.substr(gapStart, found[i].first - gapStart);
            const bool separated = gap.find(", ") != std::string::npos || gap.find(" and ") != std::string::npos ||
                                   gap.find(" or ") != std::string::npos;
            continues = separated && gap.size() <= 16 && gap.find_first_of("|;.:") == std::string::npos;
        }
        if (!continues) runs.emplace_back();
        runs.back().push_back(found[i].second);
    }
    return runs;
}

// A list of formats in the README or the docs (four names or more in one enumeration) names them
// all, or its paragraph does (bullets that group the readers): the help's and the package's lists
// come from the table, and this keeps the prose from going stale when a format is added (issue 53
// found 7 of 12 lists stale).
TEST(FormatListing, EveryListOfFormatsInTheDocsNamesEveryFormat) {
    const std::filesystem::path source(TSTYLES_SOURCE_DIR);
    std::vector<std::filesystem::path> documents{source / "README.md"};
    for (const auto& entry : std::filesystem::directory_iterator(source / "docs"))
        if (entry.path().extension() == ".md") documents.push_back(entry.path());
    std::vector<std::string> names;
    for (const FormatListing& format : seriesFormatListings()) names.push_back(shortName(format.name));
    for (const auto& document : documents)
        for (std::string paragraph : paragraphsOf(document)) {
            std::replace(paragraph.begin(), paragraph.end(), '\n', ' ');
            for (const std::vector<std::string>& run : enumerationsIn(paragraph, names)) {
                const std::set<std::string> listed(run.begin(), run.end());
                if (listed.size() < 4 || listed.size() == names.size()) continue;
                for (const std::string& name : names)
                    if (paragraph.find(name) == std::string::npos) {
                        ADD_FAILURE() << document.filename().string() << " lists formats without " << name << ":\n"
                                      << paragraph;
                        break;
                    }
            }
        }
    // The enumerations the test is meant to see, and what it leaves alone.
    EXPECT_EQ(enumerationsIn("NetCDF, NIfTI, NRRD, Plot3D and Hurricane Isabel files", names).front().size(), 5u);
    EXPECT_EQ(enumerationsIn("| NetCDF | x |\n| NIfTI | y |", names).size(), 2u);
    // And the help's list of what a dataset may be.
    const std::string kinds = datasetKindsText();
    for (const FormatListing& format : seriesFormatListings())
        EXPECT_NE(kinds.find(format.name + ": " + format.spelling), std::string::npos) << format.name;
}

}  // namespace
}  // namespace tstyles
