// Parsing JSON text, with the errors every reader of JSON files gives.
#include "tstyles/core/json_text.h"

#include <fstream>
#include <iterator>

#include "tstyles/core/errors.h"
#include "tstyles/core/user_paths.h"

namespace tstyles {
namespace {

// nlohmann's message without its exception-id prefix ("[json.exception.parse_error.101] "): the
// rest (line, column and what was expected) is what the user needs.
std::string withoutExceptionId(const nlohmann::json::exception& error) {
    std::string detail = error.what();
    if (const auto prefixEnd = detail.find("] "); prefixEnd != std::string::npos) detail.erase(0, prefixEnd + 2);
    return detail;
}

}  // namespace

nlohmann::json parseJsonText(const std::string& text, const std::filesystem::path& origin, JsonComments comments) {
    try {
        return nlohmann::json::parse(text, nullptr, true, comments == JsonComments::Allowed);
    } catch (const nlohmann::json::parse_error& error) {
        throwInputError(origin, "", "not valid JSON: " + withoutExceptionId(error));
    } catch (const nlohmann::json::out_of_range& error) {
        // Literals such as 1e999: JSON has no infinity, and the parser refuses to make one.
        throwInputError(origin, "",
                        "not valid JSON: a number is too large for a double (" + withoutExceptionId(error) + ")");
    } catch (const nlohmann::json::exception& error) {
        throwInputError(origin, "", "not valid JSON: " + withoutExceptionId(error));
    }
}

nlohmann::json probeJsonText(const std::string& text, JsonComments comments) {
    return nlohmann::json::parse(text, nullptr, false, comments == JsonComments::Allowed);
}

nlohmann::json readJsonFile(const std::filesystem::path& file, const std::string& what, JsonComments comments) {
    if (userPathKind({}, file) != PathKind::Missing) requireUserFile({}, file, what);
    std::ifstream in(file, std::ios::binary);
    if (!in) throwInputError(file, "", "cannot open the " + what);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (in.bad()) throwInputError(file, "", "cannot read the " + what);
    return parseJsonText(text, file, comments);
}

}  // namespace tstyles
