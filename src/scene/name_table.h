// Names of enum values as scene files spell them, from one table per enum, so that the name of a
// value and the value of a name cannot drift apart. Private to src/scene.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tstyles {

template <typename Enum, std::size_t N>
using NameTable = std::array<std::pair<Enum, const char*>, N>;

template <typename Enum, std::size_t N>
std::string nameOf(const NameTable<Enum, N>& table, Enum value) {
    for (const auto& [entry, name] : table)
        if (entry == value) return name;
    return "unknown";
}

template <typename Enum, std::size_t N>
std::optional<Enum> valueOf(const NameTable<Enum, N>& table, const std::string& name) {
    for (const auto& [entry, entryName] : table)
        if (name == entryName) return entry;
    return std::nullopt;
}

template <typename Enum, std::size_t N>
std::vector<std::string> allNames(const NameTable<Enum, N>& table) {
    std::vector<std::string> names;
    for (const auto& entry : table) names.emplace_back(entry.second);
    return names;
}

}  // namespace tstyles
