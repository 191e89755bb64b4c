// What the viewer has open: the scene being edited, the series it shows, and where they came from.
// Opening builds a complete new document or throws, so a bad file never half-replaces a good one.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "density_histogram.h"
#include "tstyles/data/display_frame.h"
#include "tstyles/data/read_options.h"
#include "tstyles/data/series.h"
#include "tstyles/scene/scene.h"

namespace tstyles::viewer {

struct ViewerDocument {
    Scene scene;
    std::shared_ptr<const Series> series;
    // How the series was turned and scaled for display (for ticks in the file's units).
    DisplayFrame frame;
    std::shared_ptr<const DensityHistogram> histogram;
    // The scene file it was opened from or last saved to; none for a dataset opened on its own.
    std::optional<std::filesystem::path> sceneFile;
    // The camera as opened: what "reset camera" returns to.
    Camera openedCamera;
    // Each time-step's stamp as a person reads it ("2009-07-15", "12.2 s"; formatTimes).
    std::vector<std::string> timeLabels;
};

// Opens a scene file or a dataset (with a default scene); several paths are the files of one
// series. The dataset is read with `readOptions` (the command line's --var, --steps, ...). A
// series already held by `current` is reused rather than read again. Throws InputError naming the
// file and the problem.
ViewerDocument openDocument(const std::vector<std::filesystem::path>& paths, const ViewerDocument* current,
                            const ReadOptions& readOptions);
ViewerDocument openDocument(const std::filesystem::path& path, const ViewerDocument* current);

// What `tstyles view` opens without an argument: the bundled Figure 1 scene, else the bundled
// super-ellipsoid dataset. Throws InputError if the data folder has neither.
std::filesystem::path defaultViewerInput(const std::filesystem::path& dataDirectory);

}  // namespace tstyles::viewer
