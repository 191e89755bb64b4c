// Build-time tool: draws the built-in lit-sphere styles (docs/styles.md) as PNGs plus styles.json.
// Usage:
//   generate_styles --output DIR [--size N] [--contact-sheet FILE]
#include <CLI/CLI.hpp>
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
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        // Help is a success; any other parse problem is a usage error: exit 2, like user errors.
        const int code = app.exit(error);
        return code == 0 ? 0 : 2;
    }

    try {
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
    } catch (const tstyles::InputError& error) {
        std::cerr << "generate_styles: " << error.what() << "\n";
        return 2;
    }
    return 0;
}
