#include "technique/map_settings.hpp"

namespace shadowlab::tech {

glm::vec4 lightColour(std::size_t i) {
  static const glm::vec4 colours[] = {
      {1.0f, 0.9f, 0.3f, 1.0f}, {1.0f, 0.6f, 0.3f, 1.0f}, {0.5f, 0.7f, 1.0f, 1.0f}, {0.5f, 1.0f, 0.5f, 1.0f}};
  return colours[i % 4];
}

Param& declareMapSize(ParamRegistry& r, const std::string& name, int* texels, const std::string& why) {
  return r.addNumberChoice(name, texels, kMapSizes, why);
}

std::uint64_t depthBytes(gl::DepthFormat f) { return f == gl::DepthFormat::Depth16 ? 2 : 4; }

void declareBias(ParamRegistry& r, const std::string& n, MapSettings& s) {
  r.add(n + "bias.constant", &s.constantBias, 0, 0.1f, "constant depth bias in the shader");
  r.add(n + "bias.slope", &s.slopeBias, 0, 0.02f, "slope-scaled bias in the shader: times tan(theta)");
  r.add(n + "bias.max", &s.maxBias, 0, 0.1f, "upper clamp of the in-shader bias");
  r.add(n + "offset.factor", &s.offsetFactor, 0, 10, "glPolygonOffset factor: slope-scaled, in the depth pass");
  r.add(n + "offset.units", &s.offsetUnits, 0, 100, "glPolygonOffset units: constant, in depth-format steps");
  r.add(n + "bias.normal_offset", &s.normalOffset, 0, 4, "look up from a point this many texels along the normal");
}

void declareFitting(ParamRegistry& r, const std::string& n, MapSettings& s) {
  r.add(n + "cull_front", &s.cullFront, "depth pass draws back faces only: closed casters need no bias");
  r.addChoice(n + "fit", &s.fit, {"scene", "view"},
              "sun frustum: around the scene, or fitted to the receivers in view");
  r.add(n + "snap", &s.snap, "texel snapping of the fitted frustum (no shimmer)");
  r.add(n + "cull_casters", &s.cullCasters, "skip casters that cannot shade anything in view");
}

void declareSpotRange(ParamRegistry& r, const std::string& n, MapSettings& s) {
  r.add(n + "spot.near", &s.spotNear, 0.01f, 50, "the spot frustum's near plane: depth precision lives here");
  r.add(n + "spot.far", &s.spotFar, 1, 500, "the spot frustum's far plane");
}

void setBiasUniforms(const gl::Program& p, const MapSettings& s) {
  p.set("uConstantBias", s.constantBias);
  p.set("uSlopeBias", s.slopeBias);
  p.set("uMaxBias", s.maxBias);
  p.set("uNormalOffset", s.normalOffset);
}

shadow::DirectionalFitOptions directionalFit(const MapSettings& s, int size, const shadow::CasterTest& casterTest,
                                             const shadow::OrthoFitter& fitter) {
  return {s.fit == Fit::View, s.snap, s.cullCasters, size, casterTest, fitter};
}

}  // namespace shadowlab::tech
