#include "gl/scene_draw.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/gtc/matrix_inverse.hpp>

namespace shadowlab::gl {

void setLight(const Program& program, const std::string& name, const Light& l) {
  program.set((name + ".kind").c_str(), int(l.kind));
  program.set((name + ".enabled").c_str(), l.enabled);
  program.set((name + ".position").c_str(), l.position);
  program.set((name + ".direction").c_str(), glm::normalize(l.direction));
  program.set((name + ".color").c_str(), l.color * l.intensity);
  program.set((name + ".attenuation").c_str(), l.attenuation);
  program.set((name + ".cosInner").c_str(), std::cos(l.spotInner));
  program.set((name + ".cosOuter").c_str(), std::cos(l.spotOuter));
}

void setLights(const Program& program, std::span<const Light> lights) {
  if (lights.size() > std::size_t(kMaxLights))
    throw std::invalid_argument(std::to_string(lights.size()) + " lights; the shaders take at most 4");
  for (std::size_t i = 0; i < lights.size(); ++i) setLight(program, "uLights[" + std::to_string(i) + "]", lights[i]);
  program.set("uLightCount", int(lights.size()));
}

std::size_t drawScene(const Program& program, const Scene& scene, const GpuScene& gpu, const SceneDrawOptions& o) {
  std::size_t triangles = 0;
  if (!program.valid()) return 0;  // a variant that failed to build: its error is in the header
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    if (o.filter && !o.filter(i)) continue;
    const SceneObject& object = scene.objects[i];
    const Material& m = scene.materials[object.material];
    const GLuint texture = o.textures ? gpu.materialTextures[object.material].id() : 0;
    program.set("uModel", object.model);
    program.set("uNormalMatrix", glm::inverseTranspose(glm::mat3(object.model)));
    program.set("uAlbedo", m.albedo);
    program.set("uSpecular", o.specular.value_or(m.specular));
    program.set("uShininess", o.shininess.value_or(m.shininess));
    program.set("uTwoSided", m.twoSided);
    program.set("uUseTexture", texture != 0);
    program.set("uAlphaCutoff", m.alphaCutoff);
    glActiveTexture(o.textureUnit);
    glBindTexture(GL_TEXTURE_2D, texture);
    m.twoSided ? glDisable(GL_CULL_FACE) : glEnable(GL_CULL_FACE);
    const GpuMesh& mesh = gpu.meshes[object.mesh];
    glBindVertexArray(mesh.vao.id());
    if (o.beforeDraw) o.beforeDraw(i);
    mesh.draw(o.viewer ? mesh.orderFor(object.model, *o.viewer) : -1);
    triangles += std::size_t(mesh.indexCount) / 3;
  }
  glEnable(GL_CULL_FACE);
  return triangles;
}

}  // namespace shadowlab::gl
