// `tstyles packaging-file desktop-entry|mime-package|description --output FILE`.
#include "packaging_files.h"

#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>

#include "tstyles/core/atomic_file.h"
#include "tstyles/data/format_listing.h"

namespace tstyles::cli {

Command addPackagingFileCommand(CLI::App& app) {
    struct Choice {
        std::string kind;
        std::filesystem::path output;
    };
    auto choice = std::make_shared<Choice>();
    CLI::App* command =
        app.add_subcommand("packaging-file", "Write the desktop entry, MIME package or package description (the build runs it)");
    command->group("");  // hidden: a build step, not a user's command
    command->add_option("kind", choice->kind, "What to write")
        ->required()
        ->check(CLI::IsMember({"desktop-entry", "mime-package", "description"}));
    command->add_option("--output", choice->output, "The file to write")->required();
    return {command, [choice] {
                const std::map<std::string, std::string (*)()> texts = {
                    {"desktop-entry", desktopEntryText}, {"mime-package", mimePackageText},
                    {"description", packageDescriptionText}};
                writeFileAtomically(choice->output, texts.at(choice->kind)());
                return kExitSuccess;
            }};
}

}  // namespace tstyles::cli
