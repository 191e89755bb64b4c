// The transfer functions of a scene baked for the GPU: the STF and the gradient-magnitude TSTF as
// 1D lookup textures, the index TSTF as one colour and opacity per time-step. Re-baked only when
// the scene's transfer functions change.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/gl/objects.h"
#include "tstyles/scene/transfer_function.h"

namespace tstyles {

// Entries of each 1D table; entry i holds the function at i / (kTransferTableSize - 1).
inline constexpr int kTransferTableSize = 1024;

// The table a 1D transfer function over [0,1] becomes (RGBA, straight colour and opacity).
std::vector<glm::vec4> bakeTransferTable(const TransferFunction1D& function);
// The densities where a baked table's opacity may be above 0, as (lowest, highest), with half an
// entry of margin for the filtering's rounding: outside it the table's lookup gives exactly 0
// opacity. (2, -1), an empty range, when the table is transparent everywhere.
glm::vec2 visibleDensityRange(const std::vector<glm::vec4>& table);
// Whether a baked table's opacity never falls from one entry to the next: its linear lookups then
// never fall as x rises either (RaycastVariant::stfOpacityRises).
bool opacityNeverFalls(const std::vector<glm::vec4>& table);
// One RGBA entry per time-step.
std::vector<glm::vec4> bakeIndexTstf(const IndexTstf& tstf, std::size_t timeStepCount);

class TransferTables {
public:
    TransferTables();

    // Re-bakes what changed; true when the STF did (empty-space skipping depends on it).
    bool update(const Stf& stf, const IndexTstf& indexTstf, const GradientTstf& gradientTstf,
                std::size_t timeStepCount);
    // The STF as baked into its table.
    const std::vector<glm::vec4>& stfEntries() const { return stfEntries_; }
    // visibleDensityRange of the STF's table, worked out when the STF changes.
    glm::vec2 stfVisibleRange() const { return stfVisibleRange_; }
    // opacityNeverFalls of the STF's table, worked out when the STF changes.
    bool stfOpacityRises() const { return stfOpacityRises_; }
    void bind() const;

private:
    Texture stfTable_;
    Texture gradientTstfTable_;
    Buffer indexTstfBuffer_;
    std::optional<Stf> bakedStf_;
    std::vector<glm::vec4> stfEntries_;
    glm::vec2 stfVisibleRange_{2.0f, -1.0f};
    bool stfOpacityRises_ = false;
    std::optional<IndexTstf> bakedIndexTstf_;
    std::optional<TransferFunction1D> bakedGradientCurve_;
    std::size_t bakedTimeStepCount_ = 0;
};

}  // namespace tstyles
