// Loading style images into thumbnail textures for ImGui.
#include "style_thumbnails.h"

#include "straight_bytes.h"
#include "tstyles/core/errors.h"
#include "tstyles/image/image_io.h"

namespace tstyles::viewer {
namespace {

constexpr int kThumbnailSize = 32;

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
