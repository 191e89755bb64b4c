// The two ways ParaView lists a time series of VTK files: a .pvd collection (XML) and a .series
// file (JSON). Both become (time, file) entries in time order, the files checked to exist.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace tstyles {

struct VtkCollectionEntry {
    double time = 0.0;
    std::filesystem::path file;
    std::string where;  // the entry in the list, for messages: "DataSet (line 4)", "files[2]"
};

struct VtkCollection {
    std::vector<VtkCollectionEntry> entries;
    std::vector<std::string> notes;  // choices made: parts left out, entries reordered by time
};

// <VTKFile type="Collection"><Collection><DataSet timestep part file/>...: files relative to the
// .pvd; of several parts at one time, part 0 is read (a note says so).
VtkCollection readPvdCollection(const std::filesystem::path& pvd);

// {"file-series-version": "1.0", "files": [{"name": ..., "time": ...}, ...]}.
VtkCollection readFileSeries(const std::filesystem::path& series);

}  // namespace tstyles
