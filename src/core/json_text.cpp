// Parsing JSON text, with the errors every reader of JSON files gives.
#include "tstyles/core/json_text.h"

#include <fstream>
#include <iterator>
#include <optional>
#include <set>
#include <string>
#include <vector>

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

// Finds a key given twice in one object, which the parser would keep silently, the last winning:
// a scene's {"direction": "falling", "direction": "rising"} would render rising with no word. Fed
// the parser's events; knows the path of the containers it is in ("compositor", "stf.opacity[2]").
class DuplicateKeyFinder {
public:
    bool onEvent(nlohmann::json::parse_event_t event, const nlohmann::json& parsed) {
        using Event = nlohmann::json::parse_event_t;
        switch (event) {
            case Event::object_start:
            case Event::array_start:
                containers_.push_back({event == Event::object_start, childPath(), {}, {}, 0});
                break;
            case Event::key: {
                Container& object = containers_.back();
                object.key = parsed.get<std::string>();
                if (!object.keys.insert(object.key).second && !duplicate_) duplicate_ = childPath();
                break;
            }
            case Event::object_end:
            case Event::array_end:
                containers_.pop_back();
                elementDone();
                break;
            case Event::value: elementDone(); break;
        }
        return true;
    }
    // The path of the first key given twice ("compositor.direction"), if any.
    const std::optional<std::string>& duplicate() const { return duplicate_; }

private:
    struct Container {
        bool object;
        std::string path;
        std::set<std::string> keys;  // an object's, so far
        std::string key;             // an object's current key
        std::size_t index;           // an array's current element
    };

    // The path of the element now being read inside the innermost container.
    std::string childPath() const {
        if (containers_.empty()) return "";
        const Container& parent = containers_.back();
        if (!parent.object) return parent.path + "[" + std::to_string(parent.index) + "]";
        return parent.path.empty() ? parent.key : parent.path + "." + parent.key;
    }
    void elementDone() {
        if (!containers_.empty() && !containers_.back().object) ++containers_.back().index;
    }

    std::vector<Container> containers_;
    std::optional<std::string> duplicate_;
};

// Arrays and objects nested deeper than any document of ours needs (a scene is 6 deep) are refused
// as they are met: the paths kept for naming a key (DuplicateKeyFinder) grow with the depth, and
// 25 000 nested arrays took more than 8 GiB.
constexpr int kMostJsonNesting = 100;
struct NestedTooDeep {};

}  // namespace

nlohmann::json parseJsonText(const std::string& text, const std::filesystem::path& origin, JsonComments comments) {
    try {
        DuplicateKeyFinder finder;
        nlohmann::json document = nlohmann::json::parse(
            text,
            [&finder](int depth, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
                if (depth >= kMostJsonNesting) throw NestedTooDeep{};
                return finder.onEvent(event, parsed);
            },
            true, comments == JsonComments::Allowed);
        if (finder.duplicate())
            throwInputError(origin, *finder.duplicate(), "given twice; a key may appear once in an object");
        return document;
    } catch (const NestedTooDeep&) {
        throwInputError(origin, "",
                        "arrays and objects nested more than " + std::to_string(kMostJsonNesting) +
                            " deep; no document read here needs so many");
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
