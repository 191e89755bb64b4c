// The styles a scene uses, on the GPU: one mipmapped 2D texture array (a layer per style) and a
// table of the colour nodes of each transfer function ("track"), so the shader can blend the two
// nodes around a value. Rebuilt only when the scene's colour nodes change.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/gl/objects.h"
#include "tstyles/render/style_library.h"
#include "tstyles/scene/transfer_function.h"

namespace tstyles {

// Side of every layer of the style array; styles of other sizes are resampled.
inline constexpr int kStyleSize = 256;

enum StyleTrack { kStfTrack = 0, kIndexTstfTrack = 1, kGradientTstfTrack = 2 };

class StyleTextures {
public:
    StyleTextures();

    // Loads and uploads the styles named by the colour nodes. Throws InputError for a bad style.
    void update(const std::array<const TransferFunction1D*, 3>& tracks);
    void bind() const;

    // Offset and count of each track's nodes in the node table; count 0 when the track uses no
    // style (the shader then takes the colour from the plain lookup table).
    const std::array<glm::ivec2, 3>& trackRanges() const { return trackRanges_; }
    // Bit t set where track t (STF, index TSTF, gradient TSTF) has a node with a style.
    int styledTrackBits() const;
    // Bit t set where track t has styles and one colour node (RaycastVariant::singleNodeStyleTracks).
    int singleNodeTrackBits() const;

private:
    StyleLibrary library_;
    std::optional<Texture> styles_;
    Buffer nodeTable_;
    std::vector<std::string> layerStyles_;
    std::array<glm::ivec2, 3> trackRanges_{};
    std::optional<std::array<std::vector<ColorNode>, 3>> uploadedNodes_;
};

}  // namespace tstyles
