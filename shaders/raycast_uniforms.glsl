// The uniforms of the raycasting program, declared once for both languages: GLSL declares each as
// `uniform TYPE NAME;` (an array as `uniform TYPE NAME[COUNT];`), and the C++ side
// (tstyles/render/raycast_uniforms.h) makes of each line a typed name that Program::set takes, so
// that a uniform cannot be misspelt or set with the wrong type. Only RAYCAST_UNIFORM and
// RAYCAST_UNIFORM_ARRAY lines with GLSL types (int, float, vec2-4, ivec2-3, mat3, mat4) and
// contract.glsl counts belong here. The entry/exit programs share the ray's two (ray.glsl).
#ifndef RAYCAST_UNIFORM
#include "contract.glsl"
#define RAYCAST_UNIFORM(type, name) uniform type name;
#define RAYCAST_UNIFORM_ARRAY(type, name, count) uniform type name[count];
#endif

// The viewing ray of a pixel (ray.glsl).
RAYCAST_UNIFORM(mat4, inverseViewProjection)
RAYCAST_UNIFORM(vec2, viewportSize)

// The time-steps (overlap_extraction.glsl): how many, and those that take part, first and last
// inclusive (the scene's exposure, or one time-step alone in plain playback).
RAYCAST_UNIFORM(int, timeStepCount)
RAYCAST_UNIFORM(ivec2, exposedSteps)

// The density atlas' texel size (volume_sampling.glsl) and the transfer tables' entries
// (transfer_functions.glsl).
RAYCAST_UNIFORM(vec3, inverseAtlasSize)
RAYCAST_UNIFORM(float, transferTableSize)

// The ray's march (raycast.frag).
RAYCAST_UNIFORM(float, stepLength)       // world units between samples
RAYCAST_UNIFORM(float, referenceLength)  // the length over which a transfer-function opacity applies
RAYCAST_UNIFORM(float, terminationOpacity)
RAYCAST_UNIFORM(vec4, background)        // straight (not premultiplied) colour and opacity
// The part of the world this pass renders: one process's block in distributed rendering
// (sort-last, docs/scaling.md), else a box around everything. A ray's segment belongs to the block
// its middle lies in, so the blocks take exactly the samples of one whole render between them.
RAYCAST_UNIFORM(vec3, clipLower)
RAYCAST_UNIFORM(vec3, clipUpper)
// The world box of the whole series. Segment ends sit on a lattice of stepLength along each ray,
// anchored where the ray enters this box: after a jump over empty space the ray is back on the
// lattice from the next lattice point on, and a process's block (whose part of the ray starts
// elsewhere) takes the same samples as one whole render.
RAYCAST_UNIFORM(vec3, seriesLower)
RAYCAST_UNIFORM(vec3, seriesUpper)

// What the pixel shows (final_processing.glsl): a FINAL_* code of contract.glsl.
RAYCAST_UNIFORM(int, finalMode)
// The density change that the gradient TSTF's ends stand for (characteristic_style.glsl).
RAYCAST_UNIFORM(vec2, changeRange)
// The densities the STF shows at all (time_step_visit.glsl): outside, a time-step is transparent.
RAYCAST_UNIFORM(vec2, stfVisibleRange)

// A compositor's options are uniforms its module declares (the table of compositors names them).

// Unchanged places (UNCHANGED_TIME, CompositorOptions::unchanged; temporal_sample.glsl): where the
// densities at a sample change over the time-steps by no more than `unchangedBelow` (density
// units), or the time-step a compositor picks is ahead of the runner-up by no more than
// `unchangedTie` (a tie: the time is noise's choice), no time colour shows: the STF alone, with
// unchangedOpacity of its opacity. Both per band of the picked time-step's density.
RAYCAST_UNIFORM_ARRAY(float, unchangedBelow, UNCHANGED_DENSITY_BANDS)
RAYCAST_UNIFORM_ARRAY(float, unchangedTie, UNCHANGED_DENSITY_BANDS)
RAYCAST_UNIFORM(float, unchangedOpacity)
// A place whose time shows is as opaque as if this many times as thick (the unchanged option's gain).
RAYCAST_UNIFORM(float, changedGain)
// An unchanged place keeps its whole share where the value gradient is this steep (density per world
// length), down to UNCHANGED_INTERIOR of it where the value is flat; 0: the whole share everywhere.
RAYCAST_UNIFORM(float, unchangedBoundary)

// The packed atlas of fully aligned series (packed_time_steps.glsl).
RAYCAST_UNIFORM(vec3, inversePackedAtlasSize)
RAYCAST_UNIFORM(vec3, inverseSharedValiditySize)
RAYCAST_UNIFORM(int, packedGroupCount)

// Lit-sphere styles (styles.glsl): the offset and count of each track's nodes (count 0: not
// styled), the view rotation, and how far apart, in the style image, neighbouring pixels look (the
// pixel's world footprint over the radius of the smallest curved feature the grid resolves; feeds
// the mipmapped lookup).
RAYCAST_UNIFORM_ARRAY(ivec2, styleTracks, STYLE_TRACK_COUNT)
RAYCAST_UNIFORM(mat3, worldToView)
RAYCAST_UNIFORM(float, styleFootprint)
