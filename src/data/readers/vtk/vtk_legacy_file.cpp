// Legacy VTK files keyword by keyword: the header, the structured dataset's geometry and where each
// array's values lie (passed over, not kept), then one array's values on demand. The file is read
// through a small buffer (vtk_legacy_text.h), so a binary file's values are skipped by seeking,
// never loaded whole.
#include "vtk_legacy_file.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <optional>
#include <string_view>

#include "../file_magic.h"
#include "tstyles/core/ascii_case.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"
#include "tstyles/core/interval.h"
#include "vtk_legacy_text.h"

namespace tstyles {
namespace {

constexpr std::string_view kLegacyMagic = "# vtk DataFile Version";
constexpr std::uint64_t kMaxCount = 9'000'000'000'000'000;  // counts a double holds exactly
constexpr std::uint64_t kMaxLegacyComponents = 64;

std::uint64_t pointCountOf(const glm::ivec3& dims) {
    return std::uint64_t(dims.x) * std::uint64_t(dims.y) * std::uint64_t(dims.z);
}

std::string legacyDimsText(const glm::ivec3& dims) {
    return std::to_string(dims.x) + " x " + std::to_string(dims.y) + " x " + std::to_string(dims.z);
}

enum class Section { Dataset, Point, Cell };

// One pass over the keywords, filling a VtkLegacyFile; values are passed over.
class LegacyParser {
public:
    LegacyParser(VtkLegacyFile& file, std::uint64_t memoryCap)
        : file_(file), cursor_(file.path), memoryCap_(memoryCap) {}

    void readHeader();
    void readKeywords();
    void checkGeometry();

private:
    [[noreturn]] void fail(const std::string& field, const std::string& problem) const {
        throwInputError(file_.path, printable(field), printable(problem));
    }
    std::uint64_t countIn(const std::vector<std::string>& words, std::size_t index, const std::string& field) const;
    glm::dvec3 vectorIn(const std::vector<std::string>& words, const std::string& field) const;
    VtkValueType typeIn(const std::vector<std::string>& words, std::size_t index, const std::string& field) const;
    void requireWords(const std::vector<std::string>& words, std::size_t count, const std::string& form) const;
    void requireComponents(const std::string& field, std::uint64_t components) const;
    void requirePointCount(const std::string& field, std::uint64_t count) const;

    void readKeyword(const std::vector<std::string>& words);
    void readDimensions(const std::vector<std::string>& words);
    void readAttribute(const std::vector<std::string>& words, const std::string& keyword);
    void readField(const std::vector<std::string>& words);
    void readFieldArray(const std::vector<std::string>& words, const std::string& fieldName);
    VtkLegacyArray arrayHere(const std::string& writtenName, const VtkValueType& type, std::uint64_t components,
                             std::uint64_t tuples, const std::string& field);
    void keep(const VtkLegacyArray& array, bool scalars);
    void skipStrings(std::uint64_t count, const std::string& field);
    void skipMetadata();

    VtkLegacyFile& file_;
    FileCursor cursor_;
    std::uint64_t memoryCap_;
    Section section_ = Section::Dataset;
    std::uint64_t sectionCount_ = 0;
    bool dimensionsRead_ = false;
    std::optional<std::uint64_t> pointDataCount_, pointsCount_;
    std::array<std::optional<std::uint64_t>, 3> coordinateCounts_;
};

std::uint64_t LegacyParser::countIn(const std::vector<std::string>& words, std::size_t index,
                                    const std::string& field) const {
    std::uint64_t count = 0;
    const std::string& text = words.at(index);
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), count);
    if (error != std::errc() || end != text.data() + text.size() || count > kMaxCount)
        fail(field, "'" + text + "' is not a count (a whole number of at most 9e15)");
    return count;
}

glm::dvec3 LegacyParser::vectorIn(const std::vector<std::string>& words, const std::string& field) const {
    std::string written;
    for (std::size_t index = 1; index < words.size(); ++index) written += (index > 1 ? " " : "") + words[index];
    glm::dvec3 vector{0.0};
    for (std::size_t axis = 0; axis < 3; ++axis) {
        const auto value = words.size() == 4 ? numberIn(words[axis + 1]) : std::nullopt;
        if (!value || !std::isfinite(*value)) fail(field, "'" + written + "' is not three finite numbers");
        vector[int(axis)] = *value;
    }
    return vector;
}

VtkValueType LegacyParser::typeIn(const std::vector<std::string>& words, std::size_t index,
                                  const std::string& field) const {
    const std::string& written = words.at(index);
    if (const auto type = legacyValueType(written)) return *type;
    if (asciiLowercase(written) == "bit")
        fail(field, "bit arrays (8 values a byte) are not read: write the array as unsigned_char");
    fail(field, "unknown type '" + written + "' (known: unsigned_char, char, signed_char, unsigned_short, short, "
                                             "unsigned_int, int, unsigned_long, long, vtktypeint64, vtktypeuint64, "
                                             "vtkIdType, float, double)");
}

void LegacyParser::requireWords(const std::vector<std::string>& words, std::size_t count,
                                const std::string& form) const {
    if (words.size() < count) fail(words.front(), "is incomplete: the line must read '" + form + "'");
}

void LegacyParser::requireComponents(const std::string& field, std::uint64_t components) const {
    if (components < 1 || components > kMaxLegacyComponents)
        fail(field, std::to_string(components) + " components: between 1 and " + std::to_string(kMaxLegacyComponents) +
                        " are read");
}

void LegacyParser::requirePointCount(const std::string& field, std::uint64_t count) const {
    if (dimensionsRead_ && count != pointCountOf(file_.dims))
        fail(field, std::to_string(count) + " points disagree with DIMENSIONS " + legacyDimsText(file_.dims) +
                        ", which make " + std::to_string(pointCountOf(file_.dims)));
}

void LegacyParser::readHeader() {
    if (!looksLikeVtkLegacy(file_.path))
        fail("", "not a legacy VTK file: it does not start with '# vtk DataFile Version'");
    restOfLine(cursor_);
    file_.title = restOfLine(cursor_).value_or("");
    skipSpace(cursor_);
    const std::string written = restOfLine(cursor_).value_or("");
    const std::vector<std::string> fileType = wordsOf(written);
    const std::string type = fileType.size() == 1 ? asciiLowercase(fileType.front()) : "";
    if (type != "ascii" && type != "binary")
        fail("", "the third line must say ASCII or BINARY, not '" + written.substr(0, 40) + "'");
    file_.binary = type == "binary";
    const auto dataset = nextKeywordLine(cursor_);
    if (!dataset || dataset->empty() || asciiLowercase(dataset->front()) != "dataset" || dataset->size() != 2)
        fail("DATASET", "missing: the line after ASCII or BINARY must read 'DATASET kind'");
    const std::string kind = asciiLowercase(dataset->at(1));
    if (kind == "structured_points") file_.kind = VtkGridKind::Image;
    else if (kind == "structured_grid") file_.kind = VtkGridKind::Structured;
    else if (kind == "rectilinear_grid") file_.kind = VtkGridKind::Rectilinear;
    else
        fail("DATASET", "'" + dataset->at(1) + "' is not read: only STRUCTURED_POINTS, STRUCTURED_GRID and "
                                               "RECTILINEAR_GRID datasets are (values on a grid of points)");
}

void LegacyParser::readKeywords() {
    while (const auto words = nextKeywordLine(cursor_)) readKeyword(*words);
}

void LegacyParser::readKeyword(const std::vector<std::string>& words) {
    const std::string keyword = asciiLowercase(words.front());
    const bool image = file_.kind == VtkGridKind::Image;
    if (keyword == "dimensions") {
        readDimensions(words);
    } else if (keyword == "origin" && image) {
        file_.origin = vectorIn(words, words.front());
    } else if ((keyword == "spacing" || keyword == "aspect_ratio") && image) {
        file_.spacing = vectorIn(words, words.front());
    } else if (keyword == "points" && file_.kind == VtkGridKind::Structured) {
        requireWords(words, 3, "POINTS count type");
        pointsCount_ = countIn(words, 1, "POINTS");
        requirePointCount("POINTS", *pointsCount_);
        file_.points = arrayHere("points", typeIn(words, 2, "POINTS"), 3, *pointsCount_, "POINTS");
    } else if (keyword.size() == 13 && keyword.ends_with("_coordinates") && keyword[0] >= 'x' && keyword[0] <= 'z' &&
               file_.kind == VtkGridKind::Rectilinear) {
        const std::size_t axis = std::size_t(keyword[0] - 'x');
        requireWords(words, 3, words.front() + " count type");
        coordinateCounts_[axis] = countIn(words, 1, words.front());
        if (dimensionsRead_ && *coordinateCounts_[axis] != std::uint64_t(file_.dims[int(axis)]))
            fail(words.front(), std::to_string(*coordinateCounts_[axis]) + " coordinates disagree with DIMENSIONS " +
                                    legacyDimsText(file_.dims));
        file_.coordinates[axis] = arrayHere(std::string(1, char(keyword[0])), typeIn(words, 2, words.front()), 1,
                                            *coordinateCounts_[axis], words.front());
    } else if (keyword == "point_data" || keyword == "cell_data") {
        requireWords(words, 2, words.front() + " count");
        section_ = keyword == "point_data" ? Section::Point : Section::Cell;
        sectionCount_ = countIn(words, 1, words.front());
        if (section_ == Section::Point) requirePointCount("POINT_DATA", *(pointDataCount_ = sectionCount_));
    } else if (keyword == "field") {
        readField(words);
    } else if (keyword == "metadata") {  // after an array's values, where arrayHere did not expect it
        while (const auto line = restOfLine(cursor_))
            if (wordsOf(*line).empty()) break;
    } else if (section_ != Section::Dataset) {
        readAttribute(words, keyword);
    } else {
        fail(words.front(), "is not a keyword of a " + legacyDatasetName(file_.kind) +
                                " legacy file here (before POINT_DATA or CELL_DATA)");
    }
}

void LegacyParser::readDimensions(const std::vector<std::string>& words) {
    if (words.size() != 4) fail("DIMENSIONS", "must be three whole numbers: nx ny nz");
    for (int axis = 0; axis < 3; ++axis) {
        const std::uint64_t size = countIn(words, std::size_t(axis) + 1, "DIMENSIONS");
        if (size > std::uint64_t(std::numeric_limits<std::int32_t>::max()))
            fail("DIMENSIONS", std::string("the size along ") + "xyz"[axis] + " is too large");
        file_.dims[axis] = int(size);
    }
    if (double(file_.dims.x) * double(file_.dims.y) * double(file_.dims.z) > double(kMaxCount))
        fail("DIMENSIONS", "the grid holds too many points to be read");
    if (file_.dims.x < 2 || file_.dims.y < 2 || file_.dims.z < 2)
        fail("DIMENSIONS", "a volume needs at least 2 samples along x, y and z, found " + legacyDimsText(file_.dims));
    requireMemory(file_.path, "DIMENSIONS", 4.0 * double(pointCountOf(file_.dims)), memoryCap_,
                  "the values of one time-step");
    dimensionsRead_ = true;
}

void LegacyParser::readAttribute(const std::vector<std::string>& words, const std::string& keyword) {
    const std::string field = words.front() + (words.size() > 1 ? " " + words[1] : "");
    if (keyword == "scalars") {
        requireWords(words, 3, "SCALARS name type [components]");
        const std::uint64_t components = words.size() > 3 ? countIn(words, 3, field) : 1;
        const VtkValueType type = typeIn(words, 2, field);
        if (nextWordIs(cursor_, "lookup_table")) nextKeywordLine(cursor_);  // the table's name, not the table
        keep(arrayHere(words[1], type, components, sectionCount_, field), true);
    } else if (keyword == "color_scalars") {
        requireWords(words, 3, "COLOR_SCALARS name components");
        const VtkValueType type = file_.binary ? *legacyValueType("unsigned_char") : *legacyValueType("float");
        keep(arrayHere(words[1], type, countIn(words, 2, field), sectionCount_, field), false);
    } else if (keyword == "lookup_table") {  // a table section: four numbers a colour, no array
        requireWords(words, 3, "LOOKUP_TABLE name size");
        const VtkValueType type = file_.binary ? *legacyValueType("unsigned_char") : *legacyValueType("float");
        arrayHere(words[1], type, 4, countIn(words, 2, field), field);
    } else if (keyword == "vectors" || keyword == "normals" || keyword == "tensors" || keyword == "tensors6" ||
               keyword == "global_ids" || keyword == "pedigree_ids") {
        requireWords(words, 3, words.front() + " name type");
        const std::uint64_t components =
            keyword == "tensors" ? 9 : keyword == "tensors6" ? 6 : keyword.ends_with("_ids") ? 1 : 3;
        keep(arrayHere(words[1], typeIn(words, 2, field), components, sectionCount_, field), false);
    } else if (keyword == "texture_coordinates") {
        requireWords(words, 4, "TEXTURE_COORDINATES name dimension type");
        keep(arrayHere(words[1], typeIn(words, 3, field), countIn(words, 2, field), sectionCount_, field), false);
    } else {
        fail(words.front(), "is not a keyword of POINT_DATA or CELL_DATA (known: SCALARS, COLOR_SCALARS, "
                            "LOOKUP_TABLE, VECTORS, NORMALS, TEXTURE_COORDINATES, TENSORS, FIELD)");
    }
}

void LegacyParser::readField(const std::vector<std::string>& words) {
    requireWords(words, 3, "FIELD name count");
    const std::string field = "FIELD " + words[1];
    const std::uint64_t arrays = countIn(words, 2, field);
    for (std::uint64_t index = 0; index < arrays; ++index) {
        const auto line = nextKeywordLine(cursor_);
        if (!line)
            fail(field, "is truncated: the file ends after " + std::to_string(index) + " of its " +
                            std::to_string(arrays) + " arrays");
        if (asciiLowercase(line->front()) == "null_array") continue;  // a placeholder, with no values
        readFieldArray(*line, words[1]);
    }
}

void LegacyParser::readFieldArray(const std::vector<std::string>& words, const std::string& fieldName) {
    const std::string field = "FIELD " + fieldName + " " + words.front();
    if (words.size() != 4) fail(field, "the array's line must read 'name components tuples type'");
    const std::uint64_t components = countIn(words, 1, field);
    const std::uint64_t tuples = countIn(words, 2, field);
    requireComponents(field, components);
    const std::string type = asciiLowercase(words[3]);
    if (type == "string" || type == "utf8_string") return skipStrings(components * tuples, field);
    if (section_ == Section::Point && tuples != sectionCount_)
        fail(field, "has " + std::to_string(tuples) + " tuples, but POINT_DATA has " + std::to_string(sectionCount_) +
                        " points");
    const VtkLegacyArray array = arrayHere(words.front(), typeIn(words, 3, field), components, tuples, field);
    if (section_ != Section::Dataset) keep(array, false);  // the dataset's own FIELD (TIME, ...) is no point array
}

// The values of an array start after its keyword line: note where, pass over them, and over the
// METADATA block that version 5.1 may write after them.
VtkLegacyArray LegacyParser::arrayHere(const std::string& writtenName, const VtkValueType& type,
                                       std::uint64_t components, std::uint64_t tuples, const std::string& field) {
    requireComponents(field, components);
    VtkLegacyArray array{unescapedName(writtenName), type, components, cursor_.offset()};
    if (file_.binary) {
        requireBytes(cursor_, field, tuples * components * type.bytes);
        cursor_.seek(cursor_.offset() + tuples * components * type.bytes);
    } else {
        readValues(cursor_, false, type, tuples * components, field, [](double) {});
    }
    skipMetadata();
    return array;
}

void LegacyParser::keep(const VtkLegacyArray& array, bool scalars) {
    if (section_ == Section::Cell) {
        file_.cellArrays.push_back(array.name);
        return;
    }
    if (scalars && file_.activeScalars.empty()) file_.activeScalars = array.name;
    file_.pointArrays.push_back(array);
}

// String arrays (a FIELD's notes, say) are passed over: ASCII, a line each; binary, each behind a
// big-endian length whose two top bits say its size (11: 1 byte, 10: 2, 01: 4, 00: 8).
void LegacyParser::skipStrings(std::uint64_t count, const std::string& field) {
    const std::string truncated = "is truncated: the file ends inside its strings";
    for (std::uint64_t index = 0; index < count; ++index) {
        if (!file_.binary) {
            if (!restOfLine(cursor_)) fail(field, truncated);
            continue;
        }
        const int first = cursor_.peek();
        if (first < 0) fail(field, truncated);
        const std::size_t lengthBytes = std::size_t(1) << (3 - (first >> 6));
        char bytes[8];
        if (cursor_.read(bytes, lengthBytes) < lengthBytes) fail(field, truncated);
        bytes[0] = char(static_cast<unsigned char>(bytes[0]) & 0x3f);
        const VtkValueType lengthType{"UInt", VtkValueKind::Unsigned, lengthBytes};
        const auto length = std::uint64_t(decodeVtkValue(reinterpret_cast<const std::uint8_t*>(bytes), lengthType, true));
        requireBytes(cursor_, field, length);
        cursor_.seek(cursor_.offset() + length);
    }
    skipMetadata();
}

void LegacyParser::skipMetadata() {
    if (!nextWordIs(cursor_, "metadata")) return;
    nextKeywordLine(cursor_);
    while (const auto line = restOfLine(cursor_))  // INFORMATION or COMPONENT_NAMES lines, up to a blank one
        if (wordsOf(*line).empty()) return;
}

void LegacyParser::checkGeometry() {
    if (!dimensionsRead_) fail("DIMENSIONS", "missing: a " + legacyDatasetName(file_.kind) + " needs its size");
    if (pointDataCount_) requirePointCount("POINT_DATA", *pointDataCount_);
    if (file_.kind == VtkGridKind::Structured) {
        if (!pointsCount_) fail("POINTS", "missing: a STRUCTURED_GRID needs the positions of its points");
        requirePointCount("POINTS", *pointsCount_);
    }
    if (file_.kind != VtkGridKind::Rectilinear) return;
    for (int axis = 0; axis < 3; ++axis) {
        const std::string field = std::string(1, char('X' + axis)) + "_COORDINATES";
        if (!coordinateCounts_[std::size_t(axis)])
            fail(field, "missing: a RECTILINEAR_GRID needs x, y and z coordinates");
        if (*coordinateCounts_[std::size_t(axis)] != std::uint64_t(file_.dims[axis]))
            fail(field, std::to_string(*coordinateCounts_[std::size_t(axis)]) +
                            " coordinates disagree with DIMENSIONS " + legacyDimsText(file_.dims));
    }
}

std::string legacyArrayList(const std::vector<VtkLegacyArray>& arrays) {
    std::string list;
    for (const VtkLegacyArray& array : arrays)
        list += (list.empty() ? "" : ", ") + array.name +
                (array.components > 1 ? " (" + std::to_string(array.components) + " components)" : "");
    return list;
}

const VtkLegacyArray& pointArrayNamed(const VtkLegacyFile& file, const std::string& name) {
    for (const VtkLegacyArray& array : file.pointArrays)
        if (array.name == name) return array;
    throwInputError(file.path, "--var",
                    missingPointArrayProblem(name, legacyArrayList(file.pointArrays), file.cellArrays));
}

// `count` values of `array`, read from where they start.
template <class Sink>
void readArray(const VtkLegacyFile& file, const VtkLegacyArray& array, std::uint64_t count, const std::string& field,
               Sink&& sink) {
    FileCursor cursor(file.path);
    cursor.seek(array.start);
    readValues(cursor, file.binary, array.type, count, field, sink);
}

void requireKind(const VtkLegacyFile& file, VtkGridKind kind, const std::string& what) {
    if (file.kind != kind)
        throwInputError(file.path, "DATASET", what + " are read from a " + legacyDatasetName(kind) + ", not from a " +
                                                  legacyDatasetName(file.kind));
}

}  // namespace

std::string legacyDatasetName(VtkGridKind kind) {
    switch (kind) {
        case VtkGridKind::Image: return "STRUCTURED_POINTS";
        case VtkGridKind::Rectilinear: return "RECTILINEAR_GRID";
        case VtkGridKind::Structured: return "STRUCTURED_GRID";
    }
    return "STRUCTURED_POINTS";
}

VtkLegacyFile describeVtkLegacyFile(const std::filesystem::path& path, std::uint64_t memoryCap) {
    VtkLegacyFile file;
    file.path = path;
    LegacyParser parser(file, memoryCap);
    parser.readHeader();
    parser.readKeywords();
    parser.checkGeometry();
    return file;
}

std::vector<float> readVtkLegacyPointArray(const VtkLegacyFile& file, const std::string& name,
                                           std::uint64_t memoryCap) {
    const VtkLegacyArray& array = pointArrayNamed(file, name);
    const std::uint64_t tuples = pointCountOf(file.dims);
    requireMemory(file.path, "POINT_DATA " + name, 4.0 * double(tuples), memoryCap, "the values of one time-step");
    std::vector<float> values;
    values.reserve(std::size_t(tuples));
    double sum = 0.0;
    std::uint64_t component = 0;
    readArray(file, array, tuples * array.components, "POINT_DATA " + name, [&](double value) {
        if (array.components == 1) return values.push_back(float(value));
        sum += value * value;
        if (++component < array.components) return;
        values.push_back(float(std::sqrt(sum)));
        sum = 0.0;
        component = 0;
    });
    return values;
}

std::array<std::vector<double>, 3> readVtkLegacyCoordinates(const VtkLegacyFile& file, std::uint64_t memoryCap) {
    requireKind(file, VtkGridKind::Rectilinear, "coordinates");
    std::array<std::vector<double>, 3> coordinates;
    for (int axis = 0; axis < 3; ++axis) {
        const std::string field = std::string(1, char('X' + axis)) + "_COORDINATES";
        const std::string name(1, char('x' + axis));
        std::vector<double>& values = coordinates[std::size_t(axis)];
        requireMemory(file.path, field, 8.0 * double(file.dims[axis]), memoryCap, "the coordinates");
        values.reserve(std::size_t(file.dims[axis]));
        readArray(file, file.coordinates[std::size_t(axis)], std::uint64_t(file.dims[axis]), field, [&](double value) {
            if (!std::isfinite(value))
                throwInputError(file.path, field,
                                name + " coordinate " + std::to_string(values.size()) + " is not finite");
            if (!values.empty() && !(value > values.back()))
                throwInputError(file.path, field, "the " + name + " coordinates must increase strictly: " +
                                                      formatNumber(value) + " follows " + formatNumber(values.back()));
            values.push_back(value);
        });
    }
    return coordinates;
}

std::vector<glm::vec3> readVtkLegacyPoints(const VtkLegacyFile& file, std::uint64_t memoryCap) {
    requireKind(file, VtkGridKind::Structured, "points");
    const std::uint64_t count = pointCountOf(file.dims);
    requireMemory(file.path, "POINTS", 12.0 * double(count), memoryCap, "the points of one time-step");
    std::vector<glm::vec3> points(static_cast<std::size_t>(count));
    std::uint64_t index = 0;
    readArray(file, file.points, 3 * count, "POINTS", [&](double value) {
        points[std::size_t(index / 3)][int(index % 3)] = float(value);
        ++index;
    });
    return points;
}

bool looksLikeVtkLegacy(const std::filesystem::path& path) {
    return hasMagicAt(fileStart(path, kLegacyMagic.size()), 0, kLegacyMagic);
}

}  // namespace tstyles
