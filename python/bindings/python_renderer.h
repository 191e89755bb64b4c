// A renderer that Python keeps between calls: one headless context per process (shared by every
// Renderer object), the series uploaded once and kept on the GPU while the same series is rendered
// with the same display frame, so a loop over cameras or transfer functions uploads nothing.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>

#include "bindings.h"
#include "tstyles/gl/headless_context.h"
#include "tstyles/image/image.h"
#include "tstyles/render/annotated_rendering.h"
#include "tstyles/render/renderer.h"
#include "tstyles/scene/temporal_change.h"

namespace tstyles::python {

class PythonRenderer {
public:
    // Makes the process' context (EGL, then OSMesa for Auto), or joins it; a context of another
    // backend than asked for is an InputError, since one process holds one.
    explicit PythonRenderer(GlBackend backend);
    ~PythonRenderer();
    PythonRenderer(const PythonRenderer&) = delete;
    PythonRenderer& operator=(const PythonRenderer&) = delete;

    // The scene on the series as `tstyles render` draws it: the display frame, the automatic parts,
    // the annotations. Uploads only when the series or the display frame its settings resolve to changed.
    Image render(const SharedSeries& series, const Scene& scene);
    // How many times this renderer uploaded a series.
    std::size_t uploads() const { return uploads_; }
    // Rays of the last image cut short by the driver's loop limit (Renderer::lastCutShortRays).
    std::uint32_t lastCutShortRays() const;
    std::string description() const;
    // Gives back the GPU memory and the series now; the object is unusable afterwards.
    void close();

private:
    // The series as shown: in the scene's display frame, with what an automatic camera frames.
    struct Shown {
        SharedSeries series;  // as given
        std::shared_ptr<const Series> displaySeries;  // the same object when the frame is the identity
        DisplayFrame frame;
        Bounds framed;
        Stf gradientRangeStf;  // the automatic gradient range and unchanged threshold below were fitted for this STF
        std::optional<double> gradientRangeHigh;
        UnchangedFit unchangedFit;
        std::unique_ptr<AnnotatedRendering> annotated;
    };
    void show(const SharedSeries& series, const Scene& scene);
    Scene fitted(const Scene& scene);
    Renderer& renderer();

    std::shared_ptr<HeadlessContext> context_;
    std::unique_ptr<Renderer> renderer_;  // after context_: its GL objects go first
    std::optional<Shown> shown_;
    std::size_t uploads_ = 0;
};

// Uploads by every renderer of the process since the module was loaded.
std::size_t totalUploads();

}  // namespace tstyles::python
