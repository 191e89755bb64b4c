// PNG output through OpenImageIO and the JSON index.
#include "style_files.h"

#include <OpenImageIO/imageio.h>

#include <nlohmann/json.hpp>

#include "tstyles/core/atomic_file.h"
#include "tstyles/core/errors.h"

namespace styles {

std::string styleFileName(const StyleDefinition& style) { return style.name + ".png"; }

void writePng(const RgbaImage& image, const std::filesystem::path& file) {
    tstyles::writeAtomically(file, [&](const std::filesystem::path& temporary) {
        auto output = OIIO::ImageOutput::create(temporary.string());
        if (!output) tstyles::throwInputError(file, "", "cannot create a PNG writer: " + OIIO::geterror());
        OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::UINT8);
        // Our alpha is straight already; without this the PNG writer would divide by it again.
        spec.attribute("oiio:UnassociatedAlpha", 1);
        if (!output->open(temporary.string(), spec))
            tstyles::throwInputError(file, "", "cannot open for writing: " + output->geterror());
        if (!output->write_image(OIIO::TypeDesc::UINT8, image.rgba.data()))
            tstyles::throwInputError(file, "", "write failed: " + output->geterror());
        if (!output->close())
            tstyles::throwInputError(file, "", "cannot finish writing: " + output->geterror());
    });
}

void writeStyleIndex(const std::vector<StyleDefinition>& styles, const std::filesystem::path& file) {
    auto list = nlohmann::ordered_json::array();
    for (const auto& style : styles)
        list.push_back(
            {{"name", style.name}, {"file", styleFileName(style)}, {"description", style.description}});
    const nlohmann::ordered_json index{{"styles", list}};
    tstyles::writeFileAtomically(file, index.dump(2) + "\n");
}

}  // namespace styles
