// The named built-in styles: the paper's colours (Figures 1, 4, 5 and 6) in each style family.
#include "style_catalog.h"

#include <utility>

#include "style_families.h"

namespace styles {

namespace {

// The paper's palette.
const Rgb kWhite{0.92, 0.92, 0.9};
const Rgb kBlue{0.25, 0.45, 0.95};
const Rgb kLightYellow{1.0, 0.95, 0.6};
const Rgb kOrange{1.0, 0.55, 0.1};
const Rgb kGreen{0.3, 0.8, 0.3};
const Rgb kRed{0.9, 0.2, 0.15};
const Rgb kSteel{0.86, 0.88, 0.92};
const Rgb kInk{0.04, 0.04, 0.05};
const Rgb kGlow{0.55, 0.85, 1.0};

using Family = Rgba (*)(const Rgb&, const glm::dvec3&);

StyleDefinition coloured(std::string name, std::string description, Family family, Rgb color) {
    return {std::move(name), std::move(description),
            [family, color](const glm::dvec3& normal) { return family(color, normal); }};
}

StyleDefinition silhouette(std::string name, std::string description, Rgb ink, double shading) {
    return {std::move(name), std::move(description),
            [ink, shading](const glm::dvec3& normal) { return contour(ink, shading, normal); }};
}

}  // namespace

std::vector<StyleDefinition> builtInStyles() {
    return {
        coloured("matte-white", "Plain diffuse white; takes any tint.", matte, kWhite),
        coloured("glossy-blue", "Blue with a white highlight (Figure 1, first time-step).", glossy, kBlue),
        coloured("glossy-light-yellow", "Light yellow with a white highlight (Figure 1, focused time-step).",
                 glossy, kLightYellow),
        coloured("toon-orange", "Orange cel shading: three hard bands and a highlight spot.", toon, kOrange),
        coloured("metal-grey", "Polished steel: reflected sky, horizon and floor, sharp highlight.", metal,
                 kSteel),
        silhouette("contour-black", "Silhouette only: transparent centre, dark rim (Figure 1, in between).",
                   kInk, 0.0),
        silhouette("contour-blue", "Blue silhouette only (Figure 6, sonar, last time-step).", kBlue, 0.45),
        {"xray-glow", "Faint, nearly transparent centre and a bright glowing rim.",
         [](const glm::dvec3& normal) { return xrayGlow(kGlow, normal); }},
        coloured("matte-green", "Diffuse green (Figure 5, focused time-step).", matte, kGreen),
        coloured("glossy-red", "Red with a white highlight (Figure 6, high change).", glossy, kRed),
        coloured("glossy-orange", "Orange with a white highlight (Figures 1 and 6, orange time-step).",
                 glossy, kOrange),
        coloured("toon-green", "Green cel shading (Figure 4, low change).", toon, kGreen),
    };
}

}  // namespace styles
