// Small textures of lit-sphere styles for the transfer-function editors: a styled node is drawn as
// a thumbnail of its sphere. Loaded once per style; a style that cannot be read gets none (the
// renderer reports the error).
#pragma once

#include <map>
#include <optional>
#include <string>

#include "tstyles/gl/objects.h"
#include "tstyles/render/style_library.h"

namespace tstyles::viewer {

class StyleThumbnails {
public:
    // The GL texture of the style's thumbnail, or nothing if the style cannot be loaded.
    std::optional<GLuint> textureOf(const std::string& style);

private:
    StyleLibrary library_;
    std::map<std::string, std::optional<Texture>> thumbnails_;
};

}  // namespace tstyles::viewer
