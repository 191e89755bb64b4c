// .pvd and .series lists: the entries' times must be finite and, once sorted, distinct (a time-step
// is one volume); every file must exist before any is read.
#include "vtk_collection.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>

#include <nlohmann/json.hpp>
#include <pugixml.hpp>

#include "../series_assembly.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/json_field.h"
#include "tstyles/core/json_text.h"
#include "tstyles/core/input_limits.h"

namespace tstyles {
namespace {

// Sorted by time as ParaView shows them; two entries at one time would be two volumes in one step.
void orderByTime(const std::filesystem::path& list, VtkCollection& collection) {
    auto& entries = collection.entries;
    if (entries.empty()) throwInputError(list, "", "lists no data set: there is nothing to read");
    requireStepCount(list, "", entries.size());
    const auto earlier = [](const VtkCollectionEntry& a, const VtkCollectionEntry& b) { return a.time < b.time; };
    if (!std::is_sorted(entries.begin(), entries.end(), earlier)) {
        std::stable_sort(entries.begin(), entries.end(), earlier);
        collection.notes.push_back("the list is not in time order: its data sets are read sorted by time");
    }
    for (std::size_t index = 1; index < entries.size(); ++index)
        if (entries[index].time == entries[index - 1].time)
            throwInputError(list, entries[index].where,
                            "time " + std::to_string(entries[index].time) + " is also the time of " +
                                entries[index - 1].where + ": one data set per time-step");
    for (const VtkCollectionEntry& entry : entries) {
        std::error_code error;
        if (!std::filesystem::is_regular_file(entry.file, error))
            throwInputError(list, entry.where, "the file '" + entry.file.string() + "' does not exist");
    }
}

std::size_t lineAt(const std::string& text, std::ptrdiff_t offset) {
    if (offset < 0 || std::size_t(offset) > text.size()) return 0;
    return 1 + std::size_t(std::count(text.begin(), text.begin() + offset, '\n'));
}

std::string readSmallText(const std::filesystem::path& path, const std::string& what) {
    // A list of file names: even a million time-steps is far below this.
    constexpr std::uint64_t kMaxListBytes = std::uint64_t(256) << 20;
    const std::uint64_t size = regularFileSize(path, what);
    if (size > kMaxListBytes)
        throwInputError(path, "", "is " + byteCountText(double(size)) + ", too large for a " + what);
    std::ifstream in(path, std::ios::binary);
    std::string text(size, '\0');
    in.read(text.data(), std::streamsize(size));
    if (!in) throwInputError(path, "", "cannot be read");
    return text;
}

}  // namespace

VtkCollection readPvdCollection(const std::filesystem::path& pvd) {
    const std::string text = readSmallText(pvd, "ParaView collection (.pvd)");
    pugi::xml_document document;
    const pugi::xml_parse_result parsed = document.load_buffer(text.data(), text.size());
    if (!parsed)
        throwInputError(pvd, "", std::string("bad XML at byte ") + std::to_string(parsed.offset) + ": " +
                                     parsed.description());
    const pugi::xml_node root = document.child("VTKFile");
    if (!root || std::string(root.attribute("type").as_string()) != "Collection" || !root.child("Collection"))
        throwInputError(pvd, "VTKFile", "is not a ParaView collection: <VTKFile type=\"Collection\"><Collection> expected");
    VtkCollection collection;
    std::set<int> parts;
    for (const pugi::xml_node& dataSet : root.child("Collection").children("DataSet")) {
        const std::string where = "DataSet (line " + std::to_string(lineAt(text, dataSet.offset_debug())) + ")";
        const std::string file = dataSet.attribute("file").as_string();
        if (file.empty()) throwInputError(pvd, where, "has no file attribute");
        if (!dataSet.attribute("timestep")) throwInputError(pvd, where, "has no timestep attribute");
        const char* timeText = dataSet.attribute("timestep").as_string();
        char* timeEnd = nullptr;
        const double time = std::strtod(timeText, &timeEnd);
        while (timeEnd && std::isspace(static_cast<unsigned char>(*timeEnd))) ++timeEnd;
        if (timeEnd == timeText || *timeEnd != '\0' || !std::isfinite(time))
            throwInputError(pvd, where, "timestep '" + std::string(dataSet.attribute("timestep").as_string()) +
                                            "' is not a finite number");
        const int part = dataSet.attribute("part").as_int(0);
        parts.insert(part);
        if (part != 0) continue;
        collection.entries.push_back({time, pvd.parent_path() / file, where});
    }
    if (parts.size() > 1)
        collection.notes.push_back("the collection has " + std::to_string(parts.size()) +
                                   " parts at each time: only part 0 is read");
    orderByTime(pvd, collection);
    return collection;
}

VtkCollection readFileSeries(const std::filesystem::path& series) {
    const std::string text = readSmallText(series, "ParaView file series (.series)");
    const nlohmann::json json = parseJsonText(text, series, JsonComments::Refused);
    const JsonField root(series, json, "");
    root.allowOnlyKeys({"file-series-version", "files"});
    root.member("file-series-version").string();
    const JsonField files = root.member("files");
    VtkCollection collection;
    for (std::size_t index = 0; index < files.arraySize(); ++index) {
        const JsonField entry = files.element(index);
        entry.allowOnlyKeys({"name", "time"});
        const std::string name = entry.member("name").pathName();
        if (name.empty()) entry.failAt("name", "is empty, not a file name");
        collection.entries.push_back({entry.member("time").finiteNumber(), series.parent_path() / name, entry.path()});
    }
    orderByTime(series, collection);
    return collection;
}

}  // namespace tstyles
