// Scene or dataset (input_kind.h): by the first character, then by the JSON's keys.
#include "tstyles/scene/input_kind.h"

#include <cctype>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "tstyles/core/json_text.h"
#include "tstyles/core/user_paths.h"
#include "tstyles/data/series_opener.h"

namespace tstyles {

InputKind classifyInput(const std::filesystem::path& path) {
    const PathKind kind = userPathKind(PathSource{}, path);
    if (kind == PathKind::Folder) return InputKind::Dataset;
    // A FIFO or device would block the peek below: it is refused, named, as a scene file if named so,
    // else as a data file.
    if (kind == PathKind::Other) return path.extension() == ".json" ? InputKind::Scene : InputKind::Dataset;
    std::ifstream stream(path, std::ios::binary);
    if (!stream) return InputKind::Scene;
    char first = 0;
    while (stream.get(first) && std::isspace(static_cast<unsigned char>(first))) {
    }
    // Not JSON (which starts with an object or a comment): a data file, left to the opener.
    // A ParaView .series file is JSON too: its name says what it is.
    if (!isManifestInput(path) && (isNamedLikeSeriesFile(path) || !stream || (first != '{' && first != '/')))
        return InputKind::Dataset;
    stream.clear();
    stream.seekg(0);
    std::stringstream text;
    text << stream.rdbuf();
    const nlohmann::json json = probeJsonText(text.str(), JsonComments::Allowed);
    if (json.is_object() && !json.contains("dataset") && (json.contains("time_steps") || json.contains("format")))
        return InputKind::Dataset;
    return InputKind::Scene;
}

}  // namespace tstyles
