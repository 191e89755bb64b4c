// The generated tables of docs/ and where they stand there.
#include "tstyles/scene/doc_tables.h"

#include "tstyles/core/errors.h"
#include "tstyles/data/reader_option_table.h"
#include "tstyles/scene/ray_modes.h"
#include "tstyles/scene/scene_keys.h"
#include "tstyles/scene/temporal_compositors.h"

namespace tstyles {
namespace {

constexpr GeneratedDocTable kDocTables[] = {
    {"scene-format.md", kSceneKeyTableBegin, kSceneKeyTableEnd, sceneKeyTable},
    {"compositors.md", kCompositorTableBegin, kCompositorTableEnd, compositorDocTable},
    {"ray-modes.md", kRayModeTableBegin, kRayModeTableEnd, rayModeDocTable},
    {"readers.md", kReaderOptionTableBegin, kReaderOptionTableEnd, readerOptionsMarkdown},
};

// Where the table's text starts (after the begin marker's line) and ends (at the end marker).
std::optional<std::pair<std::size_t, std::size_t>> tableSpan(const std::string& text, const GeneratedDocTable& table) {
    const std::size_t begin = text.find(table.begin);
    const std::size_t end = text.find(table.end);
    if (begin == std::string::npos || end == std::string::npos || end < begin) return std::nullopt;
    return std::pair{begin + std::string(table.begin).size() + 1, end};
}

}  // namespace

std::span<const GeneratedDocTable> generatedDocTables() { return kDocTables; }

std::optional<std::string> documentedTable(const std::string& text, const GeneratedDocTable& table) {
    const auto span = tableSpan(text, table);
    if (!span) return std::nullopt;
    return text.substr(span->first, span->second - span->first);
}

std::string withGeneratedTable(std::string text, const GeneratedDocTable& table, const std::filesystem::path& document) {
    const auto span = tableSpan(text, table);
    if (!span) throwInputError(document, "", "has no markers of its generated table");
    text.replace(span->first - 1, span->second - span->first + 1, "\n" + table.table());
    return text;
}

}  // namespace tstyles
