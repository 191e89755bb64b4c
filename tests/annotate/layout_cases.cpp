// The layout tests' scenes: bundled, realistic files through the readers, synthetic series.
#include "layout_cases.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include <unistd.h>

#include "../data/realistic_datasets.h"
#include "tstyles/data/series_opener.h"
#include "tstyles/scene/scene_file.h"

namespace tstyles::testing {
namespace {

const std::filesystem::path kSourceDir = TSTYLES_SOURCE_DIR;

// Every annotation on, with a title longer than a small image holds.
Scene annotatedFully(Scene scene, const std::string& title) {
    scene.annotations.legend = true;
    scene.annotations.caption = true;
    scene.annotations.box = true;
    scene.annotations.scaleBar = true;
    scene.annotations.title = title;
    return scene;
}

void addBundledScenes(std::vector<LayoutCase>& cases) {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(kSourceDir / "data/scenes"))
        if (entry.path().extension() == ".json") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    std::map<std::filesystem::path, Series> datasets;  // read once each
    for (const std::filesystem::path& file : files) {
        const Scene scene = loadScene(file);
        auto found = datasets.find(scene.dataset);
        if (found == datasets.end())
            found = datasets.emplace(scene.dataset, openSeries(scene.dataset, ReadOptions{})).first;
        const std::string name = file.stem().string();
        cases.push_back(
            {name, fitSceneToSeries(annotatedFully(scene, "Bundled scene " + name + ", as the paper shows it"),
                                    found->second),
             true});
    }
}

void addRealisticFiles(std::vector<LayoutCase>& cases) {
    const auto folder = std::filesystem::temp_directory_path() / ("tstyles_layout_" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    const std::vector<std::pair<std::string, void (*)(const std::filesystem::path&)>> files{
        {"ocean-anomalies.nc", testdata::writeOceanAnomalies},
        {"ocean-eddy.nc", testdata::writeOceanEddy},
        {"moving-blob.nii", testdata::writeMovingBlobNifti},
        {"ct-phantom.nii", testdata::writeCtPhantom}};
    for (const auto& [name, write] : files) {
        const auto file = folder / name;
        write(file);
        Series series = openSeries(file, ReadOptions{});
        const Scene scene = automaticScene(series, file).scene;
        cases.push_back(
            {name, fitSceneToSeries(annotatedFully(scene, name + ": the automatic scene"), std::move(series))});
    }
    std::filesystem::remove_all(folder);
}

struct SyntheticShape {
    std::string name;
    std::string valueUnit;
    glm::ivec3 dims{0};
    glm::dvec3 origin{0.0};
    glm::dvec3 spacing{1.0};
    std::array<SpatialAxis, 3> axes;
    TimeAxis time;
    std::vector<double> times;
};

// A blob that moves across the grid from one time-step to the next, on a faint background.
Series syntheticSeries(const SyntheticShape& shape) {
    Series series;
    series.name = shape.name;
    series.valueUnit = shape.valueUnit;
    series.valueRange = {-2.0, 30.0};
    series.axes = shape.axes;
    series.time = shape.time;
    RectilinearGrid grid;
    grid.dims = shape.dims;
    grid.spacing = shape.spacing;
    const glm::dvec3 size(shape.dims);
    for (std::size_t step = 0; step < shape.times.size(); ++step) {
        TimeStep timeStep;
        timeStep.time = shape.times[step];
        timeStep.grid = grid;
        timeStep.placement.origin = shape.origin;
        const double t = shape.times.size() > 1 ? double(step) / double(shape.times.size() - 1) : 0.0;
        const glm::dvec3 centre = size * glm::dvec3(0.2 + 0.6 * t, 0.5, 0.4);
        for (int z = 0; z < shape.dims.z; ++z)
            for (int y = 0; y < shape.dims.y; ++y)
                for (int x = 0; x < shape.dims.x; ++x) {
                    const glm::dvec3 d = (glm::dvec3(x, y, z) - centre) / (0.15 * size);
                    timeStep.density.push_back(float(0.05 + 0.9 * std::exp(-glm::dot(d, d))));
                }
        series.steps.push_back(std::move(timeStep));
    }
    return series;
}

std::vector<double> evenTimes(int count, double every) {
    std::vector<double> times;
    for (int i = 0; i < count; ++i) times.push_back(i * every);
    return times;
}

void addSyntheticSeries(std::vector<LayoutCase>& cases) {
    std::vector<SyntheticShape> shapes;
    // A global ocean map with the depth axis named as some models name it (as the NetCDF reader
    // gives depth: up, negative below the surface).
    shapes.push_back({"sea_water_potential_temperature",
                      "degC",
                      {72, 36, 12},
                      {-180.0, -90.0, -4950.0},
                      {5.0, 5.0, 450.0},
                      {SpatialAxis{"longitude", "degrees_east", AxisDirection::East},
                       SpatialAxis{"latitude", "degrees_north", AxisDirection::North},
                       SpatialAxis{"ZAXLEVIT19", "METERS", AxisDirection::Up}},
                      TimeAxis{TimeUnit::Days, CalendarDate{1950, 1, 1}},
                      {7305.0, 7336.0, 7364.0}});
    // A 7-step forecast, six hours apart, of a regional wind over heights in metres.
    shapes.push_back(
        {"wind_speed",
         "m s-1",
         {60, 40, 15},
         {-20.0, 30.0, 0.0},
         {0.25, 0.25, 1000.0},
         {SpatialAxis{"lon", "degrees_east", AxisDirection::East},
          SpatialAxis{"lat", "degrees_north", AxisDirection::North}, SpatialAxis{"height", "m", AxisDirection::Up}},
         TimeAxis{TimeUnit::Hours, CalendarDate{2024, 6, 1}},
         evenTimes(7, 6.0)});
    // A 40-volume fMRI run, TR 2 s, 3 mm voxels.
    shapes.push_back({"BOLD",
                      "",
                      {32, 38, 28},
                      {-48.0, -60.0, -40.0},
                      {3.0, 3.0, 3.0},
                      {SpatialAxis{"x", "mm", AxisDirection::Right}, SpatialAxis{"y", "mm", AxisDirection::Anterior},
                       SpatialAxis{"z", "mm", AxisDirection::Superior}},
                      TimeAxis{TimeUnit::Seconds},
                      evenTimes(40, 2.0)});
    for (const SyntheticShape& shape : shapes) {
        const Series series = syntheticSeries(shape);
        const std::filesystem::path file = "synthetic-" + shape.name + ".nc";
        const Scene scene =
            annotatedFully(automaticScene(series, file).scene, shape.name + ", " + std::to_string(shape.times.size()) +
                                                                   " time-steps of a synthetic series");
        cases.push_back({file.string(), fitSceneToSeries(scene, series)});
        // Turned so that the depth (or height) axis shows, as a user orbits the automatic view.
        Scene turned = scene;
        turned.camera.pose = OrbitCamera{std::nullopt, std::nullopt, 25.0, 30.0};
        cases.push_back({file.string() + " turned", fitSceneToSeries(turned, series)});
    }
}

}  // namespace

const std::vector<LayoutCase>& layoutCases() {
    static const std::vector<LayoutCase> cases = [] {
        std::vector<LayoutCase> all;
        addBundledScenes(all);
        addRealisticFiles(all);
        addSyntheticSeries(all);
        return all;
    }();
    return cases;
}

const std::vector<glm::ivec2>& layoutImageSizes() {
    static const std::vector<glm::ivec2> sizes{{320, 240}, {640, 480}, {1920, 1080}};
    return sizes;
}

std::unique_ptr<SizedPlan> planAt(const LayoutCase& layoutCase, glm::ivec2 size, const Font& font) {
    auto owned = std::make_unique<SizedPlan>();
    SizedPlan& sized = *owned;
    sized.scene = layoutCase.fitted.scene;
    sized.scene.width = size.x;
    sized.scene.height = size.y;
    const Series& series = layoutCase.fitted.series;
    // As SceneAnnotator: the framed bounds, the whole series for the clip planes, and the picture
    // moved clear of the panels.
    sized.view = resolveView(sized.scene.camera, layoutCase.fitted.framed, series.worldBounds(), size.x, size.y);
    sized.plan =
        planAnnotations(size, sized.scene, series, layoutCase.fitted.frame, sized.view, font, {}, layoutCase.fitted.framed);
    return owned;
}

}  // namespace tstyles::testing
