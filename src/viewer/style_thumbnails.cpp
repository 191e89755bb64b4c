// Loading style images into thumbnail textures for ImGui.
#include "style_thumbnails.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "tstyles/core/errors.h"
#include "tstyles/image/image_io.h"

namespace tstyles::viewer {
namespace {

constexpr int kThumbnailSize = 32;

// ImGui blends straight (not premultiplied) colours; our images carry associated alpha.
std::vector<std::uint8_t> straightBytes(const Image& image) {
    std::vector<std::uint8_t> bytes(image.rgba.size());
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
        const float alpha = image.rgba[i + 3];
        for (std::size_t c = 0; c < 4; ++c) {
            const float value = c < 3 ? (alpha > 0.0f ? image.rgba[i + c] / alpha : 0.0f) : alpha;
            bytes[i + c] = std::uint8_t(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f));
        }
    }
    return bytes;
}

}  // namespace

std::optional<GLuint> StyleThumbnails::textureOf(const std::string& style) {
    auto found = thumbnails_.find(style);
    if (found == thumbnails_.end()) {
        std::optional<Texture> texture;
        try {
            const Image thumbnail = resizeImage(library_.image(style), kThumbnailSize, kThumbnailSize);
            texture.emplace(Texture::create(GL_TEXTURE_2D));
            glTextureStorage2D(texture->id(), 1, GL_RGBA8, kThumbnailSize, kThumbnailSize);
            glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
            glTextureSubImage2D(texture->id(), 0, 0, 0, kThumbnailSize, kThumbnailSize, GL_RGBA, GL_UNSIGNED_BYTE,
                                straightBytes(thumbnail).data());
            texture->setFilter(GL_LINEAR, GL_LINEAR);
        } catch (const InputError&) {
            texture.reset();  // shown as a plain sphere marker; the renderer names the problem
        }
        found = thumbnails_.emplace(style, std::move(texture)).first;
    }
    if (!found->second) return std::nullopt;
    return found->second->id();
}

}  // namespace tstyles::viewer
