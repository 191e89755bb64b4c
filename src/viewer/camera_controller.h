// Mouse-driven camera moves on a scene's Camera: orbit, pan, zoom, fit and reset. GL-free; the
// volume view turns pixel motion into these calls. What is left unset in the camera (target,
// distance) stays unset until a move needs it written out, so a saved scene stays as small as the
// one that was opened, and still renders to the same image.
#pragma once

#include <glm/glm.hpp>

#include "tstyles/scene/camera.h"

namespace tstyles::viewer {

// Degrees of turn per pixel dragged: a drag across a 600-pixel view turns the data by 180 degrees.
inline constexpr double kOrbitDegreesPerPixel = 0.3;
// Distance factor per wheel notch (wheel up moves closer).
inline constexpr double kZoomFactorPerNotch = 0.88;

// The camera as an orbit camera. A look-at camera becomes the orbit with the same eye and target;
// its up vector is dropped (orbit cameras keep world y up).
OrbitCamera asOrbit(const Camera& camera);

// Turns the camera around its target; dragging right turns the data to the right, dragging down
// looks from higher up. Elevation stops short of the poles, where azimuth would lose meaning.
void orbitCamera(Camera& camera, glm::dvec2 pixelDelta);

// Moves the target in the view plane so that the data follows the mouse.
void panCamera(Camera& camera, glm::dvec2 pixelDelta, const Bounds& bounds, glm::ivec2 viewport);

// Moves toward (positive notches) or away from the target.
void zoomCamera(Camera& camera, double notches, const Bounds& bounds, glm::ivec2 viewport);

// The same direction of view, target and distance left to frame the whole series.
Camera fitCameraToData(const Camera& camera);

// An orbit camera without target or distance made explicit: aimed at the centre of `framed` and
// backed off until `framed` fits the viewport, as the renderer frames an automatic orbit (the
// viewer frames the visible data this way on opening and on F; docs/automatic-scene.md). Other
// cameras come back unchanged.
Camera frameExplicitly(const Camera& camera, const Bounds& framed, glm::ivec2 viewport);

}  // namespace tstyles::viewer
