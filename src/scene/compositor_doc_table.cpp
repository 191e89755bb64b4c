// docs/compositors.md's table of compositors, from their table (temporal_compositors.h).
#include "tstyles/scene/temporal_compositors.h"

namespace tstyles {
namespace {

const char* readsText(CompositorReads reads) {
    switch (reads) {
        case CompositorReads::IndexTstf: return "index TSTF";
        case CompositorReads::GradientTstf: return "gradient TSTF";
        case CompositorReads::Composited: return "composited";
    }
    return "";
}

// C is the series' typical largest change over time, T its time span (docs/compositors.md).
const char* rangeText(AutomaticRange range) {
    switch (range) {
        case AutomaticRange::Change: return "[0, C]";
        case AutomaticRange::HalfChange: return "[0, C / 2]";
        case AutomaticRange::SignedChange: return "[-C, C]";
        case AutomaticRange::SignedPerTime: return "[-C / T, C / T]";
    }
    return "";
}

// "`threshold` (0.5)", "`steps` ([0, last])", "`direction` ("rising"; or "falling")".
std::string optionText(const CompositorOption& option) {
    std::string text = "`" + std::string(option.key) + "` (";
    switch (option.kind) {
        case CompositorOptionKind::Number: text += formatNumber(option.defaultNumber); break;
        case CompositorOptionKind::TimeStepPair: text += "[0, last]"; break;
        case CompositorOptionKind::Choice: {
            const std::vector<std::string> names = option.choiceNames();
            text += "\"" + names.front() + "\"";
            for (std::size_t i = 1; i < names.size(); ++i) text += (i == 1 ? "; or \"" : ", \"") + names[i] + "\"";
            break;
        }
    }
    return text + ")";
}

}  // namespace

std::string compositorDocTable() {
    std::string table = "| name | computes | reads | options (default) | `\"auto\"` gradient range |\n"
                        "|---|---|---|---|---|\n";
    for (std::size_t line = 0; line < kTemporalCompositors.size(); ++line) {
        const TemporalCompositorInfo& info = kTemporalCompositors[line];
        if (TemporalCompositor(line) == kCustomCompositor) {
            table += "| the scene's own | your GLSL (below) | index or gradient TSTF, as it says | | " +
                     std::string(rangeText(info.range)) + " |\n";
            continue;
        }
        std::string options;
        for (const CompositorOption& option : info.options)
            options += (options.empty() ? "" : ", ") + optionText(option);
        const std::string range = info.reads == CompositorReads::GradientTstf ? rangeText(info.range) : "";
        table += "| `" + std::string(info.name) + "` | " + info.summary + " | " + readsText(info.reads) + " | " +
                 options + " | " + range + " |\n";
    }
    return table;
}

}  // namespace tstyles
