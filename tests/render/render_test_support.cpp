// Headless context, synthetic series and axis-aligned cameras for the render tests.
#include "render_test_support.h"

#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <stdexcept>

#include <unistd.h>

#include "tstyles/data/manifest.h"
#include "tstyles/gl/headless_context.h"
#include "tstyles/image/image_io.h"

namespace tstyles::testing {
namespace {

struct TestGl {
    std::unique_ptr<HeadlessContext> context;
    std::unique_ptr<Renderer> renderer;
};

TestGl& testGl() {
    static TestGl gl = [] {
        const char* name = std::getenv("TSTYLES_TEST_BACKEND");
        const auto backend = glBackendFromString(name != nullptr ? name : "auto");
        if (!backend) throw std::runtime_error("TSTYLES_TEST_BACKEND must be egl, osmesa or auto");
        TestGl created;
        created.context = createHeadlessContext(*backend, true);
        created.renderer = std::make_unique<Renderer>(ShaderLibrary::fromEnvironment(std::nullopt));
        return created;
    }();
    return gl;
}

}  // namespace

Renderer& testRenderer() { return *testGl().renderer; }
std::string testBackendDescription() { return testGl().context->description(); }

BoxSpec constantBox(glm::dvec3 origin, float density) {
    BoxSpec box;
    box.origin = origin;
    box.density = [density](glm::ivec3) { return density; };
    return box;
}

Series makeSeries(const std::vector<BoxSpec>& boxes) {
    Series series;
    series.name = "test series";
    series.valueRange = {0.0, 1.0};
    for (std::size_t index = 0; index < boxes.size(); ++index) {
        const BoxSpec& box = boxes[index];
        TimeStep step;
        step.time = double(index);
        step.grid = RectilinearGrid{box.dims, box.spacing};
        step.placement.origin = box.origin;
        step.placement.rotation = box.rotation;
        step.rawRange = {0.0, 1.0};
        const auto& grid = step.rectilinear();
        step.density.resize(grid.voxelCount());
        if (box.mask) step.mask.emplace(grid.voxelCount());
        std::size_t i = 0;
        for (int z = 0; z < box.dims.z; ++z)
            for (int y = 0; y < box.dims.y; ++y)
                for (int x = 0; x < box.dims.x; ++x, ++i) {
                    step.density[i] = box.density({x, y, z});
                    if (box.mask) (*step.mask)[i] = (*box.mask)({x, y, z}) ? 1 : 0;
                }
        series.steps.push_back(std::move(step));
    }
    return series;
}

Scene orthographicSceneLookingDownZ(glm::dvec2 centre, double viewHeight, int size) {
    Scene scene;
    const double distance = 10.0;
    scene.camera.pose = LookAtCamera{{centre.x, centre.y, distance}, {centre.x, centre.y, 0.0}, {0.0, 1.0, 0.0}};
    scene.camera.projection = Projection::Orthographic;
    scene.camera.fovDeg = glm::degrees(2.0 * std::atan(viewHeight / (2.0 * distance)));
    scene.width = size;
    scene.height = size;
    scene.background = glm::dvec4(0.0);
    return scene;
}

const Series& loadSeriesOnce(const std::filesystem::path& manifest) {
    static std::map<std::filesystem::path, Series> cache;
    auto found = cache.find(manifest);
    if (found == cache.end()) found = cache.emplace(manifest, loadSeries(manifest)).first;
    return found->second;
}

Image renderSeries(const Series& series, const Scene& scene) {
    Renderer& renderer = testRenderer();
    renderer.setSeries(series);
    return renderImage(renderer, scene, series.worldBounds());
}

Image renderSeries(const Series& series, const Scene& scene, FrameOptions options) {
    testRenderer().setSeries(series);
    return drawWithCurrentSeries(scene, series.worldBounds(), options);
}

Image drawWithCurrentSeries(const Scene& scene, const Bounds& seriesBounds, FrameOptions options) {
    Renderer& renderer = testRenderer();
    options.size = {scene.width, scene.height};
    renderer.draw(scene, resolveView(scene.camera, seriesBounds, scene.width, scene.height), options);
    return renderer.readFrame();
}

double slabOpacity(double opacityPerReference, double thickness, double referenceLength) {
    return 1.0 - std::pow(1.0 - opacityPerReference, thickness / referenceLength);
}

glm::ivec2 pixelOf(glm::dvec2 world, glm::dvec2 centre, double viewHeight, int size) {
    const glm::dvec2 normalized = (world - centre) / viewHeight + 0.5;  // 0..1, y up
    return {int(std::floor(normalized.x * size)), int(std::floor((1.0 - normalized.y) * size))};
}

TransferFunction1D constantFunction(glm::dvec3 color, double opacity) {
    TransferFunction1D function;
    function.opacity = {{0.0, opacity}};
    function.color = {{0.0, color}};
    return function;
}

std::filesystem::path styleImageFolder() {
    static const auto folder = [] {
        auto path = std::filesystem::temp_directory_path() / ("tstyles_style_tests_" + std::to_string(::getpid()));
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
        return path;
    }();
    return folder;
}

std::string writeStyle(const std::string& name, int width, int height,
                       const std::function<glm::vec4(glm::vec2)>& colorAt) {
    Image image(width, height);
    for (int row = 0; row < height; ++row)
        for (int column = 0; column < width; ++column) {
            const glm::vec2 normal((column + 0.5f) / width * 2.0f - 1.0f, 1.0f - (row + 0.5f) / height * 2.0f);
            const glm::vec4 color = colorAt(normal);
            image.set(column, row, glm::vec4(glm::vec3(color) * color.a, color.a));  // associated alpha
        }
    const auto file = styleImageFolder() / (name + ".png");
    writeImage(image, file);
    return file.string();
}

}  // namespace tstyles::testing
