// Two shortcuts of the automatic scenes, each against the exact path it replaces:
// - temporal-mip with unchanged places ranks the time-steps by density alone where the STF's opacity
//   never falls as density rises (RaycastVariant::stfOpacityRises), and looks up the STF of the
//   winner alone: the same order, so the same pixels, asserted bit for bit (the bundled data, and
//   realistic files: a CT phantom, an MR slab drawn as a maximum, an ocean eddy as the largest change);
// - a styled track of one colour node reads its style once (RaycastVariant::singleNodeStyleTracks),
//   where two nodes blend two lookups: the same scene with its node given twice, the same pixels.
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "../data/realistic_datasets.h"
#include "render_test_support.h"
#include "tstyles/data/series_opener.h"
#include "tstyles/image/image_comparison.h"
#include "tstyles/render/style_textures.h"
#include "tstyles/render/transfer_tables.h"
#include "tstyles/scene/automatic_scene.h"

namespace tstyles::testing {
namespace {

TEST(OpacityNeverFalls, HoldsForRampsAndPlateausOnly) {
    const glm::vec4 clear(1.0f, 1.0f, 1.0f, 0.0f);
    const glm::vec4 faint(1.0f, 1.0f, 1.0f, 0.1f);
    const glm::vec4 strong(1.0f, 1.0f, 1.0f, 0.6f);
    EXPECT_TRUE(opacityNeverFalls({clear, clear, faint, faint, strong}));
    EXPECT_TRUE(opacityNeverFalls({strong}));
    EXPECT_FALSE(opacityNeverFalls({clear, strong, faint}));  // a peak: a denser place may be fainter
    EXPECT_FALSE(opacityNeverFalls({strong, clear}));
}

TEST(OpacityNeverFalls, IsWhatTheAutomaticSceneOfARisingStfAsks) {
    TransferFunction1D rising;
    rising.opacity = {{0.1, 0.0}, {0.8, 0.3}};
    EXPECT_TRUE(opacityNeverFalls(bakeTransferTable(rising)));
    TransferFunction1D peak;
    peak.opacity = {{0.1, 0.0}, {0.5, 0.3}, {0.9, 0.0}};
    EXPECT_FALSE(opacityNeverFalls(bakeTransferTable(peak)));
}

struct Drawn {
    Image image;
    RaycastVariant variant;
    RaycastStatistics statistics;
};

constexpr int kSize = 160;

// A bundled dataset (`write` empty) or a realistic file that `write` makes.
struct AutomaticCase {
    std::string name;
    std::function<void(const std::filesystem::path&)> write;
};

void PrintTo(const AutomaticCase& automatic, std::ostream* out) { *out << automatic.name; }

// The series of a case, read once per test process.
const Series& seriesOf(const AutomaticCase& automatic, std::filesystem::path& dataset) {
    if (!automatic.write) {
        dataset = std::filesystem::path(TSTYLES_SOURCE_DIR) / "data" / automatic.name / "series.json";
        return loadSeriesOnce(dataset);
    }
    static std::map<std::string, Series> written;
    const auto folder = std::filesystem::temp_directory_path() / ("tstyles_ranking_" + std::to_string(::getpid()));
    dataset = folder / automatic.name;
    if (!written.contains(automatic.name)) {
        std::filesystem::create_directories(folder);
        automatic.write(dataset);
        written.emplace(automatic.name, openSeries(dataset, ReadOptions{}));
        std::filesystem::remove_all(folder);
    }
    return written.at(automatic.name);
}

// The case's automatic scene at kSize x kSize, `edit`ed, drawn with `options`.
template <typename Edit>
Drawn drawAutomatic(const AutomaticCase& automatic, FrameOptions options, Edit edit) {
    std::filesystem::path dataset;
    const Series& series = seriesOf(automatic, dataset);
    Scene scene = automaticScene(series, dataset).scene;
    scene.width = scene.height = kSize;
    edit(scene);
    const SceneOnSeries fitted = fitSceneToSeries(scene, series);
    Renderer& renderer = testRenderer();
    renderer.setSeries(fitted.series);
    options.size = {kSize, kSize};
    options.collectStatistics = true;
    // The gradient atlas from the first frame (where the grids suit it), as a user's second frame has it.
    options.precomputedGradients = true;
    renderer.draw(fitted.scene,
                  resolveView(fitted.scene.camera, fitted.framed, fitted.series.worldBounds(), kSize, kSize), options);
    return {renderer.readFrame(), renderer.lastVariant(), renderer.lastStatistics()};
}

void expectSamePixels(const Drawn& shortcut, const Drawn& exact, const std::string& what) {
    ASSERT_EQ(shortcut.image.rgba.size(), exact.image.rgba.size());
    int differing = 0;
    for (std::size_t i = 0; i < exact.image.rgba.size(); ++i)
        if (shortcut.image.rgba[i] != exact.image.rgba[i]) ++differing;
    EXPECT_EQ(differing, 0) << what << ": pixel values that differ";
    EXPECT_EQ(shortcut.statistics.samples, exact.statistics.samples) << what;
    EXPECT_EQ(shortcut.statistics.fetches, exact.statistics.fetches) << what;
}

class RankingByDensity : public ::testing::TestWithParam<AutomaticCase> {};
class OneStyleLookup : public ::testing::TestWithParam<AutomaticCase> {};

// The automatic scenes rise from transparent to their opacity, in temporal-mip with unchanged places
// (or the change the largest-change mode compares, which the same compositor measures).
TEST_P(RankingByDensity, GivesTheSamePixels) {
    const auto keep = [](Scene&) {};
    FrameOptions byStf;
    byStf.rankByDensity = false;
    const Drawn ranked = drawAutomatic(GetParam(), FrameOptions{}, keep);
    const Drawn exact = drawAutomatic(GetParam(), byStf, keep);
    EXPECT_TRUE(ranked.variant.stfOpacityRises) << "the ranking by density was not taken";
    EXPECT_TRUE(ranked.variant.unchangedTime);
    EXPECT_FALSE(exact.variant.stfOpacityRises);
    expectSamePixels(ranked, exact, GetParam().name + ", ranked by density against by STF lookups");
}

// Their STF is one styled colour node; given twice, at both ends, it blends two equal lookups.
TEST_P(OneStyleLookup, ForOneNodeGivesTheSamePixels) {
    const Drawn single = drawAutomatic(GetParam(), FrameOptions{}, [](Scene&) {});
    const Drawn twice = drawAutomatic(GetParam(), FrameOptions{}, [](Scene& scene) {
        ASSERT_EQ(scene.stf.curve.color.size(), 1u);
        ColorNode second = scene.stf.curve.color.front();
        scene.stf.curve.color.front().at = 0.0;
        second.at = 1.0;
        scene.stf.curve.color.push_back(second);
    });
    EXPECT_EQ(single.variant.singleNodeStyleTracks & (1 << kStfTrack), 1 << kStfTrack) << "one lookup not taken";
    EXPECT_EQ(twice.variant.singleNodeStyleTracks & (1 << kStfTrack), 0);
    expectSamePixels(single, twice, GetParam().name + ", one node against the node twice");
}

std::string testNameOf(const ::testing::TestParamInfo<AutomaticCase>& parameter) {
    std::string name = parameter.param.name;
    for (char& c : name)
        if (c == '-' || c == '.') c = '_';
    return name;
}

const AutomaticCase kSuperEllipsoid{"superellipsoid", {}};
const AutomaticCase kHurricane{"hurricane", {}};
const AutomaticCase kSonar{"sonar", {}};
const AutomaticCase kAlignedSuperEllipsoid{"superellipsoid-aligned", {}};
// Scientists' files: a noisy CT phantom (composited, styled), an MR slab (a maximum projection) and
// an ocean eddy (a map, the largest change), both without style.
const AutomaticCase kCtPhantom{"ct-phantom.nii", testdata::writeCtPhantom};
const AutomaticCase kMrSlab{"mr-slab.nii", testdata::writeMrSlab};
const AutomaticCase kOceanEddy{"ocean-eddy.nc", testdata::writeOceanEddy};

INSTANTIATE_TEST_SUITE_P(AutomaticScenes, RankingByDensity,
                         ::testing::Values(kSuperEllipsoid, kHurricane, kSonar, kAlignedSuperEllipsoid, kCtPhantom,
                                           kMrSlab, kOceanEddy),
                         testNameOf);
INSTANTIATE_TEST_SUITE_P(StyledAutomaticScenes, OneStyleLookup,
                         ::testing::Values(kSuperEllipsoid, kHurricane, kSonar, kAlignedSuperEllipsoid, kCtPhantom),
                         testNameOf);

}  // namespace
}  // namespace tstyles::testing
