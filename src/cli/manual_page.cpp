// tstyles(1) in roff from the CLI11 app: every visible subcommand with its options and their help.
#include "manual_page.h"

#include <memory>
#include <sstream>

#include <CLI/CLI.hpp>

#include "tstyles/core/atomic_file.h"

namespace tstyles::cli {
namespace {

// Roff text: backslashes and hyphens escaped, and no line may start with a control character.
std::string roffText(const std::string& text) {
    std::string escaped;
    bool lineStart = true;
    for (char c : text) {
        if (lineStart && (c == '.' || c == '\'')) escaped += "\\&";
        if (c == '\\') escaped += "\\e";
        else if (c == '-') escaped += "\\-";
        else escaped += c;
        lineStart = c == '\n';
    }
    return escaped;
}

// One option as a tagged paragraph: its names (or its positional name) in bold, its value's type,
// then its help and default.
void writeOption(std::ostringstream& out, const CLI::Option& option) {
    const bool positional = option.get_positional() && option.get_name(false, true) == option.get_name(true);
    std::string names = positional ? option.get_name(true) : option.get_name(false, true);
    for (std::size_t comma = names.find(','); comma != std::string::npos; comma = names.find(',', comma + 2))
        names.replace(comma, 1, ", ");
    out << ".TP\n" << (positional ? "\\fI" : "\\fB") << roffText(names) << "\\fR";
    if (!positional && option.get_expected_max() != 0 && !option.get_type_name().empty())
        out << " \\fI" << roffText(option.get_type_name()) << "\\fR";
    out << "\n" << roffText(option.get_description());
    if (!option.get_default_str().empty()) out << " (default: " << roffText(option.get_default_str()) << ")";
    out << "\n";
}

void writeOptions(std::ostringstream& out, CLI::App& app) {
    for (const CLI::Option* option : app.get_options([](const CLI::Option* o) { return !o->get_group().empty(); }))
        writeOption(out, *option);
}

std::vector<CLI::App*> visibleSubcommands(CLI::App& app) {
    return app.get_subcommands([](CLI::App* sub) { return !sub->get_group().empty(); });
}

}  // namespace

std::string manualPageRoff(CLI::App& app) {
    std::ostringstream out;
    out << ".TH TSTYLES 1 \"\" \"tstyles " TSTYLES_VERSION "\" \"User Commands\"\n"
        << ".\\\" Written by `tstyles manual-page` at build time from the program's own options: do not edit.\n"
        << ".SH NAME\ntstyles \\- " << roffText(app.get_description()) << "\n"
        << ".SH SYNOPSIS\n.B tstyles\n\\fISUBCOMMAND\\fR [\\fIOPTIONS\\fR] [\\fIINPUT\\fR...]\n"
        << ".br\n.B tstyles\n[\\fB\\-h\\fR | \\fB\\-\\-version\\fR]\n"
        << ".SH DESCRIPTION\n" << roffText(app.get_description())
        << ". Each subcommand below has its own options; \\fBtstyles \\fISUBCOMMAND\\fB \\-\\-help\\fR prints them.\n"
        << ".SH OPTIONS\n";
    writeOptions(out, app);
    out << ".SH SUBCOMMANDS\n";
    for (CLI::App* sub : visibleSubcommands(app)) {
        out << ".SS \"tstyles " << roffText(sub->get_name()) << "\"\n" << roffText(sub->get_description()) << "\n";
        writeOptions(out, *sub);
    }
    out << ".SH EXIT STATUS\n0 success; 1 an internal error; 2 bad input (one line names the file, the field and the "
           "problem); 3 no usable OpenGL 4.5 context; 130 interrupted.\n"
        << ".SH ENVIRONMENT\n"
        << ".TP\n.B TSTYLES_DATA_DIR\nThe bundled data (styles, scenes, datasets) instead of the installed "
           "\\fIshare/tstyles\\fR beside the program.\n"
        << ".TP\n.B TSTYLES_FONT\nThe legend font instead of DejaVu Sans (fonts\\-dejavu\\-core).\n"
        << ".TP\n.B TSTYLES_SHADER_DIR\nShaders from this folder instead of the embedded copy.\n"
        << ".TP\n.B TSTYLES_GL_DEBUG\n1: report OpenGL errors (KHR_debug).\n"
        << ".SH FILES\n.TP\n.I PREFIX/share/tstyles\nBuilt\\-in lit\\-sphere styles, the bundled scenes and "
           "their datasets; \\fBtstyles \\-\\-version\\fR says which folder is used.\n"
        << ".SH SEE ALSO\nThe documentation in the source tree, docs/*.md (docs/install.md for this page).\n";
    return out.str();
}

Command addManualPageCommand(CLI::App& app) {
    auto output = std::make_shared<std::filesystem::path>();
    CLI::App* command = app.add_subcommand("manual-page", "Write the man page tstyles.1 (the build runs it)");
    command->group("");  // hidden: a build step, not a user's command
    command->add_option("--output", *output, "The .1 file to write")->required();
    return {command, [output, &app] {
                writeFileAtomically(*output, manualPageRoff(app));
                return kExitSuccess;
            }};
}

}  // namespace tstyles::cli
