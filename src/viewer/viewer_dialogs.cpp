// The file browser and the error dialog.
#include "viewer_dialogs.h"

#include <algorithm>
#include <iostream>

#include <imgui.h>
#include <imgui_stdlib.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "tstyles/data/series_opener.h"

namespace tstyles::viewer {
namespace {

const char* titleOf(FilePurpose purpose) {
    switch (purpose) {
        case FilePurpose::Open: return "Open scene or dataset###file dialog";
        case FilePurpose::SaveScene: return "Save scene as###file dialog";
        case FilePurpose::SaveScreenshot: return "Save screenshot as###file dialog";
        case FilePurpose::ExportProbes: return "Export the probes' values as CSV###file dialog";
    }
    return "###file dialog";
}

// What the listing says a file or folder is ("" for nothing beside it); none: not listed. Opening
// lists what the program reads (the format table's extensions and folders, through formatNamedBy,
// and .json scenes and manifests); saving lists the kind of file being saved.
std::optional<std::string> describeEntry(const std::filesystem::directory_entry& entry, FilePurpose purpose) {
    std::error_code error;
    const std::string name = entry.path().filename().string();
    const bool folder = entry.is_directory(error);
    if (folder && name.front() == '.') return std::nullopt;
    const std::string extension = entry.path().extension().string();
    if (purpose == FilePurpose::SaveScreenshot)
        return folder || extension == ".png" ? std::optional<std::string>("") : std::nullopt;
    if (purpose == FilePurpose::ExportProbes)
        return folder || extension == ".csv" ? std::optional<std::string>("") : std::nullopt;
    const std::string format = purpose == FilePurpose::Open ? formatNamedBy(entry.path()) : "";
    if (!format.empty()) return format;
    if (folder) return "";
    if (extension == ".json") return purpose == FilePurpose::Open ? "scene or manifest" : "";
    return std::nullopt;
}

bool enterPressed() { return ImGui::IsKeyPressed(GLFW_KEY_ENTER) || ImGui::IsKeyPressed(GLFW_KEY_KP_ENTER); }

}  // namespace

void FileDialog::open(FilePurpose purpose, const std::filesystem::path& folder, const std::string& suggestedName) {
    purpose_ = purpose;
    name_ = suggestedName;
    enter(folder);
    openRequested_ = true;
}

void FileDialog::enter(const std::filesystem::path& folder) {
    folder_ = std::filesystem::absolute(folder).lexically_normal();
    entries_.clear();
    listingError_.clear();
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder_, error)) {
        const std::optional<std::string> kind = describeEntry(entry, purpose_);
        if (!kind) continue;
        std::error_code ignored;
        const bool isFolder = entry.is_directory(ignored);
        const std::string name = entry.path().filename().string() + (isFolder ? "/" : "");
        entries_.push_back({entry.path(), isFolder, kind->empty() ? name : name + "   (" + *kind + ")"});
    }
    if (error) listingError_ = "cannot list " + folder_.string() + ": " + error.message();
    std::sort(entries_.begin(), entries_.end(), [](const Entry& a, const Entry& b) {
        return a.folder != b.folder ? a.folder : a.path.filename() < b.path.filename();
    });
}

std::optional<FileChoice> FileDialog::draw() {
    const char* title = titleOf(purpose_);
    if (openRequested_) {
        ImGui::OpenPopup(title);
        openRequested_ = false;
    }
    ImGui::SetNextWindowSize({560.0f, 400.0f}, ImGuiCond_Appearing);
    if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_NoSavedSettings)) return std::nullopt;
    std::optional<FileChoice> choice;
    auto choose = [&](const std::filesystem::path& path) {
        choice = FileChoice{purpose_, path};
        ImGui::CloseCurrentPopup();
    };

    if (ImGui::Button("Up")) enter(folder_.parent_path());
    ImGui::SameLine();
    ImGui::TextWrapped("%s", folder_.string().c_str());
    const float footer = 2.0f * ImGui::GetFrameHeightWithSpacing();
    ImGui::BeginChild("entries", {0.0f, -footer}, true);
    if (!listingError_.empty()) ImGui::TextColored({1.0f, 0.5f, 0.4f, 1.0f}, "%s", listingError_.c_str());
    std::optional<std::filesystem::path> enterFolder;
    for (const Entry& entry : entries_) {
        const bool folder = entry.folder;
        const std::string name = entry.path.filename().string();
        if (ImGui::Selectable(entry.label.c_str(), !folder && name == name_, ImGuiSelectableFlags_AllowDoubleClick)) {
            if (folder && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left))
                enterFolder = entry.path;
            else if (folder)
                name_ = name;
            else if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left))
                choose(entry.path);
            else
                name_ = name;
        }
    }
    ImGui::EndChild();
    if (enterFolder) enter(*enterFolder);

    ImGui::SetNextItemWidth(-170.0f);
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::InputText("##name", &name_);
    const std::filesystem::path chosen =
        std::filesystem::path(name_).is_absolute() ? std::filesystem::path(name_) : folder_ / name_;
    ImGui::SameLine();
    const bool accept = ImGui::Button(purpose_ == FilePurpose::Open ? "Open" : "Save") || enterPressed();
    if (accept && !name_.empty() && !choice) choose(chosen);
    ImGui::SameLine();
    if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(GLFW_KEY_ESCAPE)) ImGui::CloseCurrentPopup();
    if (purpose_ == FilePurpose::Open)
        ImGui::TextDisabled("A scene (.json), or a dataset: a file or folder shown with its format.");
    ImGui::EndPopup();
    return choice;
}

QuitDialog::Answer QuitDialog::draw(bool canSave) {
    constexpr const char* title = "Unsaved changes###quit dialog";
    if (openRequested_) ImGui::OpenPopup(title);
    openRequested_ = false;
    if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings))
        return Answer::None;
    Answer answer = Answer::None;
    ImGui::TextUnformatted("The scene has changes that are not saved.");
    if (canSave && ImGui::Button("Save and quit")) answer = Answer::SaveAndQuit;
    if (canSave) ImGui::SameLine();
    if (ImGui::Button("Quit without saving")) answer = Answer::Quit;
    ImGui::SameLine();
    if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(GLFW_KEY_ESCAPE)) answer = Answer::Cancel;
    if (answer != Answer::None) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    return answer;
}

void ErrorDialog::show(std::string message) {
    std::cerr << "tstyles view: " << message << "\n";
    messages_.push_back(std::move(message));
    openRequested_ = true;
}

void ErrorDialog::draw() {
    constexpr const char* title = "Something went wrong###error dialog";
    if (openRequested_ && !ImGui::IsPopupOpen(title)) ImGui::OpenPopup(title);
    openRequested_ = false;
    ImGui::SetNextWindowSize({480.0f, 0.0f}, ImGuiCond_Appearing);
    if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_NoSavedSettings)) return;
    for (const std::string& message : messages_) ImGui::TextWrapped("%s", message.c_str());
    ImGui::Separator();
    ImGui::TextDisabled("The current scene is unchanged.");
    if (ImGui::Button("OK", {120.0f, 0.0f}) || enterPressed() || ImGui::IsKeyPressed(GLFW_KEY_ESCAPE)) {
        messages_.clear();
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

}  // namespace tstyles::viewer
