// The fields of a NRRD header (http://teem.sourceforge.net/nrrd/format.html) that a volume series
// needs, parsed and checked. Fields we do not use are skipped; fields we cannot honour are errors.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "../../value_decoding.h"
#include "../file_bytes.h"
#include "tstyles/data/series.h"

namespace tstyles {

struct NrrdHeader {
    std::filesystem::path headerFile;
    ValueType type = ValueType::Float32;
    int dimension = 0;
    std::vector<std::int64_t> sizes;
    DataEncoding encoding = DataEncoding::Raw;
    ByteOrder byteOrder = ByteOrder::Little;
    std::filesystem::path dataFile;  // the header file itself when the data is attached
    std::uint64_t dataOffset = 0;    // where the data starts in dataFile (after line and byte skips)
    bool dataAtEnd = false;          // byte skip -1: the data are the file's last bytes
    // Per axis: the world step of one voxel (space directions), or none for a non-spatial axis.
    std::vector<std::optional<glm::dvec3>> directions;
    std::optional<glm::dvec3> origin;
    std::vector<double> spacings;    // per axis, NaN where not given
    std::vector<double> axisMins;    // per axis, NaN where not given
    std::vector<std::string> kinds;  // per axis, empty when not given
    std::string space;               // "right-anterior-superior", "LPS", ...; empty when not given
    std::vector<std::string> spaceUnits;  // per world axis ("mm"), empty when not given
};

// Reads and checks the header of a .nrrd (attached data) or .nhdr (detached data) file.
NrrdHeader readNrrdHeader(const std::filesystem::path& file);

}  // namespace tstyles
