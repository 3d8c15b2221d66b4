#pragma once
// Drawing a scene's objects with a course scene shader: per object it sets the uniforms every
// scene shader in the course names the same way (uModel, uNormalMatrix, uAlbedo, uSpecular,
// uShininess, uTwoSided, uUseTexture, uAlphaCutoff; unused ones cost nothing), binds the material
// texture, culls back faces except on two-sided materials, and draws. Lessons keep the passes;
// this keeps the bookkeeping in one place.
#include <functional>
#include <optional>
#include <span>
#include <string>

#include "core/light.hpp"
#include "core/scene.hpp"
#include "gl/mesh_gpu.hpp"
#include "gl/program.hpp"

namespace shadowlab::gl {

struct SceneDrawOptions {
  bool textures = true;              // bind material textures (uUseTexture says whether there is one)
  std::optional<float> specular;     // override every material's k_s (a lesson's slider)
  std::optional<float> shininess;    // override every material's exponent
  GLenum textureUnit = GL_TEXTURE0;  // where the material texture goes (uTexture's unit)
  // Draw only objects for which this returns true (caster culling, receivers only...); empty: all.
  std::function<bool(std::size_t object)> filter;
  // Called after the object's VAO is bound and its uniforms set, right before it is drawn.
  std::function<void(std::size_t object)> beforeDraw;
  // The eye (w = 1) or the direction toward it (w = 0): meshes with view orders (gl::GpuMesh) draw
  // their triangles nearest it first. Empty: every mesh in its own order.
  std::optional<glm::vec4> viewer;
};

// Sets a `Light` uniform struct of shaders/common/lighting.glsl (`name` is e.g. "uLight" or
// "uLights[2]"): kind, enabled, position, direction, colour times intensity, attenuation, cone.
void setLight(const Program& program, const std::string& name, const Light& light);

// Every light of the lesson, in its order: uLights[i] (shaders/common/light.glsl) and uLightCount.
// Lights beyond MAX_LIGHTS (4) are an error: throws std::invalid_argument.
void setLights(const Program& program, std::span<const Light> lights);

// Returns the number of triangles drawn.
std::size_t drawScene(const Program& program, const Scene& scene, const GpuScene& gpu,
                      const SceneDrawOptions& options = {});

}  // namespace shadowlab::gl
