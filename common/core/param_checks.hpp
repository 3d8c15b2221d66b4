#pragma once
// The checks the framework adds to the shared light rig (declareLight) and camera (declareCamera):
// values that each lie in their range but together leave nothing to render, registered with
// ParamRegistry::addCheck so the UI, --set, presets and tests all refuse them with one line
// naming the parameter. A lesson adds its own the same way, next to its parameters.
#include <string>

#include "core/camera.hpp"
#include "core/light.hpp"
#include "core/params.hpp"

namespace shadowlab {

// Shorter than this, a direction does not survive normalisation in float (1e-45 0 0 becomes NaN).
inline constexpr float kMinDirectionLength = 1e-6f;
// Beyond this far/near ratio a float view volume degenerates: its near face collapses to a point
// (near 1e-4 with far 1e7) and depth cannot tell the planes apart.
inline constexpr float kMaxDepthRatio = 1e6f;

// `prefix` is the parameters' common start ("light0."): PREFIXdirection must have a length (a
// spot's axis, the sun's travel) and PREFIXattenuation must not be 0 0 0 (f_att would divide by
// zero). (spot_inner above spot_outer is defined: the cone's edge turns hard, see spotFactor.)
void addLightChecks(ParamRegistry& params, const std::string& prefix, const Light& light);

// camera.near < camera.far, and camera.far / camera.near at most kMaxDepthRatio.
void addCameraChecks(ParamRegistry& params, const OrbitCamera& camera);

}  // namespace shadowlab
