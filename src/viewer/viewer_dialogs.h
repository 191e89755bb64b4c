// The viewer's modal dialogs: a small file browser (Dear ImGui has none) for opening scenes and
// datasets and for saving scenes and screenshots, and the error dialog that reports a file that
// could not be used while the current scene stays as it was.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace tstyles::viewer {

enum class FilePurpose { Open, SaveScene, SaveScreenshot, ExportProbes };

struct FileChoice {
    FilePurpose purpose;
    std::filesystem::path path;
};

class FileDialog {
public:
    void open(FilePurpose purpose, const std::filesystem::path& folder, const std::string& suggestedName);
    // Draws the dialog while it is open; returns the choice in the frame it is made.
    std::optional<FileChoice> draw();

private:
    // A line of the listing: the format beside it is worked out once, when the folder is entered.
    struct Entry {
        std::filesystem::path path;
        bool folder = false;
        std::string label;  // "ocean.nc   (NetCDF)", "bounce/   (tstyles manifest)"
    };
    void enter(const std::filesystem::path& folder);

    bool openRequested_ = false;
    FilePurpose purpose_ = FilePurpose::Open;
    std::filesystem::path folder_;
    std::vector<Entry> entries_;
    std::string name_;
    std::string listingError_;
};

// "The scene has unsaved changes": asked before the viewer closes.
class QuitDialog {
public:
    enum class Answer { None, SaveAndQuit, Quit, Cancel };
    void ask() { openRequested_ = true; }
    // `canSave`: the scene has a file to be saved to.
    Answer draw(bool canSave);

private:
    bool openRequested_ = false;
};

class ErrorDialog {
public:
    // Shows the message (and writes it to stderr, for whoever started the viewer from a shell).
    void show(std::string message);
    void draw();
    bool visible() const { return !messages_.empty(); }

private:
    std::vector<std::string> messages_;
    bool openRequested_ = false;
};

}  // namespace tstyles::viewer
