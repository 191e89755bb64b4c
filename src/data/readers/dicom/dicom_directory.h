// A DICOMDIR, the index of a CD or USB export (PS3.10 media): the files its directory records
// reference, so that choosing the DICOMDIR opens the series it lists, as choosing its folder does.
#pragma once

#include <cstddef>
#include <filesystem>
#include <vector>

namespace tstyles {

// True for a file named DICOMDIR (any case): the name PS3.10 gives the index on every medium.
bool isDicomDirectoryFile(const std::filesystem::path& file);

struct DicomDirectoryFiles {
    std::vector<std::filesystem::path> files;  // each referenced file once, sorted by path
    std::size_t records = 0;                   // directory records read (patients, studies, series, images ...)
};

// The files the DICOMDIR's records reference (ReferencedFileID, (0004,1500)), found from its folder;
// each path component matched without regard to case where the exact name is not there (a CD
// mounted on Linux often shows ISO 9660's upper-case names in lower case). A record naming a file
// that is not there, a component that climbs out of the folder, or no referenced file at all is an
// InputError naming the DICOMDIR and the record.
DicomDirectoryFiles filesOfDicomDirectory(const std::filesystem::path& dicomdir);

}  // namespace tstyles
