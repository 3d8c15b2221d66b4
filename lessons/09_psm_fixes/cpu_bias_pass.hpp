#pragma once
// Fix 4 of [Kozlov2004] (§5) written out on the CPU, for impl=student: every caster vertex of a map
// moved by texelSizeBias (exercise 09.4), P + L (a + b L_texel) away from the light, L_texel the
// world size of one of the map's texels at P; the moved world positions uploaded beside the mesh's
// own uvs and indices, and drawn into the map with the plain depth shader. The reference does the
// same per vertex on the GPU (shaders/08_psm/depth_psm.vert, bias=world); lesson 08's map set
// (08_psm/projective_maps) calls this pass instead when a student's bias is set.
#include <functional>
#include <vector>

#include "08_psm/projective_maps.hpp"
#include "gl/objects.hpp"
#include "technique/casters.hpp"

namespace shadowlab::tech {

class CpuBiasPass {
 public:
  // A student's P_biased(worldToClip, P, L, a, b, mapSize): exercise 09.4's signature.
  using Bias =
      std::function<glm::dvec3(const glm::dmat4&, const glm::dvec3&, const glm::dvec3&, double, double, double)>;
  void init() { casters_.build(); }
  // The map set's hook (PerspectiveShadowMaps::Student::worldBias) drawing through this pass.
  ProjectiveMapSet::WorldBias with(Bias bias);

 private:
  std::size_t draw(const Bias& bias, const ProjectiveMapSet::BiasedDraw& d);
  // The reference's depth pass with its own bias off (uWorldBias false): its depth clamp as well.
  CasterPass casters_{"lesson 09: depth pass (CPU-biased vertices)", "08_psm/depth_psm.vert", "uLightViewProj",
                      "08_psm/depth_psm.frag"};
  gl::Buffer vertices_;
  std::vector<glm::vec3> moved_;       // every kept caster's vertices, biased, in world space
  std::vector<gl::VertexArray> vaos_;  // per scene object: its moved positions, its mesh's uvs
};

}  // namespace shadowlab::tech
