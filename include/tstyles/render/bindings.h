// Texture units and buffer binding points; must match shaders/bindings.glsl.
#pragma once

namespace tstyles::binding {

inline constexpr unsigned kAtlasUnit = 0;
inline constexpr unsigned kMaskAtlasUnit = 1;
inline constexpr unsigned kEntryExitUnit = 2;
inline constexpr unsigned kStfUnit = 4;
inline constexpr unsigned kGradientTstfUnit = 5;
inline constexpr unsigned kStyleUnit = 6;
inline constexpr unsigned kOccupancyUnit = 7;
inline constexpr unsigned kInverseMapUnit = 8;
inline constexpr unsigned kPackedAtlasUnit = 9;
inline constexpr unsigned kPackedOccupancyUnit = 10;
inline constexpr unsigned kPackedValidityUnit = 11;

inline constexpr unsigned kTimeStepBuffer = 0;
inline constexpr unsigned kProxyBuffer = 1;
inline constexpr unsigned kIndexTstfBuffer = 2;
inline constexpr unsigned kStatisticsBuffer = 3;
inline constexpr unsigned kStyleNodeBuffer = 4;
inline constexpr unsigned kStructuredGridBuffer = 5;
inline constexpr unsigned kProxyMeshBuffer = 6;
inline constexpr unsigned kUnevenAxisBuffer = 7;
inline constexpr unsigned kAxisNodeBuffer = 8;
inline constexpr unsigned kBeamAngleBuffer = 9;
inline constexpr unsigned kPackedGroupBuffer = 10;

inline constexpr float kNoEntry = 1.0e30f;
inline constexpr float kNoExit = -1.0e30f;

}  // namespace tstyles::binding
