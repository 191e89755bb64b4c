// The two editor panels along the bottom: the STF over density (with the log histogram) and the
// TSTF, shown as the index TSTF (one section per time-step) or the gradient TSTF on [0, 1]. Keeps
// track of which editor has the keyboard, so group, delete and nudge act where the user last clicked.
#pragma once

#include "curve_editor.h"
#include "tstyles/data/series.h"
#include "tstyles/scene/scene.h"
#include "ui_anchors.h"
#include "viewer_layout.h"

namespace tstyles::viewer {

class EditorPanels {
public:
    EditorPanels() : stf_("stf"), index_("tstf"), gradient_("gradient") {}
    // Holds a pointer to one of its own editors.
    EditorPanels(const EditorPanels&) = delete;
    EditorPanels& operator=(const EditorPanels&) = delete;

    void draw(Scene& scene, const Series& series, const std::vector<std::string>& timeLabels,
              const DensityHistogram& histogram, const ViewerLayout& layout,
              UiAnchors& anchors);

    // The editor that has the keyboard, with the curve it edits in `scene` and that curve's axis.
    CurveEditor& focused() { return *focused_; }
    TransferFunction1D& focusedCurve(Scene& scene) const;
    CurveAxis focusedAxis(const Series& series) const;

    void clearSelections();
    bool dragging() const { return stf_.dragging() || index_.dragging() || gradient_.dragging(); }

private:
    enum class TstfView { Index, Gradient };

    void drawStf(Scene& scene, const DensityHistogram& histogram, const ScreenRect& rect, UiAnchors& anchors);
    void drawTstf(Scene& scene, const Series& series, const std::vector<std::string>& timeLabels, const ScreenRect& rect,
                  UiAnchors& anchors);
    // Toolbar, canvas and inspector of one editor inside the current window.
    void drawEditor(CurveEditor& editor, TransferFunction1D& curve, const CurveEditorConfig& config,
                    UiAnchors& anchors);

    CurveEditor stf_;
    CurveEditor index_;
    CurveEditor gradient_;
    CurveEditor* focused_ = &index_;
    TstfView tstfView_ = TstfView::Index;
    bool followCompositor_ = true;  // show the TSTF the compositor reads until the user picks a tab
};

CurveAxis stfAxis();
CurveAxis indexTstfAxis(const Series& series);
CurveAxis gradientTstfAxis();

}  // namespace tstyles::viewer
