// Build-time tool: draws the built-in lit-sphere styles (docs/styles.md) as PNGs plus styles.json.
// Usage:
//   generate_styles --output DIR [--size N] [--contact-sheet FILE]
#include <CLI/CLI.hpp>

#include "generator_main.h"
#include <filesystem>
#include <iostream>
#include <system_error>

#include "styles/contact_sheet.h"
#include "styles/lit_sphere_raster.h"
#include "styles/style_catalog.h"
#include "styles/style_files.h"
#include "tstyles/core/errors.h"

int main(int argc, char** argv) {
    CLI::App app{"Writes the built-in lit-sphere styles as RGBA PNGs and a styles.json index."};
    std::filesystem::path output;
    int size = 256;
    app.add_option("--output", output, "Directory for the PNGs and styles.json")->required();
    app.add_option("--size", size, "Width and height of each square image in pixels")
        ->check(CLI::Range(8, 4096));
    std::filesystem::path contactSheet;
    app.add_option("--contact-sheet", contactSheet,
                   "Also write one picture of all styles, cut out over a checkerboard (for the docs)");
    if (const auto exitCode = generator::parseArguments(app, argc, argv)) return *exitCode;

    const int exitCode = generator::runReportingErrors("generate_styles", [&] {
        std::error_code error;
        std::filesystem::create_directories(output, error);
        if (error) tstyles::throwInputError(output, "", "cannot create the folder: " + error.message());
        const auto library = styles::builtInStyles();
        for (const auto& style : library)
            styles::writePng(styles::rasterizeLitSphere(style, size), output / styles::styleFileName(style));
        styles::writeStyleIndex(library, output / "styles.json");
        if (!contactSheet.empty()) styles::writePng(styles::drawContactSheet(library, size, 6), contactSheet);
        std::cout << "wrote " << library.size() << " styles of " << size << "x" << size << " to "
                  << output.string() << "\n";
    });
    return exitCode;
}
