// The "annotations" section of a scene file, in and out, and the names of the image's corners.
#include <array>
#include <utility>

#include "name_table.h"
#include "scene_sections.h"
#include "tstyles/scene/scene_keys.h"

namespace tstyles {
namespace {

constexpr std::array cornerNameTable{
    std::pair{Corner::TopLeft, "top-left"},
    std::pair{Corner::TopRight, "top-right"},
    std::pair{Corner::BottomLeft, "bottom-left"},
    std::pair{Corner::BottomRight, "bottom-right"},
};

}  // namespace

std::string toString(Corner corner) { return nameOf(cornerNameTable, corner); }
std::optional<Corner> cornerFromString(const std::string& name) { return valueOf(cornerNameTable, name); }
std::vector<std::string> cornerNames() { return allNames(cornerNameTable); }

Annotations readAnnotations(const JsonField& section) {
    section.allowOnlyKeys({"legend", "title", "caption", "box", "scale_bar", "coast", "font_size"});
    Annotations annotations;
    if (const auto legend = section.optionalMember("legend")) {
        if (legend->isObject()) {
            legend->allowOnlyKeys({"corner"});
            annotations.legend = true;
            if (const auto corner = legend->optionalMember("corner"))
                annotations.legendCorner = corner->name<Corner>(cornerFromString, cornerNames());
        } else if (!legend->isBoolean()) {
            legend->fail("expected true, false or {\"corner\": \"top-right\"}");
        } else {
            annotations.legend = legend->boolean();
        }
    }
    if (const auto title = section.optionalMember("title")) annotations.title = title->string();
    if (const auto caption = section.optionalMember("caption")) annotations.caption = caption->boolean();
    if (const auto box = section.optionalMember("box")) annotations.box = box->boolean();
    if (const auto scaleBar = section.optionalMember("scale_bar")) annotations.scaleBar = scaleBar->boolean();
    if (const auto coast = section.optionalMember("coast")) annotations.coast = coast->boolean();
    if (const auto fontSize = section.optionalMember("font_size")) annotations.fontSize = readKeyNumber(*fontSize);
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
