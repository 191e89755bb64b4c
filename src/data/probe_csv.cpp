// CSV fields are quoted where they hold a comma, a quote or a line break (RFC 4180), labels always.
#include "tstyles/data/probe_csv.h"

#include <charconv>
#include <stdexcept>

#include "tstyles/core/interval.h"

namespace tstyles {
namespace {

std::string quotedField(const std::string& text) {
    std::string quoted = "\"";
    for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

std::string csvField(const std::string& text) {
    return text.find_first_of(",\"\r\n") == std::string::npos ? text : quotedField(text);
}

}  // namespace

std::string storedValueText(double value) {
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, float(value));
    return std::string(text, result.ptr);
}

void writeProbeCsv(std::ostream& out, const ProbeColumns& columns) {
    if (columns.timeLabels.size() != columns.times.size() || columns.headers.size() != columns.values.size())
        throw std::logic_error("writeProbeCsv: the times, labels, headers and value columns do not match");
    out << "time,label";
    for (const std::string& header : columns.headers) out << "," << csvField(header);
    out << "\n";
    for (std::size_t step = 0; step < columns.times.size(); ++step) {
        out << formatNumber(columns.times[step]) << "," << quotedField(columns.timeLabels[step]);
        for (const auto& column : columns.values) {
            if (column.size() != columns.times.size())
                throw std::logic_error("writeProbeCsv: a value column has the wrong length");
            out << "," << (column[step] ? storedValueText(*column[step]) : "");
        }
        out << "\n";
    }
}

}  // namespace tstyles
