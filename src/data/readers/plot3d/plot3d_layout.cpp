// Finding a Plot3D file's layout: parse the header under each guess of byte order, record markers
// and block count, then accept the precision and IBLANK whose data size matches the file exactly.
#include "plot3d_layout.h"

#include <bit>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <system_error>

#include "../../value_decoding.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"

namespace tstyles {
namespace {

constexpr std::int64_t kMaxBlocks = 100000;
constexpr std::int64_t kMaxNodesPerBlock = std::int64_t(1) << 32;

std::uint64_t readUnsigned(const std::vector<std::uint8_t>& bytes, std::size_t offset, int size, bool bigEndian) {
    return decodeUnsigned(bytes.data() + offset, std::size_t(size), bigEndian ? ByteOrder::Big : ByteOrder::Little);
}

std::int32_t readInt(const std::vector<std::uint8_t>& bytes, std::size_t offset, bool bigEndian) {
    return std::bit_cast<std::int32_t>(std::uint32_t(readUnsigned(bytes, offset, 4, bigEndian)));
}

// A guess of the framing (byte order, markers, block count) with the header it implies.
struct HeaderGuess {
    bool bigEndian = false;
    bool records = false;
    bool multiBlock = false;
    std::vector<glm::ivec3> dims;
    std::vector<int> functionCounts;  // function files only
    std::size_t dataStart = 0;  // first byte after the header
};

constexpr int kMaxFunctions = 10000;

// Reads `count` ints at `offset`, framed by markers when `records`; nothing if they do not fit.
std::optional<std::vector<std::int32_t>> readIntRecord(const std::vector<std::uint8_t>& bytes, std::size_t& offset,
                                                       std::size_t count, bool records, bool bigEndian) {
    const std::size_t payload = count * 4;
    const std::size_t framed = payload + (records ? 8 : 0);
    if (offset + framed > bytes.size()) return std::nullopt;
    if (records) {
        if (readInt(bytes, offset, bigEndian) != std::int32_t(payload)) return std::nullopt;
        if (readInt(bytes, offset + 4 + payload, bigEndian) != std::int32_t(payload)) return std::nullopt;
    }
    std::vector<std::int32_t> values;
    for (std::size_t index = 0; index < count; ++index)
        values.push_back(readInt(bytes, offset + (records ? 4 : 0) + index * 4, bigEndian));
    offset += framed;
    return values;
}

std::optional<HeaderGuess> parseHeader(const std::vector<std::uint8_t>& bytes, bool bigEndian, bool records,
                                       bool multiBlock, Plot3DKind kind) {
    HeaderGuess guess{bigEndian, records, multiBlock, {}, {}, 0};
    const std::size_t intsPerBlock = kind == Plot3DKind::FunctionFile ? 4 : 3;
    std::size_t offset = 0;
    std::int64_t blocks = 1;
    if (multiBlock) {
        const auto count = readIntRecord(bytes, offset, 1, records, bigEndian);
        if (!count || (*count)[0] < 1 || (*count)[0] > kMaxBlocks) return std::nullopt;
        blocks = (*count)[0];
    }
    const auto dims = readIntRecord(bytes, offset, std::size_t(blocks) * intsPerBlock, records, bigEndian);
    if (!dims) return std::nullopt;
    for (std::size_t block = 0; block < std::size_t(blocks); ++block) {
        const std::size_t first = block * intsPerBlock;
        const glm::ivec3 size((*dims)[first], (*dims)[first + 1], (*dims)[first + 2]);
        if (kind == Plot3DKind::FunctionFile) {
            const int functions = (*dims)[first + 3];
            if (functions < 1 || functions > kMaxFunctions) return std::nullopt;
            guess.functionCounts.push_back(functions);
        }
        if (glm::any(glm::lessThan(size, glm::ivec3(1)))) return std::nullopt;
        if (double(size.x) * double(size.y) * double(size.z) > double(kMaxNodesPerBlock)) return std::nullopt;
        guess.dims.push_back(size);
    }
    guess.dataStart = offset;
    return guess;
}

std::size_t nodeCount(glm::ivec3 dims) {
    return std::size_t(dims.x) * std::size_t(dims.y) * std::size_t(dims.z);
}

// The record payload sizes of each block's data.
std::vector<std::size_t> blockRecords(Plot3DKind kind, glm::ivec3 dims, int precision, bool iblank, int functions) {
    const std::size_t nodes = nodeCount(dims);
    if (kind == Plot3DKind::GridFile) return {nodes * (3 * std::size_t(precision) + (iblank ? 4 : 0))};
    if (kind == Plot3DKind::FunctionFile) return {nodes * std::size_t(functions) * std::size_t(precision)};
    return {4 * std::size_t(precision), 5 * nodes * std::size_t(precision)};
}

// Checks the data records against the file and fills in the offsets; false if they do not match.
bool placeBlocks(const std::vector<std::uint8_t>& bytes, const HeaderGuess& guess, Plot3DKind kind, int precision,
                 bool iblank, Plot3DLayout& layout) {
    std::size_t offset = guess.dataStart;
    layout = Plot3DLayout{guess.bigEndian, guess.records, guess.multiBlock, precision, iblank, guess.dims,
                          guess.functionCounts, {}, {}};
    for (std::size_t block = 0; block < guess.dims.size(); ++block) {
        const int functions = guess.functionCounts.empty() ? 0 : guess.functionCounts[block];
        const std::vector<std::size_t> records = blockRecords(kind, guess.dims[block], precision, iblank, functions);
        for (std::size_t record = 0; record < records.size(); ++record) {
            const std::size_t payload = records[record];
            if (offset + payload + (guess.records ? 8 : 0) > bytes.size()) return false;
            if (guess.records) {
                if (payload > 0x7fffffffu) return false;  // Fortran markers are 32-bit
                if (readInt(bytes, offset, guess.bigEndian) != std::int32_t(payload) ||
                    readInt(bytes, offset + 4 + payload, guess.bigEndian) != std::int32_t(payload))
                    return false;
                offset += 4;
            }
            if (record == 0) layout.blockOffsets.push_back(offset);
            if (record == 1) layout.solutionArrayOffsets.push_back(offset);
            offset += payload + (guess.records ? 4 : 0);
        }
    }
    return offset == bytes.size();
}

std::string dimsText(const std::vector<glm::ivec3>& dims) {
    std::ostringstream text;
    for (std::size_t block = 0; block < dims.size() && block < 4; ++block)
        text << (block ? ", " : "") << dims[block].x << "x" << dims[block].y << "x" << dims[block].z;
    if (dims.size() > 4) text << ", ...";
    return text.str();
}

[[noreturn]] void failNoLayout(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes,
                               const std::vector<HeaderGuess>& guesses, Plot3DKind kind) {
    const char* what = kind == Plot3DKind::GridFile ? "grid" : kind == Plot3DKind::SolutionFile ? "solution" : "function";
    for (const HeaderGuess& guess : guesses) {
        std::size_t smallest = guess.dataStart;
        for (std::size_t block = 0; block < guess.dims.size(); ++block) {
            const int functions = guess.functionCounts.empty() ? 0 : guess.functionCounts[block];
            for (std::size_t payload : blockRecords(kind, guess.dims[block], 4, false, functions))
                smallest += payload + (guess.records ? 8 : 0);
        }
        if (bytes.size() < smallest) {
            throwInputError(path, "", std::string("Plot3D ") + what + " file is truncated: its header announces " +
                                          std::to_string(guess.dims.size()) + " block(s) of " + dimsText(guess.dims) +
                                          " nodes, which need at least " + std::to_string(smallest) +
                                          " bytes, found " + std::to_string(bytes.size()));
        }
    }
    throwInputError(path, "", std::string("not a binary 3D Plot3D ") + what + " file: no layout (byte order, " +
                                  "record markers, block count, float32/float64" +
                                  (kind == Plot3DKind::GridFile ? ", IBLANK" : "") + ") matches its " +
                                  std::to_string(bytes.size()) +
                                  " bytes (2D and formatted ASCII Plot3D files are not supported)");
}

std::vector<std::uint8_t> readWholeFile(const std::filesystem::path& path) {
    // Read whole to find its layout: its size is what it takes, checked first (a sparse file can
    // claim terabytes it does not hold).
    const std::uint64_t size = regularFileSize(path, "Plot3D file");
    requireMemory(path, "", double(size), defaultMemoryCap(), "reading the whole Plot3D file would");
    std::ifstream in(path, std::ios::binary);
    if (!in) throwInputError(path, "", "cannot open the file for reading");
    std::vector<std::uint8_t> bytes(size);
    in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size));
    if (!in || std::uint64_t(in.gcount()) != size) throwInputError(path, "", "cannot read the file");
    return bytes;
}

}  // namespace

std::string Plot3DLayout::describe() const {
    return std::string(multiBlock ? "multi-block" : "single-block") + ", " + (bigEndian ? "big" : "little") +
           "-endian, " + (records ? "Fortran records" : "no record markers") + ", float" +
           std::to_string(precision * 8) + (iblank ? ", IBLANK" : "");
}

std::int32_t Plot3DFile::integer(std::size_t offset) const {
    return readInt(bytes, offset, layout.bigEndian);
}

double Plot3DFile::real(std::size_t offset) const {
    if (layout.precision == 8) return std::bit_cast<double>(readUnsigned(bytes, offset, 8, layout.bigEndian));
    return double(std::bit_cast<float>(std::uint32_t(readUnsigned(bytes, offset, 4, layout.bigEndian))));
}

Plot3DFile readPlot3DFile(const std::filesystem::path& path, Plot3DKind kind) {
    Plot3DFile file{path, readWholeFile(path), {}};
    std::vector<HeaderGuess> guesses;
    for (bool records : {true, false})
        for (bool bigEndian : {false, true})
            for (bool multiBlock : {true, false})
                if (auto guess = parseHeader(file.bytes, bigEndian, records, multiBlock, kind)) guesses.push_back(*guess);
    for (const HeaderGuess& guess : guesses)
        for (int precision : {4, 8})
            for (bool iblank : kind == Plot3DKind::GridFile ? std::vector<bool>{false, true} : std::vector<bool>{false})
                if (placeBlocks(file.bytes, guess, kind, precision, iblank, file.layout)) return file;
    failNoLayout(path, file.bytes, guesses, kind);
}

}  // namespace tstyles
