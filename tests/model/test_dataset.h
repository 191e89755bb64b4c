// Small datasets for the data-model tests: fresh temporary folders, raw little-endian bytes and a
// base manifest that each error test breaks in one place.
#pragma once

#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include "tstyles/core/errors.h"
#include "tstyles/data/manifest.h"

namespace tstyles_test {

// A new empty folder under the system temp folder; the pid keeps parallel test runs apart.
inline std::filesystem::path freshFolder(const std::string& name) {
    const auto folder =
        std::filesystem::temp_directory_path() / ("tstyles_data_" + name + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

inline void writeBytes(const std::filesystem::path& file, const std::vector<std::uint8_t>& bytes) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

inline void writeText(const std::filesystem::path& file, const std::string& text) {
    std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
}

inline std::vector<std::uint8_t> uint16Bytes(const std::vector<std::uint16_t>& values) {
    std::vector<std::uint8_t> bytes;
    for (std::uint16_t value : values) {
        bytes.push_back(std::uint8_t(value & 0xFF));
        bytes.push_back(std::uint8_t(value >> 8));
    }
    return bytes;
}

inline std::vector<std::uint8_t> float32Bytes(const std::vector<float>& values) {
    std::vector<std::uint8_t> bytes;
    for (float value : values) {
        const auto bits = std::bit_cast<std::uint32_t>(value);
        for (int shift = 0; shift < 32; shift += 8) bytes.push_back(std::uint8_t(bits >> shift));
    }
    return bytes;
}

// 0, 1, ..., count - 1 as uint8.
inline std::vector<std::uint8_t> rampBytes(std::size_t count) {
    std::vector<std::uint8_t> bytes(count);
    for (std::size_t index = 0; index < count; ++index) bytes[index] = std::uint8_t(index);
    return bytes;
}

// The grid every base time-step uses: 2 x 3 x 4 = 24 voxels, so each axis is told apart.
constexpr std::size_t kBaseVoxels = 24;

inline nlohmann::json baseStep(double time, const std::string& stem) {
    return {{"time", time},
            {"grid", {{"type", "rectilinear"}, {"dims", {2, 3, 4}}, {"spacing", {0.5, 0.5, 0.25}}}},
            {"placement",
             {{"origin", {1.0, 2.0, 3.0}}, {"rotation", {{"axis", {0, 0, 1}}, {"angle_deg", 30.0}}}}},
            {"values", {{"file", stem + ".raw"}, {"type", "uint8"}}}};
}

// Two uint8 time-steps (t00 with a mask, t01 without) that load without error.
inline nlohmann::json baseManifest() {
    nlohmann::json manifest = {{"format", "tstyles-series"},
                               {"version", 1},
                               {"name", "base"},
                               {"value_range", {0, 255}},
                               {"time_steps", {baseStep(0.0, "t00"), baseStep(1.0, "t01")}}};
    manifest["time_steps"][0]["mask"] = {{"file", "t00_mask.raw"}};
    return manifest;
}

// A folder holding the base dataset's raw files and `manifest` as series.json.
inline std::filesystem::path writeBaseDataset(const std::string& name, const nlohmann::json& manifest) {
    const auto folder = freshFolder(name);
    writeBytes(folder / "t00.raw", rampBytes(kBaseVoxels));
    writeBytes(folder / "t01.raw", rampBytes(kBaseVoxels));
    writeBytes(folder / "t00_mask.raw", std::vector<std::uint8_t>(kBaseVoxels, 1));
    writeText(folder / "series.json", manifest.dump(2));
    return folder;
}

// The message of the InputError that loading `manifestPath` throws, or a test failure.
inline std::string loadError(const std::filesystem::path& manifestPath) {
    try {
        tstyles::loadSeries(manifestPath);
    } catch (const tstyles::InputError& error) {
        return error.what();
    }
    ADD_FAILURE() << "loading " << manifestPath << " did not throw an InputError";
    return {};
}

// Checks that the message contains every part (file name, field, a word of the problem).
inline void expectMentions(const std::string& message, std::initializer_list<std::string> parts) {
    for (const std::string& part : parts) {
        EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' missing from: " << message;
    }
}

}  // namespace tstyles_test
