#include "light_mesh.hpp"

#include <chrono>
#include <sstream>

#include "technique/scene_cache.hpp"

namespace shadowlab::tech {

void LightMesh::declare(ParamRegistry& r, const std::string& n) {
  r.add(n + "nodes", &p_.nodes, 4, 256, "grid nodes along the scene's longest side: memory grows with the cube");
  r.add(n + "samples", &p_.samples, 1, SoftMaps::kMaxSamples, "point lights on the sphere for baking the nodes");
  r.add(n + "offset", &p_.offset, 0, 2, "cells along the normal before the lookup (the nodes inside are dark)");
  maps_.declare(r, n);
  maps_.checkBudget(r, n, &p_.samples);
}

void LightMesh::init() {
  maps_.init();
  fbo_ = gl::makeFramebuffer("light mesh: bake fbo");
  vao_ = gl::makeVertexArray("light mesh: fullscreen");
  dummy_ = gl::makeTexture(GL_TEXTURE_3D, "light mesh: none");
  const unsigned char lit = 255;
  glBindTexture(GL_TEXTURE_3D, dummy_.id());
  glTexImage3D(GL_TEXTURE_3D, 0, GL_R8, 1, 1, 1, 0, GL_RED, GL_UNSIGNED_BYTE, &lit);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_3D, 0);
}

// What the nodes depend on: the scene, every light's position, axis, radius and switch, the grid,
// the samples and the maps. Equal keys: the baked mesh is still right.
std::string LightMesh::key(const ShadowContext& c) const {
  std::ostringstream k;
  k << c.scene.revision() << ' ' << p_.nodes << ' ' << p_.samples << ' ' << maps_.mapSize() << ' '
    << maps_.params().bias << ' ' << maps_.params().normalOffset;
  for (const Light& l : c.lights)
    k << '|' << l.enabled << int(l.kind) << int(l.area) << l.radius << ' ' << l.position.x << ' ' << l.position.y << ' '
      << l.position.z << ' ' << l.direction.x << ' ' << l.direction.y << ' ' << l.direction.z << ' ' << l.spotOuter;
  return k.str();
}

// ==== the bake: sample maps, then one slice of the grid at a time per light ======================
void LightMesh::bake(const ShadowContext& c) {
  const auto start = std::chrono::steady_clock::now();
  bakeStats_ = {};
  maps_.render(c, ManyLights::samplesFor(p_.samples, SampleLayout::Ball), bakeStats_);
  grid_ = soft::makeLightGrid(c.scene.bounds(), p_.nodes);
  gl::Program& bake = bakePrograms_.get({"SOFT_SAMPLES " + std::to_string(maps_.samples().size())});
  auto t = gl::TimerScope(c.timers, "light mesh bake");
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, grid_.nodes.x, grid_.nodes.y);
  bake.use();
  maps_.bind(bake, 0);
  bake.set("uGridOrigin", grid_.origin);
  bake.set("uGridStep", grid_.step);
  glBindVertexArray(vao_.id());
  const auto& lights = maps_.lights();
  for (int i = 0; i < kMaxLights; ++i) {
    on_[std::size_t(i)] = i < int(lights.size()) && lights[std::size_t(i)].on;
    if (!on_[std::size_t(i)]) {
      meshes_[std::size_t(i)].reset();
      continue;
    }
    gl::Texture& mesh = meshes_[std::size_t(i)];
    mesh = gl::makeTexture(GL_TEXTURE_3D, "light mesh: light" + std::to_string(i));
    glBindTexture(GL_TEXTURE_3D, mesh.id());
    glTexImage3D(GL_TEXTURE_3D, 0, GL_R8, grid_.nodes.x, grid_.nodes.y, grid_.nodes.z, 0, GL_RED, GL_UNSIGNED_BYTE,
                 nullptr);
    for (GLenum p : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
      glTexParameteri(GL_TEXTURE_3D, p, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);  // the trilinear average of the nodes
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAX_LEVEL, 0);
    glBindTexture(GL_TEXTURE_3D, 0);
    bake.set("uLight", i);
    for (int z = 0; z < grid_.nodes.z; ++z) {
      glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, mesh.id(), 0, z);
      if (z == 0) gl::requireComplete(GL_FRAMEBUFFER, "light mesh: bake fbo");
      bake.set("uGridSlice", float(z));
      glDrawArrays(GL_TRIANGLES, 0, 3);
    }
  }
  maps_.unbind(0);
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, c.frame.framebuffer);
  glViewport(0, 0, c.frame.width, c.frame.height);
  glEnable(GL_DEPTH_TEST);
  glFinish();  // a software renderer draws when flushed: the build time includes the drawing
  buildMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  ++builds_;
}

void LightMesh::render(const ShadowContext& c) {
  const std::string k = key(c);
  stats_ = {};
  if (k != key_) {
    bake(c);
    key_ = k;
    stats_ = bakeStats_;  // the maps' passes were this frame's
  } else {
    stats_.keep({bakeStats_.triangles, bakeStats_.texels});  // the bake's maps, as drawn
    stats_.extra = {};
  }
  stats_.culls = false;
  countStats();
}

void LightMesh::countStats() {
  int lights = 0;
  for (bool on : on_) lights += on;
  const std::uint64_t nodes = grid_.count();
  stats_.bytes = bakeStats_.bytes + nodes * std::uint64_t(lights);
  char buf[96];
  std::snprintf(buf, sizeof buf, "%dx%dx%d nodes, %.1f cm apart, %llu KiB", grid_.nodes.x, grid_.nodes.y, grid_.nodes.z,
                100.0 * grid_.step.x, (unsigned long long)(nodes * std::uint64_t(lights) / 1024));
  stats_.extra.push_back({"light mesh", buf});
  std::snprintf(buf, sizeof buf, "%.0f ms (%d samples), %d build(s)", buildMs_, int(maps_.samples().size()), builds_);
  stats_.extra.push_back({"light mesh build", buf});
}

// Units: the sample maps' two (soft_maps.glsl: the lights' centres and radii for the horizon),
// then one 3D texture per light.
void LightMesh::bindVisibility(const gl::Program& lit, int firstUnit) const {
  maps_.bind(lit, firstUnit);
  firstUnit += 2;
  lit.set("uMeshOffset", p_.offset);
  for (int i = 0; i < kMaxLights; ++i) {
    const std::string n = "[" + std::to_string(i) + "]";
    const bool on = on_[std::size_t(i)] && meshes_[std::size_t(i)];
    lit.set(("uMeshOn" + n).c_str(), on ? 1 : 0);
    lit.set(("uMesh" + n).c_str(), firstUnit + i);
    if (on) {
      lit.set(("uMeshOrigin" + n).c_str(), grid_.origin);
      lit.set(("uMeshStep" + n).c_str(), grid_.step);
      lit.set(("uMeshNodes" + n).c_str(), glm::vec3(grid_.nodes));
    }
    glActiveTexture(GLenum(GL_TEXTURE0 + firstUnit + i));
    glBindTexture(GL_TEXTURE_3D, on ? meshes_[std::size_t(i)].id() : dummy_.id());
    glBindSampler(GLuint(firstUnit + i), 0);
  }
  glActiveTexture(GL_TEXTURE0);
}

void LightMesh::unbindVisibility(int firstUnit) const {
  maps_.unbind(firstUnit);
  firstUnit += 2;
  for (int i = 0; i < kMaxLights; ++i) {
    glActiveTexture(GLenum(GL_TEXTURE0 + firstUnit + i));
    glBindTexture(GL_TEXTURE_3D, 0);
  }
  glActiveTexture(GL_TEXTURE0);
}

}  // namespace shadowlab::tech
