// Back-buffer read-back for screenshots.
#include "window_capture.h"

#include <algorithm>

#include "tstyles/gl/gl_api.h"

namespace tstyles::viewer {

Image captureWindowRegion(glm::ivec2 offset, glm::ivec2 size) {
    Image bottomUp(size.x, size.y);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glNamedFramebufferReadBuffer(0, GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(offset.x, offset.y, size.x, size.y, GL_RGBA, GL_FLOAT, bottomUp.rgba.data());
    Image image(size.x, size.y);
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            glm::vec4 pixel = bottomUp.at(x, size.y - 1 - y);
            pixel.a = 1.0f;
            image.set(x, y, pixel);
        }
    return image;
}

}  // namespace tstyles::viewer
