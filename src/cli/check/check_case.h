// One `tstyles check` worker: a headless GL context with its own renderer and datasets, which
// renders cases and compares them with their goldens. Every object here belongs to the thread
// that made it (the context is current there), so workers on several threads share nothing but
// the lock around dataset reading.
#pragma once

#include <memory>
#include <optional>

#include "check_datasets.h"
#include "check_report.h"
#include "check_suite.h"
#include "tstyles/gl/headless_context.h"
#include "tstyles/gl/program.h"
#include "tstyles/render/renderer.h"
#include "tstyles/scene/automatic_scene.h"

namespace tstyles::cli {

class CaseWorker {
public:
    // Makes a context of `backend` current on the calling thread. The cases' datasets come from
    // `datasets`, shared by the workers.
    CaseWorker(GlBackend backend, const ShaderLibrary& shaders, CheckDatasets& datasets);

    const HeadlessContext& context() const { return *context_; }

    // Renders the case and compares it with its golden as that file is now. With `update` the
    // result is Updated and keeps the render in `actual`: the caller writes the golden, so that
    // cases sharing one are written in suite order whatever thread rendered them.
    CaseResult check(const CheckCase& entry, Scene scene, bool update);

private:
    // The scene fitted to its dataset, read once per dataset and uploaded unless it is the series
    // already on the GPU.
    const SceneOnSeries& fit(const Scene& scene);

    std::unique_ptr<HeadlessContext> context_;
    std::string glRenderer_;  // GL_RENDERER and version: which of a case's thresholds apply
    Renderer renderer_;
    CheckDatasets& datasets_;
    std::optional<SceneOnSeries> fitted_;
    std::filesystem::path uploaded_;
};

}  // namespace tstyles::cli
