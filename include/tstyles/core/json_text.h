// JSON text into a document, in one place: the scenes, the manifests, the check suites, the
// comparison thresholds, OME-Zarr metadata and ParaView .series files are all parsed here, so a bad
// document reads alike everywhere: "FILE: not valid JSON: parse error at line 2, column 5: ...".
// The typed reads of its values are JsonField's (json_field.h).
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace tstyles {

// Hand-written files (scenes, check suites) may explain themselves in // and /* */ comments;
// written ones (manifests, Zarr metadata) may not.
enum class JsonComments { Refused, Allowed };

// Throws InputError naming `origin` (a file, or empty for text from elsewhere) for text that is not
// JSON, that holds a number too large for a double (JSON has no infinity), or that gives a key twice
// in one object (naming its path: the parser would keep the last silently).
nlohmann::json parseJsonText(const std::string& text, const std::filesystem::path& origin, JsonComments comments);

// Whether `text` is JSON, for telling kinds of files apart: the document, or a discarded value
// (is_discarded()) where it is not. Never throws.
nlohmann::json probeJsonText(const std::string& text, JsonComments comments);

// A regular file's JSON (a FIFO would block the read: only a regular file is opened); `what` names
// the file's kind in errors ("scene file", "check suite").
nlohmann::json readJsonFile(const std::filesystem::path& file, const std::string& what, JsonComments comments);

}  // namespace tstyles
