// The table of scene keys (scene_keys.h) against the reader, the animation and the documentation:
// every numeric key is read at both ends of its range and refused one step past each, naming the
// key; its accessors read and write what the reader reads, and the writer writes it back;
// docs/scene-format.md holds the table.
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <set>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tstyles/core/errors.h"
#include "tstyles/scene/animation.h"
#include "tstyles/scene/doc_tables.h"
#include "tstyles/scene/scene_file.h"
#include "tstyles/scene/scene_keys.h"

namespace tstyles {
namespace {

// A scene whose every numeric key has a number: an orbit with a distance, a compositor that takes
// a threshold and has fitted-by-hand unchanged places, a ray mode with an attenuation, a step, an
// exaggeration and a last step.
nlohmann::json sceneWithEveryNumber() {
    return nlohmann::json::parse(R"({
        "dataset": "series.json",
        "camera": {"orbit": {"distance": 10, "azimuth_deg": 30, "elevation_deg": 20}},
        "raycast": {"step": 0.5, "termination": 0.99},
        "vertical_exaggeration": 2,
        "compositor": {"name": "first-arrival", "threshold": 0.5,
                       "unchanged": {"below": 0.1, "tie": 0.05, "gain": 2, "boundary": 1, "opacity": 0.3}},
        "ray": {"mode": "attenuated-maximum", "attenuation": 2},
        "exposure": {"first": 1, "last": 3},
        "annotations": {"font_size": 20}
    })");
}

// `document` with the number at a key path ("camera.orbit.distance") set.
nlohmann::json withNumber(nlohmann::json document, std::string_view path, double value) {
    nlohmann::json* at = &document;
    std::size_t start = 0;
    while (true) {
        const std::size_t dot = path.find('.', start);
        const std::string key(path.substr(start, dot == std::string_view::npos ? std::string_view::npos : dot - start));
        at = &(*at)[key];
        if (dot == std::string_view::npos) break;
        start = dot + 1;
    }
    *at = value;
    return document;
}

std::string readError(const nlohmann::json& document) {
    try {
        parseScene(document.dump(), "scene.json");
    } catch (const InputError& error) {
        return error.what();
    }
    return "";
}

// The smallest step past an end that the reader must refuse: 1 for whole keys, else the next double.
double pastEnd(const NumericKey& key, double end, double direction) {
    return key.whole ? end + direction : std::nextafter(end, direction * std::numeric_limits<double>::infinity());
}

TEST(SceneKeys, EveryNumericKeyIsReadWithinItsRangeAndRefusedPastIt) {
    int numericKeys = 0;
    for (const SceneKey& key : sceneKeys()) {
        if (!key.numeric) continue;
        ++numericKeys;
        const NumericKey& numeric = *key.numeric;
        const Interval& range = numeric.range;
        SCOPED_TRACE(std::string(key.path));
        for (const double end : {range.low, range.high}) {
            if (std::isinf(end) || std::abs(end) == std::numeric_limits<double>::max()) continue;
            const bool included = end == range.low ? range.lowIncluded : range.highIncluded;
            const double direction = end == range.low ? -1.0 : 1.0;
            // Exposure must stay ordered: its ends are checked against each other elsewhere.
            if (key.path == "exposure.first" && end == range.high) continue;
            if (key.path == "exposure.last" && end == range.low) continue;
            if (included) {
                const Scene scene = parseScene(withNumber(sceneWithEveryNumber(), key.path, end).dump(), "scene.json");
                EXPECT_EQ(numeric.get(scene), end);
            }
            const double outside = included ? pastEnd(numeric, end, direction) : end;
            const std::string error = readError(withNumber(sceneWithEveryNumber(), key.path, outside));
            EXPECT_NE(error.find("scene.json: " + std::string(key.path) + ": must be"), std::string::npos) << error;
        }
        // The accessors write what the reader reads.
        Scene scene = parseScene(sceneWithEveryNumber().dump(), "scene.json");
        ASSERT_TRUE(numeric.get(scene).has_value());
        const double inside = numeric.whole ? *numeric.get(scene) + 1.0 : *numeric.get(scene) * 0.5;
        ASSERT_TRUE(range.contains(inside));
        numeric.set(scene, inside);
        const Scene read = parseScene(withNumber(sceneWithEveryNumber(), key.path, inside).dump(), "scene.json");
        EXPECT_EQ(scene, read);
        // The writer writes it: the scene's own file reads back with the number.
        const std::filesystem::path folder = std::filesystem::current_path();
        EXPECT_EQ(numeric.get(parseScene(sceneToJson(scene, folder), folder / "scene.json")), inside);
    }
    EXPECT_EQ(numericKeys, 19);
}

// A frame of a value track on a key of the table is set in the scene directly; it must be the scene
// a file with that value reads as (the way every other key path is applied).
TEST(SceneKeys, AnAnimatedKeyIsTheSceneAFileWithItsValueReadsAs) {
    for (const SceneKey& key : sceneKeys()) {
        if (!key.numeric) continue;
        SCOPED_TRACE(std::string(key.path));
        const Scene still = parseScene(sceneWithEveryNumber().dump(), "scene.json");
        const double from = *key.numeric->get(still);
        const double to = key.numeric->whole ? from + 1.0 : from * 0.5;
        Scene animated = still;
        AnimationTrack track;
        track.target = ValueTrackTarget{std::string(key.path)};
        track.keys = {{0.0, from}, {4.0, to}};
        animated.animation.tracks = {track};
        animated.animation.frames = 5;
        // Frame 2 is halfway (linear): whole keys round it.
        const double halfway = key.numeric->whole ? std::round(0.5 * (from + to)) : 0.5 * (from + to);
        const Scene expected = parseScene(withNumber(sceneWithEveryNumber(), key.path, halfway).dump(), "scene.json");
        EXPECT_EQ(sceneAtFrame(animated, 2), expected);
    }
}

TEST(SceneKeys, TheTableNamesEveryKeyOnce) {
    std::set<std::string_view> paths;
    for (const SceneKey& key : sceneKeys()) EXPECT_TRUE(paths.insert(key.path).second) << key.path;
    EXPECT_TRUE(numericSceneKey("image.width")->whole);
    EXPECT_FALSE(numericSceneKey("raycast.termination")->whole);
    EXPECT_EQ(numericSceneKey("stf.opacity[1].at"), nullptr);
    EXPECT_THROW(sceneKey("raycast.steps"), std::logic_error);
}

TEST(DocTables, TheDocsHoldTheGeneratedTables) {
    for (const GeneratedDocTable& table : generatedDocTables()) {
        std::ifstream in(std::filesystem::path(TSTYLES_SOURCE_DIR) / "docs" / table.document);
        const std::string doc{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        const std::optional<std::string> documented = documentedTable(doc, table);
        ASSERT_TRUE(documented) << table.document << " lacks the markers of its generated table";
        EXPECT_EQ(*documented, table.table())
            << "docs/" << table.document << "'s generated table differs from the code's: run "
            << "build/tools/write_doc_tables docs";
    }
}

}  // namespace
}  // namespace tstyles
