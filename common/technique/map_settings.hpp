#pragma once
// What every 2D-map technique shares (the uniform maps of lesson 03, the hybrid maps of lesson 07):
// the depth pass's polygon offset and culled faces, the lookup's bias family
// (shaders/common/shadow_bias.glsl), the directional light's fit and caster culling, and the spot's
// depth range. Registered with the same names and reasons under each holder's prefix, so a preset
// reads `bias.constant = 0` whichever technique it sets.
#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/light_cameras.hpp"
#include "core/params.hpp"
#include "gl/program.hpp"
#include "gl/shadow_map.hpp"

namespace shadowlab::tech {

enum class Fit { Scene, View };

struct MapSettings {
  float constantBias = 0.0005f;             // depth units subtracted before the comparison
  float slopeBias = 0.0005f;                // times tan(theta): steep receivers need more
  float maxBias = 0.003f;                   // clamp: tan(theta) grows without bound
  float offsetFactor = 1.0f;                // glPolygonOffset factor (depth pass)
  float offsetUnits = 1.0f;                 // glPolygonOffset units (depth pass)
  float normalOffset = 0.5f;                // lookup point moved this many texels along N
  bool cullFront = false;                   // depth pass draws back faces
  Fit fit = Fit::View;                      // directional frustum around the scene or the view
  bool snap = true;                         // texel snapping of the fitted frustum
  bool cullCasters = true;                  // skip casters that cannot shade the view
  float spotNear = 0.5f, spotFar = 150.0f;  // the spot frustum's depth range
};

// The shadow-map sizes a lesson offers, in texels per side: one table for every technique and lesson.
inline const std::vector<int> kMapSizes{256, 512, 1024, 2048, 4096, 8192};
// Registers a map size (texels per side, one of kMapSizes) under `name`.
Param& declareMapSize(ParamRegistry& r, const std::string& name, int* texels, const std::string& why);
// MAX_LIGHTS in shaders/common/light.glsl
// Light i's colour in the god view (its frustum, its cross).
glm::vec4 lightColour(std::size_t i);
// Bytes a texel of a depth map takes: 2 for 16 bits, 4 for 24 (padded) and 32F.
std::uint64_t depthBytes(gl::DepthFormat format);

// bias.constant, bias.slope, bias.max, offset.factor, offset.units, bias.normal_offset.
void declareBias(ParamRegistry& r, const std::string& prefix, MapSettings& s);
// cull_front, fit, snap, cull_casters.
void declareFitting(ParamRegistry& r, const std::string& prefix, MapSettings& s);
// spot.near, spot.far.
void declareSpotRange(ParamRegistry& r, const std::string& prefix, MapSettings& s);
// The uniforms of shaders/common/shadow_bias.glsl on the bound program.
void setBiasUniforms(const gl::Program& program, const MapSettings& s);
// The directional fit a map of `size` texels gets from these settings (and a student's steps).
shadow::DirectionalFitOptions directionalFit(const MapSettings& s, int size, const shadow::CasterTest& casterTest,
                                             const shadow::OrthoFitter& fitter);

}  // namespace shadowlab::tech
