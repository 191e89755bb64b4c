// Annotations drawn on the CPU, shown as an ImGui image over the volume.
#include "annotation_overlay.h"

#include <cstdint>

#include <imgui.h>

#include "straight_bytes.h"
#include "tstyles/annotate/scene_annotations.h"
#include "tstyles/scene/camera.h"

namespace tstyles::viewer {

void AnnotationOverlay::redraw(glm::ivec2 frameSize, const Scene& scene, const Series& series,
                               const DisplayFrame& frame) {
    if (!font_) font_ = Font::openDefault();
    Scene sized = scene;
    sized.width = frameSize.x;
    sized.height = frameSize.y;
    Image overlay(frameSize.x, frameSize.y);
    const View view = resolveView(sized.camera, series.worldBounds(), frameSize.x, frameSize.y);
    drawAnnotations(overlay, sized, series, frame, view, *font_,
                    [this](const std::string& style) { return &styles_.image(style); });
    if (!texture_ || textureSize_ != frameSize) {
        texture_.emplace(Texture::create(GL_TEXTURE_2D));
        glTextureStorage2D(texture_->id(), 1, GL_RGBA8, frameSize.x, frameSize.y);
        texture_->setFilter(GL_LINEAR, GL_LINEAR);
        textureSize_ = frameSize;
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(texture_->id(), 0, 0, 0, frameSize.x, frameSize.y, GL_RGBA, GL_UNSIGNED_BYTE,
                        straightBytes(overlay).data());
}

void AnnotationOverlay::draw(const ScreenRect& rect, glm::ivec2 frameSize, const Scene& scene, const Series& series,
                             const DisplayFrame& frame) {
    if (!scene.annotations.any() || frameSize.x <= 0 || frameSize.y <= 0) return;
    if (!drawnScene_ || !(*drawnScene_ == scene) || textureSize_ != frameSize) {
        redraw(frameSize, scene, series, frame);
        drawnScene_ = scene;
    }
    ImGui::GetBackgroundDrawList()->AddImage(
        reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(texture_->id())), {rect.min.x, rect.min.y},
        {rect.max.x, rect.max.y});
}

}  // namespace tstyles::viewer
