// OME-NGFF multiscales to axes and levels; the checks follow the spec's "MUST"s that our reading
// depends on (axis kinds and count, one scale per level, transforms of the right length).
#include "ome_multiscales.h"

#include <set>

#include "tstyles/core/errors.h"
#include "tstyles/core/json_field.h"
#include "zarr_json.h"

namespace tstyles {
namespace {

OmeAxisType axisTypeNamed(const std::string& type, const std::string& name, const std::filesystem::path& file,
                          const std::string& field) {
    if (type == "time") return OmeAxisType::Time;
    if (type == "channel") return OmeAxisType::Channel;
    if (type == "space") return OmeAxisType::Space;
    // Versions before 0.4 name the axes only: t, c, z, y, x.
    if (type.empty() && name == "t") return OmeAxisType::Time;
    if (type.empty() && name == "c") return OmeAxisType::Channel;
    if (type.empty() && (name == "x" || name == "y" || name == "z")) return OmeAxisType::Space;
    throwInputError(file, field, "axis \"" + name + "\" of type \"" + type +
                                     "\": only time, channel and space axes can be shown as a volume over time");
}

std::vector<OmeAxis> readAxes(const nlohmann::json& multiscale, const std::filesystem::path& file) {
    std::vector<OmeAxis> axes;
    // 0.1 and 0.2 have no axes: their arrays are always t, c, z, y, x.
    if (!multiscale.contains("axes")) {
        for (const char* name : {"t", "c", "z", "y", "x"})
            axes.push_back({name, axisTypeNamed("", name, file, "multiscales[0].axes"), ""});
        return axes;
    }
    const auto& list = multiscale["axes"];
    if (!list.is_array() || list.size() < 2 || list.size() > 5)
        throwInputError(file, "multiscales[0].axes", "must list 2 to 5 axes, found " + list.dump());
    std::set<std::string> names;
    for (std::size_t index = 0; index < list.size(); ++index) {
        const std::string field = "multiscales[0].axes[" + std::to_string(index) + "]";
        OmeAxis axis;
        if (list[index].is_string()) {
            axis.name = list[index].get<std::string>();
            axis.type = axisTypeNamed("", axis.name, file, field);
        } else {
            axis.name = JsonField(file, list[index], field).member("name").string();
            const std::string type = list[index].contains("type") ? JsonField(file, list[index]["type"], field + ".type").string() : "";
            axis.type = axisTypeNamed(type, axis.name, file, field);
            if (list[index].contains("unit")) axis.unit = JsonField(file, list[index]["unit"], field + ".unit").string();
        }
        if (!names.insert(axis.name).second) throwInputError(file, field, "repeats the axis name \"" + axis.name + "\"");
        axes.push_back(axis);
    }
    return axes;
}

// A list of transforms: one scale (or identity), then at most one translation.
void applyTransforms(const nlohmann::json& list, std::size_t axisCount, const std::filesystem::path& file,
                     const std::string& field, std::vector<double>& scale, std::vector<double>& translation) {
    if (!list.is_array()) throwInputError(file, field, "must be a list of transformations");
    std::vector<double> ownScale(axisCount, 1.0), ownTranslation(axisCount, 0.0);
    for (std::size_t index = 0; index < list.size(); ++index) {
        const std::string at = field + "[" + std::to_string(index) + "]";
        const std::string type = JsonField(file, list[index], at).member("type").string();
        if (type == "identity") continue;
        if (type != "scale" && type != "translation")
            throwInputError(file, at + ".type", "\"" + type + "\" is not a transformation this reader knows (scale, translation)");
        if (list[index].contains("path"))
            throwInputError(file, at + ".path", "transformations stored in arrays are not supported");
        auto values = JsonField(file, list[index], at).member(type).finiteNumbers();
        if (values.size() != axisCount)
            throwInputError(file, at + "." + type, "has " + std::to_string(values.size()) + " values for " +
                                                       std::to_string(axisCount) + " axes");
        (type == "scale" ? ownScale : ownTranslation) = values;
    }
    // Composed after what came before: x' = s * x + t applied to the earlier s0 * i + t0.
    for (std::size_t axis = 0; axis < axisCount; ++axis) {
        scale[axis] *= ownScale[axis];
        translation[axis] = translation[axis] * ownScale[axis] + ownTranslation[axis];
    }
}

std::vector<OmeLevel> readLevels(const nlohmann::json& multiscale, std::size_t axisCount, const std::filesystem::path& file) {
    const auto& datasets = JsonField(file, multiscale, "multiscales[0]").member("datasets").value();
    if (!datasets.is_array() || datasets.empty())
        throwInputError(file, "multiscales[0].datasets", "must list at least one resolution level");
    std::vector<OmeLevel> levels;
    for (std::size_t index = 0; index < datasets.size(); ++index) {
        const std::string field = "multiscales[0].datasets[" + std::to_string(index) + "]";
        OmeLevel level;
        level.path = JsonField(file, datasets[index], field).member("path").string();
        const std::filesystem::path relative(level.path);
        if (level.path.empty() || relative.is_absolute() || level.path.find("..") != std::string::npos)
            throwInputError(file, field + ".path", "\"" + level.path + "\" is not a path inside the store");
        level.scale.assign(axisCount, 1.0);
        level.translation.assign(axisCount, 0.0);
        if (datasets[index].contains("coordinateTransformations"))
            applyTransforms(datasets[index]["coordinateTransformations"], axisCount, file,
                            field + ".coordinateTransformations", level.scale, level.translation);
        if (multiscale.contains("coordinateTransformations"))
            applyTransforms(multiscale["coordinateTransformations"], axisCount, file,
                            "multiscales[0].coordinateTransformations", level.scale, level.translation);
        levels.push_back(level);
    }
    return levels;
}

std::vector<std::string> readChannelLabels(const nlohmann::json& attributes) {
    std::vector<std::string> labels;
    // omero is transitional metadata: labels are read where they are plain strings, never required.
    const auto omero = attributes.find("omero");
    if (omero == attributes.end() || !omero->is_object() || !omero->contains("channels")) return labels;
    const auto& channels = (*omero)["channels"];
    if (!channels.is_array()) return labels;
    for (const auto& channel : channels)
        labels.push_back(channel.is_object() && channel.contains("label") && channel["label"].is_string()
                             ? channel["label"].get<std::string>()
                             : "");
    return labels;
}

// 0.4 keeps multiscales in the attributes; 0.5 under attributes.ome, with the version beside it.
const nlohmann::json& omeAttributes(const nlohmann::json& attributes, const std::filesystem::path& file, int zarrFormat) {
    if (zarrFormat == 3 && attributes.contains("ome")) return attributes["ome"];
    if (!attributes.contains("multiscales"))
        throwInputError(file, zarrFormat == 3 ? "attributes.ome.multiscales" : "multiscales",
                        "is missing: this Zarr group is not an OME-Zarr image (an HCS plate or a bare group is not read)");
    return attributes;
}

}  // namespace

std::filesystem::path zarrGroupFile(const std::filesystem::path& folder) {
    std::error_code error;
    for (const char* name : {"zarr.json", ".zattrs", ".zgroup"})
        if (std::filesystem::is_regular_file(folder / name, error)) return folder / name;
    return {};
}

OmeMultiscales readOmeMultiscales(const std::filesystem::path& store) {
    OmeMultiscales result;
    result.store = store;
    std::error_code error;
    result.zarrFormat = std::filesystem::is_regular_file(store / "zarr.json", error) ? 3 : 2;
    result.attributesFile = store / (result.zarrFormat == 3 ? "zarr.json" : ".zattrs");
    if (!std::filesystem::is_regular_file(result.attributesFile, error))
        throwInputError(result.attributesFile, "", "is missing: an OME-Zarr store keeps its multiscales there");
    const nlohmann::json json = readZarrJson(result.attributesFile);
    const std::filesystem::path& file = result.attributesFile;
    try {
        const nlohmann::json& attributes = result.zarrFormat == 3 ? JsonField(file, json, "").member("attributes").value() : json;
        const nlohmann::json& ome = omeAttributes(attributes, file, result.zarrFormat);
        const auto& list = JsonField(file, ome, result.zarrFormat == 3 ? "attributes.ome" : "").member("multiscales").value();
        if (!list.is_array() || list.empty()) throwInputError(file, "multiscales", "must list at least one image");
        const auto& multiscale = list[0];
        if (ome.contains("version")) result.version = JsonField(file, ome["version"], "version").string();
        if (result.version.empty() && multiscale.contains("version"))
            result.version = JsonField(file, multiscale["version"], "multiscales[0].version").string();
        if (multiscale.contains("name") && multiscale["name"].is_string()) result.name = multiscale["name"].get<std::string>();
        result.axes = readAxes(multiscale, file);
        result.levels = readLevels(multiscale, result.axes.size(), file);
        result.channelLabels = readChannelLabels(ome);
    } catch (const nlohmann::json::exception& problem) {
        throwInputError(file, "multiscales", std::string("holds a value of the wrong kind: ") + problem.what());
    }
    return result;
}

}  // namespace tstyles
