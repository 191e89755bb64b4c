// Paths into scene JSON: parsing "a.b[2].c" and setting the number there.
#include "json_path.h"

#include <cctype>

namespace tstyles {

std::optional<std::vector<JsonPathStep>> parseJsonPath(const std::string& path) {
    std::vector<JsonPathStep> steps;
    std::size_t at = 0;
    while (at < path.size()) {
        if (path[at] == '[') {
            const std::size_t close = path.find(']', at);
            if (close == std::string::npos || close == at + 1) return std::nullopt;
            std::size_t index = 0;
            for (std::size_t i = at + 1; i < close; ++i) {
                if (!std::isdigit(static_cast<unsigned char>(path[i]))) return std::nullopt;
                index = index * 10 + std::size_t(path[i] - '0');
            }
            steps.emplace_back(index);
            at = close + 1;
            if (at < path.size() && path[at] == '.') {
                ++at;
                if (at == path.size()) return std::nullopt;
            }
            continue;
        }
        const std::size_t end = path.find_first_of(".[", at);
        const std::string key = path.substr(at, end == std::string::npos ? std::string::npos : end - at);
        if (key.empty()) return std::nullopt;
        steps.emplace_back(key);
        at = end == std::string::npos ? path.size() : end;
        if (at < path.size() && path[at] == '.') {
            ++at;
            if (at == path.size()) return std::nullopt;
        }
    }
    if (steps.empty()) return std::nullopt;
    return steps;
}

bool setNumberAtPath(nlohmann::json& root, const std::vector<JsonPathStep>& steps, double value) {
    nlohmann::json* current = &root;
    for (const JsonPathStep& step : steps) {
        if (const auto* key = std::get_if<std::string>(&step)) {
            if (current->is_null()) *current = nlohmann::json::object();
            if (!current->is_object()) return false;
            current = &(*current)[*key];
        } else {
            const std::size_t index = std::get<std::size_t>(step);
            if (!current->is_array() || index >= current->size()) return false;
            current = &(*current)[index];
        }
    }
    if (!current->is_null() && !current->is_number()) return false;
    *current = value;
    return true;
}

}  // namespace tstyles
