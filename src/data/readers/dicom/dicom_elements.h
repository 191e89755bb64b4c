// Reading the values of DICOM data elements as GDCM holds them (the bytes of the file): text,
// decimal strings (DS, IS), unsigned shorts (US) and times (TM, DA, DT). Damaged values are an
// InputError naming the file and the tag; absent ones are empty optionals.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <gdcmDataSet.h>

namespace tstyles {

// Where an element is read from, for messages, and whether its binary values are big-endian.
struct DicomContext {
    std::filesystem::path file;
    bool bigEndian = false;
};

// "(0020,0032) ImagePositionPatient": how messages name a tag.
std::string dicomTagName(const gdcm::Tag& tag, const char* keyword);

// The element's text without its padding (trailing spaces and NULs, leading spaces); empty
// optional when absent or empty.
std::optional<std::string> dicomText(const gdcm::DataSet& data, const gdcm::Tag& tag);

// The backslash-separated decimal numbers of a DS or IS element; `count` numbers exactly (0: any
// number, at least one). Absent: empty optional.
std::optional<std::vector<double>> dicomNumbers(const gdcm::DataSet& data, const gdcm::Tag& tag, const char* keyword,
                                                std::size_t count, const DicomContext& context);

// One decimal number (DS or IS).
std::optional<double> dicomNumber(const gdcm::DataSet& data, const gdcm::Tag& tag, const char* keyword,
                                  const DicomContext& context);

// A US element (Rows, BitsAllocated ...): its first value.
std::optional<std::uint16_t> dicomUnsignedShort(const gdcm::DataSet& data, const gdcm::Tag& tag, const char* keyword,
                                                const DicomContext& context);

// A UL element (TemporalPositionIndex) or an FD element (NominalCardiacTriggerDelayTime): its first
// value, as a double.
std::optional<double> dicomUnsignedLong(const gdcm::DataSet& data, const gdcm::Tag& tag, const char* keyword,
                                        const DicomContext& context);
std::optional<double> dicomFloat64(const gdcm::DataSet& data, const gdcm::Tag& tag, const char* keyword,
                                   const DicomContext& context);

// Seconds since 0000-03-01 (a day count that needs no calendar tables) from a date (DA,
// "YYYYMMDD"), a time (TM, "HHMMSS.FFFFFF" or the old "HH:MM:SS.frac"), or a date-time (DT,
// "YYYYMMDDHHMMSS.FFFFFF&ZZXX"; the offset is ignored: a series is taken in one place).
double dicomDateSeconds(const std::string& date, const gdcm::Tag& tag, const char* keyword, const DicomContext& context);
double dicomTimeSeconds(const std::string& time, const gdcm::Tag& tag, const char* keyword, const DicomContext& context);
double dicomDateTimeSeconds(const std::string& dateTime, const gdcm::Tag& tag, const char* keyword,
                            const DicomContext& context);

// The nested data sets of a sequence element (SQ), or none when absent. At most `limit` items.
std::vector<gdcm::DataSet> dicomItems(const gdcm::DataSet& data, const gdcm::Tag& tag, const char* keyword,
                                      std::size_t limit, const DicomContext& context);

}  // namespace tstyles
