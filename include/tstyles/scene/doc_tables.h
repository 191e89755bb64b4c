// The tables of docs/ that are made from the code's own tables: the scene keys (scene_keys.h) in
// scene-format.md, the compositors (temporal_compositors.h) in compositors.md and the ray modes
// (ray_modes.h) in ray-modes.md, the reader options (reader_option_table.h) in readers.md. Each stands
// between its two marker lines; build/tools/write_doc_tables docs writes them, and
// DocTables.TheDocsHoldTheGeneratedTables fails while one differs.
#pragma once

#include <filesystem>
#include <optional>
#include <span>
#include <string>

namespace tstyles {

struct GeneratedDocTable {
    const char* document;  // in docs/
    const char* begin;     // the marker lines around it
    const char* end;
    std::string (*table)();
};

std::span<const GeneratedDocTable> generatedDocTables();
// The text between the table's markers in a document's `text`, none where it lacks them.
std::optional<std::string> documentedTable(const std::string& text, const GeneratedDocTable& table);
// `text` with the table made afresh between its markers; an InputError naming `document` where it
// lacks them.
std::string withGeneratedTable(std::string text, const GeneratedDocTable& table, const std::filesystem::path& document);

}  // namespace tstyles
