// Grouping and choosing series: a folder from a scanner often holds a scout, the 4D series and a
// few reformats; the choice is the user's, the default the series with the most frames.
#include "dicom_series.h"

#include <algorithm>
#include <map>
#include <optional>
#include <sstream>

#include "tstyles/core/errors.h"

namespace tstyles {

std::size_t DicomSeriesEntry::frameCount() const {
    std::size_t count = 0;
    for (const DicomImageFile& file : files) count += file.frames.size();
    return count;
}

std::string DicomSeriesEntry::describe(std::size_t number) const {
    const DicomImageFile& first = files.front();
    std::ostringstream text;
    text << "series " << number << ": UID " << (uid.empty() ? "(none)" : uid);
    if (first.seriesNumber) text << ", number " << *first.seriesNumber;
    if (!first.seriesDescription.empty()) text << ", \"" << first.seriesDescription << "\"";
    if (!first.modality.empty()) text << ", " << first.modality;
    text << ", " << files.size() << (files.size() == 1 ? " file" : " files") << " (" << frameCount() << " frames of "
         << first.columns << " x " << first.rows << ")";
    return text.str();
}

std::vector<DicomSeriesEntry> groupDicomSeries(std::vector<DicomImageFile> files) {
    std::map<std::string, DicomSeriesEntry> byUid;
    for (DicomImageFile& file : files) {
        if (file.frames.empty()) continue;
        DicomSeriesEntry& entry = byUid[file.seriesUid];
        entry.uid = file.seriesUid;
        entry.files.push_back(std::move(file));
    }
    std::vector<DicomSeriesEntry> series;
    for (auto& [uid, entry] : byUid) series.push_back(std::move(entry));
    // By SeriesNumber (series without one last), then UID: the order a scanner's console shows.
    std::stable_sort(series.begin(), series.end(), [](const DicomSeriesEntry& a, const DicomSeriesEntry& b) {
        const auto& na = a.files.front().seriesNumber;
        const auto& nb = b.files.front().seriesNumber;
        if (na.has_value() != nb.has_value()) return na.has_value();
        if (na && *na != *nb) return *na < *nb;
        return a.uid < b.uid;
    });
    return series;
}

bool DicomSeriesChoice::taken(std::size_t index) const {
    return std::find(indices.begin(), indices.end(), index) != indices.end();
}

std::size_t largestDicomSeries(const std::vector<DicomSeriesEntry>& series) {
    std::size_t largest = 0;
    for (std::size_t i = 1; i < series.size(); ++i)
        if (series[i].frameCount() > series[largest].frameCount()) largest = i;
    return largest;
}

namespace {

std::optional<std::size_t> seriesNumberOf(const std::string& text, std::size_t count) {
    const bool isNumber = !text.empty() && text.size() < 10 &&
                          std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (!isNumber) return std::nullopt;
    const std::size_t number = std::stoul(text);
    if (number < 1 || number > count) return std::nullopt;
    return number - 1;
}

[[noreturn]] void refuseChoice(const std::vector<DicomSeriesEntry>& series, const std::string& choice,
                               const std::filesystem::path& input, const std::string& problem) {
    std::string available;
    for (std::size_t i = 0; i < series.size(); ++i)
        available += (i == 0 ? "" : "; ") + std::to_string(i + 1) + " (UID " + series[i].uid + ")";
    throwInputError(input, "--series",
                    "\"" + choice + "\" " + problem + ": give a number from 1 to " + std::to_string(series.size()) +
                        ", numbers separated by commas, all, or a SeriesInstanceUID: " + available);
}

}  // namespace

DicomSeriesChoice chooseDicomSeries(const std::vector<DicomSeriesEntry>& series, const std::string& choice,
                                    const std::filesystem::path& input) {
    if (choice.empty()) return {};
    if (choice == "all") {
        DicomSeriesChoice all{{}, "--series all"};
        for (std::size_t i = 0; i < series.size(); ++i) all.indices.push_back(i);
        return all;
    }
    if (const auto number = seriesNumberOf(choice, series.size())) return {{*number}, "--series " + choice};
    for (std::size_t i = 0; i < series.size(); ++i)
        if (series[i].uid == choice) return {{i}, "--series " + choice};
    if (choice.find(',') == std::string::npos) refuseChoice(series, choice, input, "names no series here");
    DicomSeriesChoice list{{}, "--series " + choice};
    std::size_t start = 0;
    while (start <= choice.size()) {
        const std::size_t end = std::min(choice.find(',', start), choice.size());
        const auto number = seriesNumberOf(choice.substr(start, end - start), series.size());
        if (!number) refuseChoice(series, choice, input, "has \"" + choice.substr(start, end - start) + "\", no series here");
        if (list.taken(*number)) refuseChoice(series, choice, input, "names series " + std::to_string(*number + 1) + " twice");
        list.indices.push_back(*number);
        start = end + 1;
    }
    return list;
}

}  // namespace tstyles
