// Resolving and loading lit-sphere style images.
#include "tstyles/render/style_library.h"

#include <algorithm>

#include "tstyles/core/bundled_data.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/user_paths.h"
#include "tstyles/image/image_io.h"
#include "tstyles/scene/style_reference.h"

namespace tstyles {

std::filesystem::path resolveStyleFile(const std::string& style) {
    if (isStyleFile(style)) return style;
    return bundledDataDirectory() / "styles" / (style + ".png");
}

std::vector<std::string> builtInStyleNames() {
    std::vector<std::string> names;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(bundledDataDirectory() / "styles", error))
        if (entry.path().extension() == ".png") names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

const Image& StyleLibrary::image(const std::string& style) {
    if (auto found = loaded_.find(style); found != loaded_.end()) return found->second;
    const std::filesystem::path file = resolveStyleFile(style);
    const PathKind kind = userPathKind({"", "style"}, file);
    if (!isStyleFile(style) && kind == PathKind::Missing) {
        std::string known;
        for (const auto& name : builtInStyleNames()) known += (known.empty() ? "" : ", ") + name;
        throwInputError(file, "style", "no built-in style \"" + style + "\" (built-in: " + known + ")");
    }
    if (kind == PathKind::Missing) throwInputError(file, "style", "no such file");
    Image image = readImageIsolated(file);
    if (image.width != image.height)
        throwInputError(file, "style", "a lit-sphere style must be square, this image is " +
                                           std::to_string(image.width) + "x" + std::to_string(image.height));
    return loaded_.emplace(style, std::move(image)).first->second;
}

}  // namespace tstyles
