// Carrying out the viewer commands: files (open, save, screenshot), undo/redo, node edits, camera.
#include <algorithm>
#include <iostream>

#include "camera_controller.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/user_paths.h"
#include "tstyles/scene/scene_file.h"
#include "viewer_app.h"

#include "tstyles/scene/visible_bounds.h"

namespace tstyles::viewer {

void ViewerApp::execute(ViewerCommand command) {
    Scene& scene = document_.scene;
    switch (command) {
        case ViewerCommand::Open:
            fileDialog_.open(FilePurpose::Open, dialogFolder(), "");
            break;
        case ViewerCommand::Save:
            if (!document_.sceneFile) {
                execute(ViewerCommand::SaveAs);
                break;
            }
            try {
                saveTo(*document_.sceneFile);
            } catch (const InputError& error) {
                errorDialog_.show(error.what());
            }
            break;
        case ViewerCommand::SaveAs:
            fileDialog_.open(FilePurpose::SaveScene, dialogFolder(),
                             document_.sceneFile ? document_.sceneFile->filename().string() : "scene.json");
            break;
        case ViewerCommand::Screenshot:
            fileDialog_.open(FilePurpose::SaveScreenshot, std::filesystem::current_path(), "tstyles-view.png");
            break;
        case ViewerCommand::Quit:
            requestQuit();
            break;
        case ViewerCommand::Undo:
        case ViewerCommand::Redo:
            // A change still being dragged is committed first, so undo takes back exactly it.
            history_.record(scene);
            if (command == ViewerCommand::Undo ? history_.canUndo() : history_.canRedo()) {
                scene = command == ViewerCommand::Undo ? history_.undo() : history_.redo();
                editors_.clearSelections();
            }
            break;
        case ViewerCommand::ResetCamera:
            scene.camera = document_.openedCamera;
            break;
        case ViewerCommand::FitCamera:
            scene.camera = frameExplicitly(fitCameraToData(scene.camera), visibleBounds(*document_.series, scene.stf),
                                           frameSize());
            break;
        case ViewerCommand::TogglePlay:
            time_.togglePlay();
            break;
        case ViewerCommand::AddKey:
            addKey();
            break;
        case ViewerCommand::ExportMovie:
            startMovieExport();
            break;
        case ViewerCommand::CancelExport:
            movieExport_.reset();
            animation_.exportProgress = -1.0;
            animation_.message = "export cancelled; nothing was written";
            frame_.invalidate();
            break;
        default:
            executeEdit(command);
    }
}

void ViewerApp::executeEdit(ViewerCommand command) {
    CurveEditor& editor = editors_.focused();
    TransferFunction1D& curve = editors_.focusedCurve(document_.scene);
    switch (command) {
        case ViewerCommand::Group:
            editor.groupSelection(curve);
            break;
        case ViewerCommand::Ungroup:
            editor.ungroupSelection(curve);
            break;
        case ViewerCommand::DeleteNodes:
            editor.deleteSelection(curve);
            break;
        case ViewerCommand::SelectAll:
            editor.selectAll(curve);
            break;
        case ViewerCommand::ClearSelection:
            editor.clearSelection();
            break;
        case ViewerCommand::NudgeEarlier:
        case ViewerCommand::NudgeLater:
            editor.nudgeSelection(curve, command == ViewerCommand::NudgeEarlier ? -1 : 1,
                                  editors_.focusedAxis(*document_.series));
            break;
        default:
            break;
    }
}

void ViewerApp::handleFileChoice(const FileChoice& choice) {
    switch (choice.purpose) {
        case FilePurpose::Open:
            openPath(choice.path);
            break;
        case FilePurpose::SaveScene:
            try {
                saveTo(choice.path);
            } catch (const InputError& error) {
                errorDialog_.show(error.what());
            }
            break;
        case FilePurpose::SaveScreenshot:
            requestScreenshot(choice.path, false);
            break;
        case FilePurpose::ExportProbes:
            try {
                exportProbes(choice.path);
            } catch (const InputError& error) {
                errorDialog_.show(error.what());
            }
            break;
    }
}

void ViewerApp::openPath(const std::filesystem::path& path) {
    try {
        ViewerDocument previous = document_;
        adopt(openDocument(path, &document_));
        try {
            // Draw it now: what only the renderer can refuse (an unreadable style image) must
            // send us back to the previous document, not to half of each.
            frame_.update(renderer_, document_.scene, document_.series->worldBounds(), frameSize(), std::nullopt, false);
        } catch (...) {
            adopt(std::move(previous));
            throw;
        }
        std::cout << "opened " << path.string() << std::endl;
        recentFiles_.remember(path);
    } catch (const InputError& error) {
        errorDialog_.show(error.what());
    } catch (const std::exception& error) {
        errorDialog_.show(path.string() + ": cannot be shown: " + error.what());
    }
}

void ViewerApp::adopt(ViewerDocument next) {
    if (next.series != document_.series) {
        try {
            uploadSeries(*next.series);
        } catch (...) {
            // The upload failed half-way (nothing fits the GPU memory, say): put the current series back.
            uploadSeries(*document_.series);
            throw;
        }
    }
    document_ = std::move(next);
    history_.reset(document_.scene);
    lastRenderable_ = document_.scene;
    savedScene_ = document_.scene;
    editors_.clearSelections();
    frame_.invalidate();
    probeNote_ = nullptr;
    time_.solo = false;
    time_.playing = false;
    movieExport_.reset();
    animation_ = {};
    time_.step = 0;
}

void ViewerApp::saveTo(const std::filesystem::path& path) {
    // The file records the volume area's size, so `tstyles render` of it gives the window's image.
    Scene saved = document_.scene;
    saved.width = std::max(frameSize().x, 1);
    saved.height = std::max(frameSize().y, 1);
    saveScene(saved, path);
    document_.sceneFile = userAbsolutePath(PathSource{}, path);
    savedScene_ = document_.scene;
    std::cout << "saved scene " << path.string() << " (" << saved.width << "x" << saved.height << ")" << std::endl;
}

void ViewerApp::requestQuit() {
    if (script_ || document_.scene == savedScene_)
        quit_ = true;
    else
        quitDialog_.ask();
}

void ViewerApp::updateTitle() {
    const std::string name = document_.sceneFile ? document_.sceneFile->filename().string()
                                                 : document_.series->name + " (no scene file)";
    const std::string title = "Temporal Styles - " + name + (document_.scene == savedScene_ ? "" : " *");
    if (title == title_) return;
    title_ = title;
    window_.setTitle(title);
}

std::filesystem::path ViewerApp::dialogFolder() const {
    if (document_.sceneFile) return document_.sceneFile->parent_path();
    return std::filesystem::current_path();
}

}  // namespace tstyles::viewer

namespace tstyles::viewer {

Scene ViewerApp::shownScene() const {
    const Scene& scene = document_.scene;
    Scene shown = scene;
    if (animation_.previewing && !scene.animation.empty()) {
        shown = sceneAtFrame(scene, std::clamp(animation_.previewFrame, 0, scene.animation.frames - 1));
        shown.exposure.stepsOf(document_.series->size());  // an exposure the series lacks fails here, named
    }
    // The probes are drawn over the picture, not in it: pinning one does not render it again.
    shown.probes.clear();
    return shown;
}

void ViewerApp::addKey() {
    const int frame = animation_.nextKeyFrame;
    try {
        document_.scene.animation = animation_.addKey(frame, document_.scene);
        animation_.nextKeyFrame = frame + animation_.framesPerSecond;
        animation_.message = "key " + std::to_string(animation_.keys.size()) + " recorded at frame " +
                             std::to_string(frame) + "; the movie has " +
                             std::to_string(document_.scene.animation.frames) + " frames";
    } catch (const InputError& error) {
        animation_.message = error.what();
    }
}

void ViewerApp::startMovieExport() {
    if (movieExport_) return;
    if (animation_.moviePath.empty()) animation_.moviePath = defaultMoviePath(document_.sceneFile).string();
    try {
        movieExport_.emplace(document_.scene, document_.series, document_.frame, animation_.moviePath);
        animation_.exportProgress = 0.0;
        animation_.message.clear();
    } catch (const InputError& error) {
        animation_.message = error.what();
    }
}

void ViewerApp::continueMovieExport() {
    if (!movieExport_) return;
    try {
        const bool done = movieExport_->step(renderer_);
        animation_.exportProgress = movieExport_->progress();
        if (done) {
            animation_.message = "wrote " + movieExport_->target().string();
            std::cout << animation_.message << std::endl;
            movieExport_.reset();
            animation_.exportProgress = -1.0;
        }
    } catch (const InputError& error) {
        animation_.message = error.what();
        movieExport_.reset();  // removes the half-written movie
        animation_.exportProgress = -1.0;
    }
    // The export drew into the renderer's target: the view is drawn again.
    frame_.invalidate();
}

}  // namespace tstyles::viewer
