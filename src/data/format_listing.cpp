// The desktop entry, the MIME package and the package description, from the format table.
#include "tstyles/data/format_listing.h"

#include <set>
#include <sstream>

#include "readers/format_table.h"

namespace tstyles {
namespace {

// What every desktop list holds besides the formats: our own manifest and scene files.
constexpr const char* kOwnMimeTypes[] = {"application/x-tstyles-series", "application/x-tstyles-scene"};

// The MIME types of every format, each once, in the table's order.
std::vector<std::string> formatMimeTypes() {
    std::vector<std::string> types;
    std::set<std::string> seen;
    for (const FormatListing& format : seriesFormatListings())
        for (const FormatMimeType& mime : format.mimeTypes)
            if (seen.insert(mime.type).second) types.push_back(mime.type);
    return types;
}

}  // namespace

std::vector<FormatListing> seriesFormatListings() {
    std::vector<FormatListing> listings;
    for (const SeriesFormat& format : seriesFormats())
        listings.push_back({format.name, format.extensions, format.mimeTypes, format.spelling});
    return listings;
}

std::string datasetKindsText() {
    std::string text = "a manifest (series.json) or its folder; ";
    for (const FormatListing& format : seriesFormatListings()) text += format.name + ": " + format.spelling + "; ";
    return text + "or several files of one series (Isabel hours, 3D volumes in time order)";
}

std::string seriesFormatNames() {
    const std::vector<FormatListing> formats = seriesFormatListings();
    std::string names;
    for (std::size_t i = 0; i < formats.size(); ++i) {
        if (i > 0) names += i + 1 == formats.size() ? " and " : ", ";
        names += formats[i].name;
    }
    return names;
}

std::string desktopEntryText() {
    std::ostringstream out;
    out << "[Desktop Entry]\n"
           "Type=Application\n"
           "Name=Temporal Styles\n"
           "GenericName=Time-Varying Volume Viewer\n"
           "Comment=Render time-varying volume data with temporal style transfer functions\n"
           "Exec=tstyles view %F\n"
           "Icon=tstyles\n"
           "Terminal=false\n"
           "Categories=Science;DataVisualization;\n"
           "MimeType=";
    for (const std::string& type : formatMimeTypes()) out << type << ";";
    for (const char* type : kOwnMimeTypes) out << type << ";";
    out << "\nKeywords=volume;time-varying;raycasting;";
    for (const FormatListing& format : seriesFormatListings()) out << format.name << ";";
    out << "\n";
    return out.str();
}

std::string mimePackageText() {
    std::ostringstream out;
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
           "<!-- Written by `tstyles packaging-file mime-package` from the format table: do not edit. The types of\n"
           "     the files tstyles opens that shared-mime-info has none for; installed as\n"
           "     share/mime/packages/tstyles.xml (docs/install.md). -->\n"
           "<mime-info xmlns=\"http://www.freedesktop.org/standards/shared-mime-info\">\n";
    for (const FormatListing& format : seriesFormatListings())
        for (const FormatMimeType& mime : format.mimeTypes) {
            if (mime.comment.empty()) continue;  // the desktop's database has it
            out << "  <mime-type type=\"" << mime.type << "\">\n    <comment>" << mime.comment << "</comment>\n";
            for (const std::string& extension : format.extensions)
                out << "    <glob pattern=\"*" << extension << "\"/>\n";
            if (!mime.magic.empty()) out << "    <magic priority=\"50\">" << mime.magic << "</magic>\n";
            out << "  </mime-type>\n";
        }
    // The manifest is JSON whose "format" is "tstyles-series" (docs/dataset-format.md); a scene
    // (docs/scene-format.md) names its "dataset" and its "camera", after comment lines.
    out << "  <mime-type type=\"application/x-tstyles-series\">\n"
           "    <comment>Temporal Styles series manifest</comment>\n"
           "    <sub-class-of type=\"application/json\"/>\n"
           "    <magic priority=\"60\"><match type=\"string\" offset=\"0:512\" value=\"&quot;tstyles-series&quot;\"/>"
           "</magic>\n"
           "    <glob pattern=\"series.json\" weight=\"60\"/>\n"
           "  </mime-type>\n"
           "  <mime-type type=\"application/x-tstyles-scene\">\n"
           "    <comment>Temporal Styles scene</comment>\n"
           "    <sub-class-of type=\"application/json\"/>\n"
           "    <magic priority=\"55\"><match type=\"string\" offset=\"0:4096\" value=\"&quot;dataset&quot;\">"
           "<match type=\"string\" offset=\"0:4096\" value=\"&quot;camera&quot;\"/></match></magic>\n"
           "  </mime-type>\n"
           "</mime-info>\n";
    return out.str();
}

std::string packageDescriptionText() {
    const std::string text = "tstyles renders time-varying volume data (" + seriesFormatNames() +
                             " files, and its own manifests) with temporal compositors and temporal style transfer "
                             "functions, from the command line, in a window, or from Python (import tstyles).";
    // Lines of at most 79 characters, as a package's description has them.
    std::string wrapped, line;
    std::istringstream words(text);
    for (std::string word; words >> word;) {
        if (!line.empty() && line.size() + 1 + word.size() > 79) {
            wrapped += line + "\n";
            line.clear();
        }
        line += (line.empty() ? "" : " ") + word;
    }
    return wrapped + line + "\n";
}

}  // namespace tstyles
