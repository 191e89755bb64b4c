// Densities quantised to 16 bits, premultiplied by validity when the series has missing values.
#include "tstyles/render/density_texels.h"

#include <algorithm>
#include <cmath>

namespace tstyles {

bool hasMissingValues(const Series& series) {
    return std::any_of(series.steps.begin(), series.steps.end(), [](const TimeStep& step) {
        return std::any_of(step.density.begin(), step.density.end(), [](float d) { return isMissing(d); });
    });
}

std::vector<std::uint16_t> densityTexels(const TimeStep& step, bool withValidity) {
    const auto quantise = [](float density) {
        return std::uint16_t(std::lround(std::clamp(density, 0.0f, 1.0f) * 65535.0f));
    };
    std::vector<std::uint16_t> texels;
    texels.reserve(step.density.size() * (withValidity ? 2 : 1));
    for (const float density : step.density) {
        if (!withValidity) {
            texels.push_back(quantise(density));
            continue;
        }
        const bool valid = !isMissing(density);
        texels.push_back(valid ? quantise(density) : 0);
        texels.push_back(valid ? 65535 : 0);
    }
    return texels;
}

}  // namespace tstyles
