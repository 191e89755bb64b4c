// The annotations laid out together: panels first (title, caption, legends), then the scale bar,
// the box's axis titles and its tick labels, each where it overlaps nothing placed before it and
// stays inside the image, or left out (docs/annotations.md, "Layout").
#include "tstyles/annotate/scene_annotations.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "annotation_panels.h"
#include "box_annotations.h"
#include "coastline.h"
#include "layout_space.h"
#include "legend_panels.h"
#include "picture_room.h"
#include "text_box.h"
#include "tstyles/data/time_axis.h"

namespace tstyles {
namespace {

constexpr glm::vec4 kLineText{1.0f, 1.0f, 1.0f, 1.0f};  // a title or caption
constexpr glm::vec4 kCoastInk{0.85f, 0.85f, 0.8f, 0.9f};

std::string captionText(const Scene& scene, glm::ivec2 steps, const std::vector<std::string>& labels) {
    // "temporal-mip · maximum · 40 time-steps": the ray mode where it is not the paper's compositing.
    std::string text = toString(scene.compositor) + " \u00b7 ";
    if (scene.rayMode != kCompositeRay) text += toString(scene.rayMode) + " \u00b7 ";
    const int count = steps.y - steps.x + 1;
    text += count == 1 ? "time-step " + std::to_string(steps.x) : std::to_string(count) + " time-steps";
    if (labels[std::size_t(steps.x)].rfind("time-step ", 0) != 0)
        text += ", " + labels[std::size_t(steps.x)] + (count > 1 ? " to " + labels[std::size_t(steps.y)] : "");
    return text;
}

// One line of text on a panel, `scale` times the annotations' text size, shortened to `maxWidth`.
PanelDraft textPanel(AnnotationKind kind, const PanelMetrics& m, const std::string& fullText, double scale,
                     double maxWidth) {
    const int pixels = int(std::lround(scale * m.pixels));
    const std::string text = shortenToWidth(*m.font, fullText, pixels, maxWidth - 2 * m.pad);
    const double lineHeight = scale * m.row;
    PanelDraft draft{kind, text, 2 * m.pad + m.font->width(text, pixels), 2 * m.pad + lineHeight, {}, {}};
    const double baseline = std::round(0.5 * (lineHeight + m.font->ascent(pixels) - m.font->descent(pixels)));
    draft.draw = [text, pixels, baseline, m](Canvas& canvas, const Rect& panel) {
        fillPanel(canvas, panel);
        canvas.drawText(*m.font, text, {panel.x + m.pad, panel.y + m.pad + baseline}, pixels, kLineText);
    };
    return draft;
}

// The widest a title or caption may be: the image's width, less the room of the panels that share
// its edge (the legend, the scale bar) where that leaves it at least 40 % of the image; else the
// other panels move inward past it.
double widestLine(const LayoutSpace& space, double besideWidth) {
    const double whole = space.imageSize().x - 2 * space.margin();
    const double beside = whole - space.margin() - besideWidth;
    return besideWidth > 0.0 && beside >= 0.4 * space.imageSize().x ? beside : whole;
}

void placePanel(LayoutSpace& space, Corner corner, const PanelDraft& draft, AnnotationPlan& plan) {
    if (draft.text.empty() || !draft.draw) return;
    const auto panel = space.placeInCorner(corner, draft.width, draft.height);
    if (!panel) return;
    addElement(plan, draft.kind, *panel, draft.text,
               [draw = draft.draw, rect = *panel](Canvas& canvas) { draw(canvas, rect); });
    plan.layout.panels.push_back(*panel);
    if (draft.record) draft.record(*panel, plan.layout);
}

double widestOf(const std::vector<PanelDraft>& drafts) {
    double widest = 0.0;
    for (const PanelDraft& draft : drafts) widest = std::max(widest, draft.width);
    return widest;
}

// The scale bar's width before it is placed, for the caption's room: its bar is at most a quarter
// of the image (scaleBarCorner), and its label may stand out a little.
double scaleBarRoom(const Scene& scene, glm::ivec2 size) { return scene.annotations.scaleBar ? 0.3 * size.x : 0.0; }

}  // namespace

std::string toString(AnnotationKind kind) {
    switch (kind) {
        case AnnotationKind::Title: return "title";
        case AnnotationKind::Caption: return "caption";
        case AnnotationKind::Legend: return "legend";
        case AnnotationKind::ScaleBar: return "scale bar";
        case AnnotationKind::ScaleBarLabel: return "scale bar label";
        case AnnotationKind::AxisTitle: return "axis title";
        case AnnotationKind::TickLabel: return "tick label";
    }
    return "annotation";
}

int annotationPixelSize(const Scene& scene, int imageHeight) {
    return std::max(6, int(std::lround(scene.annotations.fontSize * imageHeight / 512.0)));
}

std::vector<std::string> timeStepLabels(const Series& series) {
    std::vector<double> times;
    for (const TimeStep& step : series.steps) times.push_back(step.time);
    std::vector<std::string> labels = formatTimes(times, series.time);
    if (series.time.unit != TimeUnit::None) return labels;
    // Plain numbers: the index, with the stamp where it says more than the index does.
    bool stampsAreIndices = true;
    for (std::size_t step = 0; step < times.size(); ++step)
        stampsAreIndices = stampsAreIndices && times[step] == double(step);
    for (std::size_t step = 0; step < labels.size(); ++step)
        labels[step] = "time-step " + std::to_string(step) + (stampsAreIndices ? "" : " (" + labels[step] + ")");
    return labels;
}

namespace {

// The least share of its size the picture keeps beside the panels; below it, legends give way.
constexpr double kSmallestPictureShare = 0.5;

// Title, caption and the first `legendCount` legends, each in its corner.
void placePanels(LayoutSpace& space, const PanelMetrics& m, const Scene& scene, glm::ivec2 imageSize,
                 const std::vector<std::string>& labels, glm::ivec2 steps, const std::vector<PanelDraft>& legends,
                 std::size_t legendCount, AnnotationPlan& plan) {
    const Annotations& wanted = scene.annotations;
    const Corner legendCorner = wanted.legendCorner;
    const std::vector<PanelDraft> placed(legends.begin(), legends.begin() + std::ptrdiff_t(legendCount));
    if (!wanted.title.empty()) {
        const double beside = legendCorner == Corner::TopRight ? widestOf(placed) : 0.0;
        placePanel(space, Corner::TopLeft,
                   textPanel(AnnotationKind::Title, m, wanted.title, 1.35, widestLine(space, beside)), plan);
    }
    if (wanted.caption) {
        const double beside =
            std::max(legendCorner == Corner::BottomRight ? widestOf(placed) : 0.0, scaleBarRoom(scene, imageSize));
        placePanel(
            space, Corner::BottomLeft,
            textPanel(AnnotationKind::Caption, m, captionText(scene, steps, labels), 1.0, widestLine(space, beside)),
            plan);
    }
    for (const PanelDraft& legend : placed) placePanel(space, legendCorner, legend, plan);
}

}  // namespace

AnnotationPlan planAnnotations(glm::ivec2 imageSize, const Scene& scene, const Series& series,
                               const DisplayFrame& frame, const View& view, const Font& font,
                               const StyleImages& styles, const std::optional<Bounds>& keepClear) {
    AnnotationPlan plan;
    plan.view = view;
    if (!scene.annotations.any() || series.size() == 0 || imageSize.x <= 0 || imageSize.y <= 0) return plan;
    const PanelMetrics m = panelMetrics(font, annotationPixelSize(scene, imageSize.y));
    const glm::ivec2 steps = scene.exposure.stepsOf(series.size());
    const std::vector<std::string> labels = timeStepLabels(series);
    const Annotations& wanted = scene.annotations;
    const std::vector<PanelDraft> legends =
        wanted.legend ? legendDrafts({scene, series, steps, labels, styles, m, imageSize, 0.5 * imageSize.x})
                      : std::vector<PanelDraft>{};
    const std::optional<Rect> footprint = keepClear ? footprintOnImage(view, imageSize, *keepClear) : std::nullopt;
    // Panels first, in the order they give way: title, caption, legends; the picture moved into the
    // room they and the scale bar's corner leave; then the scale bar, the axis titles and the tick
    // labels in what is left.
    for (std::size_t legendCount = legends.size();; --legendCount) {
        plan = AnnotationPlan{};
        plan.view = view;
        LayoutSpace space(imageSize, m.pad);
        placePanels(space, m, scene, imageSize, labels, steps, legends, legendCount, plan);
        if (footprint) {
            std::vector<Rect> obstacles = plan.layout.panels;
            if (wanted.scaleBar)
                if (const auto corner = scaleBarCorner(space, m)) obstacles.push_back(*corner);
            const PictureMove move = moveClearOf(*footprint, imageSize, obstacles, m.pad);
            if (shareKept(*footprint, move, imageSize) < kSmallestPictureShare && legendCount > 0) continue;
            if (move.scale > 0.0) plan.view = movedOnImage(view, imageSize, move);
            // The scale bar, axis titles and tick labels keep clear of the data too.
            if (const auto outline = outlineOnImage(plan.view, imageSize, *keepClear)) space.keepClearOf(*outline);
        }
        if (wanted.scaleBar) placeScaleBar(space, m, series, frame, plan.view, plan);
        if (wanted.box) placeBox(space, m, scene, series, frame, plan.view, plan);
        if (wanted.coast) {
            // Under the box and every element: the coast lies on the picture itself.
            auto segments = std::make_shared<const std::vector<WorldSegment>>(coastSegments(series));
            plan.drawUnderlay = [segments, box = std::move(plan.drawUnderlay), onPicture = plan.view](Canvas& canvas) {
                drawCoast(canvas, *segments, onPicture, kCoastInk);
                if (box) box(canvas);
            };
        }
        return plan;
    }
}

AnnotationLayout drawAnnotations(Image& image, const Scene& scene, const Series& series, const DisplayFrame& frame,
                                 const View& view, const Font& font, const StyleImages& styles,
                                 const std::optional<Bounds>& keepClear) {
    AnnotationPlan plan =
        planAnnotations({image.width, image.height}, scene, series, frame, view, font, styles, keepClear);
    Canvas canvas(image);
    // The box and its ticks lie under the panels and labels.
    if (plan.drawUnderlay) plan.drawUnderlay(canvas);
    for (const auto& draw : plan.drawElements) draw(canvas);
    return std::move(plan.layout);
}

View pictureView(glm::ivec2 imageSize, const Scene& scene, const Series& series, const DisplayFrame& frame,
                 const View& view, const Font& font, const StyleImages& styles, const Bounds& keepClear) {
    return planAnnotations(imageSize, scene, series, frame, view, font, styles, keepClear).view;
}

}  // namespace tstyles
