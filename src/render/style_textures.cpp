// Uploading styles into a texture array and colour nodes into the node table.
#include "tstyles/render/style_textures.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "tstyles/image/image_io.h"
#include "tstyles/render/shader_contract.h"

namespace tstyles {
namespace {

using contract::StyleNode;

int mipLevels(int size) { return int(std::floor(std::log2(double(size)))) + 1; }

std::vector<std::uint8_t> toBytes(const Image& image) {
    std::vector<std::uint8_t> bytes(image.rgba.size());
    std::transform(image.rgba.begin(), image.rgba.end(), bytes.begin(), [](float value) {
        return std::uint8_t(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f));
    });
    return bytes;
}

}  // namespace

StyleTextures::StyleTextures() : nodeTable_(Buffer::create()) {}

void StyleTextures::update(const std::array<const TransferFunction1D*, 3>& tracks) {
    std::array<std::vector<ColorNode>, 3> nodes;
    for (std::size_t t = 0; t < 3; ++t) nodes[t] = tracks[t]->color;
    if (uploadedNodes_ && *uploadedNodes_ == nodes) return;

    std::vector<std::string> layerStyles;
    for (const auto& track : nodes)
        for (const auto& node : track)
            if (!node.style.empty() && std::find(layerStyles.begin(), layerStyles.end(), node.style) == layerStyles.end())
                layerStyles.push_back(node.style);

    if (layerStyles != layerStyles_ || !styles_) {
        // Load every style first, so a bad one leaves the current textures untouched.
        std::vector<Image> images;
        for (const auto& style : layerStyles) images.push_back(resizeImage(library_.image(style), kStyleSize, kStyleSize));
        Texture array = Texture::create(GL_TEXTURE_2D_ARRAY);
        glTextureStorage3D(array.id(), mipLevels(kStyleSize), GL_RGBA8, kStyleSize, kStyleSize,
                           GLsizei(std::max<std::size_t>(images.size(), 1)));
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        for (std::size_t layer = 0; layer < images.size(); ++layer)
            glTextureSubImage3D(array.id(), 0, 0, 0, GLint(layer), kStyleSize, kStyleSize, 1, GL_RGBA, GL_UNSIGNED_BYTE,
                                toBytes(images[layer]).data());
        glGenerateTextureMipmap(array.id());
        array.setFilter(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
        array.setClampToEdge();
        styles_.emplace(std::move(array));
        layerStyles_ = layerStyles;
    }

    std::vector<StyleNode> table;
    for (std::size_t t = 0; t < 3; ++t) {
        const bool styled = std::any_of(nodes[t].begin(), nodes[t].end(), [](const ColorNode& n) { return !n.style.empty(); });
        trackRanges_[t] = glm::ivec2(int(table.size()), styled ? int(nodes[t].size()) : 0);
        if (!styled) continue;
        for (const auto& node : nodes[t]) {
            const auto layer = node.style.empty()
                                   ? -1
                                   : int(std::find(layerStyles_.begin(), layerStyles_.end(), node.style) - layerStyles_.begin());
            table.push_back({glm::vec4(glm::vec3(node.color), float(node.at)), glm::ivec4(layer, 0, 0, 0)});
        }
    }
    nodeTable_.setData(std::as_bytes(std::span(table)));
    uploadedNodes_ = nodes;
}

int StyleTextures::styledTrackBits() const {
    int bits = 0;
    for (std::size_t t = 0; t < trackRanges_.size(); ++t)
        if (trackRanges_[t].y > 0) bits |= 1 << t;
    return bits;
}

int StyleTextures::singleNodeTrackBits() const {
    int bits = 0;
    for (std::size_t t = 0; t < trackRanges_.size(); ++t)
        if (trackRanges_[t].y == 1) bits |= 1 << t;
    return bits;
}

void StyleTextures::bind() const {
    styles_->bindToUnit(contract::STYLE_UNIT);
    nodeTable_.bindBase(GL_SHADER_STORAGE_BUFFER, contract::STYLE_NODE_BUFFER);
}

}  // namespace tstyles
