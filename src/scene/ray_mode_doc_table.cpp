// docs/ray-modes.md's table of ray modes, from their table (ray_modes.h).
#include "tstyles/scene/ray_modes.h"

namespace tstyles {
namespace {

// "`attenuation` (1)", "`values` ([0.5])", "`opacities` (1 for each of `values`)".
std::string optionText(const RayModeOption& option) {
    std::string text = "`" + std::string(option.key) + "` (";
    if (option.kind == RayModeOptionKind::Number) text += formatNumber(option.defaultNumber);
    else if (option.countOf) text += formatNumber(option.defaultNumber) + " for each of `" + option.countOf + "`";
    else text += "[" + formatNumber(option.defaultNumber) + "], up to " + std::to_string(option.maxCount);
    return text + ")";
}

}  // namespace

std::string rayModeDocTable() {
    std::string table = "| name | shows | options (default) | needs the compositor's value | may stop early |\n"
                        "|---|---|---|---|---|\n";
    for (const RayModeInfo& info : kRayModes) {
        std::string options;
        for (const RayModeOption& option : info.options)
            options += (options.empty() ? "" : ", ") + optionText(option);
        table += "| `" + std::string(info.name) + "` | " + info.summary + " | " + options + " | " +
                 (info.needsValue ? "yes" : "no") + " | " + (info.stopsEarly ? "yes" : "no") + " |\n";
    }
    return table;
}

}  // namespace tstyles
