// Value parsing for DICOM elements: every number is checked to be a whole, finite decimal, every
// date and time to be in range, so a damaged header never becomes a wrong position or time.
#include "dicom_elements.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <cstdlib>

#include <gdcmSequenceOfItems.h>

#include "../../value_decoding.h"
#include "tstyles/core/errors.h"

namespace tstyles {
namespace {

std::string withoutPadding(std::string text) {
    while (!text.empty() && (text.back() == ' ' || text.back() == '\0')) text.pop_back();
    std::size_t first = 0;
    while (first < text.size() && text[first] == ' ') ++first;
    return text.substr(first);
}

std::vector<std::string> splitAtBackslash(const std::string& text) {
    std::vector<std::string> parts(1);
    for (char c : text) {
        if (c == '\\') parts.emplace_back();
        else parts.back() += c;
    }
    return parts;
}

[[noreturn]] void badValue(const DicomContext& context, const gdcm::Tag& tag, const char* keyword,
                           const std::string& problem) {
    throwInputError(context.file, dicomTagName(tag, keyword), problem);
}

// A whole number of `digits` digits at `text[at]`.
int digitsAt(const std::string& text, std::size_t at, std::size_t digits, const gdcm::Tag& tag, const char* keyword,
             const DicomContext& context) {
    if (at + digits > text.size()) badValue(context, tag, keyword, "\"" + text + "\" is cut short");
    int value = 0;
    for (std::size_t i = at; i < at + digits; ++i) {
        if (text[i] < '0' || text[i] > '9') badValue(context, tag, keyword, "\"" + text + "\" is not a date or time");
        value = value * 10 + (text[i] - '0');
    }
    return value;
}

// Days from 0000-03-01 to the date (proleptic Gregorian), counting March as the year's first month.
long daysFromCivil(int year, int month, int day) {
    const int shifted = month <= 2 ? year - 1 : year;
    const long era = shifted / 400;
    const long yearOfEra = shifted - era * 400;
    const long dayOfYear = (153 * (month + (month > 2 ? -3 : 9)) + 2) / 5 + day - 1;
    return era * 146097 + yearOfEra * 365 + yearOfEra / 4 - yearOfEra / 100 + dayOfYear;
}

}  // namespace

std::string dicomTagName(const gdcm::Tag& tag, const char* keyword) {
    char code[16];
    std::snprintf(code, sizeof(code), "(%04X,%04X)", unsigned(tag.GetGroup()), unsigned(tag.GetElement()));
    return std::string(code) + " " + keyword;
}

std::optional<std::string> dicomText(const gdcm::DataSet& data, const gdcm::Tag& tag) {
    if (!data.FindDataElement(tag)) return std::nullopt;
    const gdcm::ByteValue* bytes = data.GetDataElement(tag).GetByteValue();
    if (bytes == nullptr || bytes->GetPointer() == nullptr) return std::nullopt;
    std::string text = withoutPadding(std::string(bytes->GetPointer(), bytes->GetLength()));
    if (text.empty()) return std::nullopt;
    return text;
}

std::optional<std::vector<double>> dicomNumbers(const gdcm::DataSet& data, const gdcm::Tag& tag, const char* keyword,
                                                std::size_t count, const DicomContext& context) {
    const std::optional<std::string> text = dicomText(data, tag);
    if (!text) return std::nullopt;
    std::vector<double> numbers;
    for (const std::string& part : splitAtBackslash(*text)) {
        const std::string number = withoutPadding(part);
        char* end = nullptr;
        const double value = number.empty() ? 0.0 : std::strtod(number.c_str(), &end);
        if (number.empty() || end != number.c_str() + number.size() || !std::isfinite(value))
            badValue(context, tag, keyword, "\"" + *text + "\" is not a list of finite decimal numbers");
        numbers.push_back(value);
    }
    if (count != 0 && numbers.size() != count)
        badValue(context, tag, keyword,
                 "holds " + std::to_string(numbers.size()) + " numbers, expected " + std::to_string(count));
    return numbers;
}

std::optional<double> dicomNumber(const gdcm::DataSet& data, const gdcm::Tag& tag, const char* keyword,
                                  const DicomContext& context) {
    const auto numbers = dicomNumbers(data, tag, keyword, 0, context);
    if (!numbers) return std::nullopt;
    return numbers->front();
}

std::optional<std::uint16_t> dicomUnsignedShort(const gdcm::DataSet& data, const gdcm::Tag& tag, const char* keyword,
                                                const DicomContext& context) {
    if (!data.FindDataElement(tag)) return std::nullopt;
    const gdcm::ByteValue* bytes = data.GetDataElement(tag).GetByteValue();
    if (bytes == nullptr || bytes->GetLength() == 0) return std::nullopt;
    if (bytes->GetLength() < 2 || bytes->GetPointer() == nullptr)
        badValue(context, tag, keyword, "holds " + std::to_string(bytes->GetLength()) + " bytes, not a 2-byte number");
    const auto* raw = reinterpret_cast<const unsigned char*>(bytes->GetPointer());
    return std::uint16_t(decodeUnsigned(raw, 2, context.bigEndian ? ByteOrder::Big : ByteOrder::Little));
}

namespace {

// The first `size` bytes of a binary element in the host's order; empty when absent.
std::optional<std::vector<unsigned char>> binaryValue(const gdcm::DataSet& data, const gdcm::Tag& tag,
                                                      const char* keyword, std::size_t size,
                                                      const DicomContext& context) {
    if (!data.FindDataElement(tag)) return std::nullopt;
    const gdcm::ByteValue* bytes = data.GetDataElement(tag).GetByteValue();
    if (bytes == nullptr || bytes->GetLength() == 0) return std::nullopt;
    if (bytes->GetLength() < size || bytes->GetPointer() == nullptr)
        badValue(context, tag, keyword,
                 "holds " + std::to_string(bytes->GetLength()) + " bytes, not a " + std::to_string(size) + "-byte number");
    std::vector<unsigned char> value(bytes->GetPointer(), bytes->GetPointer() + size);
    const bool hostIsBig = std::endian::native == std::endian::big;
    if (context.bigEndian != hostIsBig) std::reverse(value.begin(), value.end());
    return value;
}

}  // namespace

std::optional<double> dicomUnsignedLong(const gdcm::DataSet& data, const gdcm::Tag& tag, const char* keyword,
                                        const DicomContext& context) {
    const auto bytes = binaryValue(data, tag, keyword, 4, context);
    if (!bytes) return std::nullopt;
    std::uint32_t value;
    std::memcpy(&value, bytes->data(), 4);
    return double(value);
}

std::optional<double> dicomFloat64(const gdcm::DataSet& data, const gdcm::Tag& tag, const char* keyword,
                                   const DicomContext& context) {
    const auto bytes = binaryValue(data, tag, keyword, 8, context);
    if (!bytes) return std::nullopt;
    double value;
    std::memcpy(&value, bytes->data(), 8);
    if (!std::isfinite(value)) badValue(context, tag, keyword, "is not a finite number");
    return value;
}

double dicomDateSeconds(const std::string& date, const gdcm::Tag& tag, const char* keyword, const DicomContext& context) {
    // "YYYYMMDD", or the old "YYYY.MM.DD".
    const bool dotted = date.size() == 10 && date[4] == '.' && date[7] == '.';
    const int year = digitsAt(date, 0, 4, tag, keyword, context);
    const int month = digitsAt(date, dotted ? 5 : 4, 2, tag, keyword, context);
    const int day = digitsAt(date, dotted ? 8 : 6, 2, tag, keyword, context);
    if (month < 1 || month > 12 || day < 1 || day > 31) badValue(context, tag, keyword, "\"" + date + "\" is no date");
    return double(daysFromCivil(year, month, day)) * 86400.0;
}

double dicomTimeSeconds(const std::string& time, const gdcm::Tag& tag, const char* keyword, const DicomContext& context) {
    // HH, HHMM, HHMMSS, HHMMSS.F..., or the old HH:MM:SS.
    std::string compact;
    for (char c : time)
        if (c != ':') compact += c;
    const std::size_t dot = compact.find('.');
    const std::string whole = compact.substr(0, dot);
    if (whole.size() != 2 && whole.size() != 4 && whole.size() != 6)
        badValue(context, tag, keyword, "\"" + time + "\" is not a time HHMMSS.FFFFFF");
    const int hours = digitsAt(whole, 0, 2, tag, keyword, context);
    const int minutes = whole.size() >= 4 ? digitsAt(whole, 2, 2, tag, keyword, context) : 0;
    const int seconds = whole.size() == 6 ? digitsAt(whole, 4, 2, tag, keyword, context) : 0;
    double fraction = 0.0;
    if (dot != std::string::npos) {
        const std::string digits = compact.substr(dot + 1);
        if (digits.empty() || digits.size() > 6) badValue(context, tag, keyword, "\"" + time + "\" has a bad fraction");
        fraction = double(digitsAt(digits, 0, digits.size(), tag, keyword, context)) / std::pow(10.0, double(digits.size()));
    }
    if (hours > 23 || minutes > 59 || seconds > 60) badValue(context, tag, keyword, "\"" + time + "\" is no time of day");
    return hours * 3600.0 + minutes * 60.0 + seconds + fraction;
}

double dicomDateTimeSeconds(const std::string& dateTime, const gdcm::Tag& tag, const char* keyword,
                            const DicomContext& context) {
    std::string local = dateTime.substr(0, dateTime.find_first_of("+-"));
    if (local.size() < 8) badValue(context, tag, keyword, "\"" + dateTime + "\" is not a date-time YYYYMMDDHHMMSS");
    const double day = dicomDateSeconds(local.substr(0, 8), tag, keyword, context);
    return local.size() == 8 ? day : day + dicomTimeSeconds(local.substr(8), tag, keyword, context);
}

std::vector<gdcm::DataSet> dicomItems(const gdcm::DataSet& data, const gdcm::Tag& tag, const char* keyword,
                                      std::size_t limit, const DicomContext& context) {
    std::vector<gdcm::DataSet> items;
    if (!data.FindDataElement(tag)) return items;
    const gdcm::SmartPointer<gdcm::SequenceOfItems> sequence = data.GetDataElement(tag).GetValueAsSQ();
    if (!sequence) return items;
    const std::size_t count = sequence->GetNumberOfItems();
    if (count > limit)
        badValue(context, tag, keyword, "holds " + std::to_string(count) + " items, more than the " +
                                            std::to_string(limit) + " expected");
    for (std::size_t item = 1; item <= count; ++item) items.push_back(sequence->GetItem(item).GetNestedDataSet());
    return items;
}

}  // namespace tstyles
