// The "annotations" section of a scene file, in and out, and the names of the image's corners.
#include <array>
#include <utility>

#include "name_table.h"
#include "scene_sections.h"

namespace tstyles {
namespace {

using nlohmann::json;

constexpr std::array cornerNameTable{
    std::pair{Corner::TopLeft, "top-left"},
    std::pair{Corner::TopRight, "top-right"},
    std::pair{Corner::BottomLeft, "bottom-left"},
    std::pair{Corner::BottomRight, "bottom-right"},
};

bool readSwitch(const JsonFieldReader& fields, const json& value, const std::string& path) {
    if (!value.is_boolean()) fields.fail(path, "expected true or false");
    return value.get<bool>();
}

}  // namespace

std::string toString(Corner corner) { return nameOf(cornerNameTable, corner); }
std::optional<Corner> cornerFromString(const std::string& name) { return valueOf(cornerNameTable, name); }
std::vector<std::string> cornerNames() { return allNames(cornerNameTable); }

Annotations readAnnotations(const JsonFieldReader& fields, const json& value) {
    const std::string path = "annotations";
    fields.expectObject(value, path, {"legend", "title", "caption", "box", "scale_bar", "coast", "font_size"});
    Annotations annotations;
    if (const json* legend = JsonFieldReader::member(value, "legend")) {
        const std::string legendPath = childPath(path, "legend");
        if (legend->is_object()) {
            fields.expectObject(*legend, legendPath, {"corner"});
            annotations.legend = true;
            if (const json* corner = JsonFieldReader::member(*legend, "corner"))
                annotations.legendCorner =
                    fields.name<Corner>(*corner, childPath(legendPath, "corner"), cornerFromString, cornerNames());
        } else if (!legend->is_boolean()) {
            fields.fail(legendPath, "expected true, false or {\"corner\": \"top-right\"}");
        } else {
            annotations.legend = legend->get<bool>();
        }
    }
    if (const json* title = JsonFieldReader::member(value, "title"))
        annotations.title = fields.string(*title, childPath(path, "title"));
    if (const json* caption = JsonFieldReader::member(value, "caption"))
        annotations.caption = readSwitch(fields, *caption, childPath(path, "caption"));
    if (const json* box = JsonFieldReader::member(value, "box"))
        annotations.box = readSwitch(fields, *box, childPath(path, "box"));
    if (const json* scaleBar = JsonFieldReader::member(value, "scale_bar"))
        annotations.scaleBar = readSwitch(fields, *scaleBar, childPath(path, "scale_bar"));
    if (const json* coast = JsonFieldReader::member(value, "coast"))
        annotations.coast = readSwitch(fields, *coast, childPath(path, "coast"));
    if (const json* fontSize = JsonFieldReader::member(value, "font_size"))
        annotations.fontSize = fields.numberIn(*fontSize, childPath(path, "font_size"), {4.0, 200.0});
    return annotations;
}

nlohmann::ordered_json annotationsJson(const Annotations& annotations) {
    nlohmann::ordered_json result;
    result["legend"] = annotations.legend ? nlohmann::ordered_json{{"corner", toString(annotations.legendCorner)}}
                                          : nlohmann::ordered_json(false);
    result["title"] = annotations.title;
    result["caption"] = annotations.caption;
    result["box"] = annotations.box;
    result["scale_bar"] = annotations.scaleBar;
    if (annotations.coast) result["coast"] = true;  // written where it is on: scenes before it stay as they were
    result["font_size"] = annotations.fontSize;
    return result;
}

}  // namespace tstyles
