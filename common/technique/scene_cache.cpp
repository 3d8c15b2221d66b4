#include "technique/scene_cache.hpp"

#include <stdexcept>

#include "core/scene_gen.hpp"

namespace shadowlab::tech {
std::vector<std::string> SceneCache::choices() {
  std::vector<std::string> names = sceneNames();
  names.push_back("model");
  return names;
}

void SceneCache::declare(ParamRegistry& r, SceneChoice* c, const std::string& whyScene,
                         const std::string& whyTriangles) {
  r.addChoice("scene", &c->scene, choices(), whyScene + "; model: the file given with --model");
  r.add("triangles", &c->triangles, 10000, 1000000, whyTriangles);
  r.add("scene.plain", &c->plain,
        "plain surfaces: no brick or checker texture, each its mean colour; the shadows alone (projector)");
}

bool SceneCache::update(const SceneChoice& c) {
  const std::vector<std::string> names = choices();
  const std::string& name = names.at(std::size_t(c.scene));
  const bool model = name == "model";
  const std::uint64_t generation = model ? currentModelGeneration() : 0;
  const std::uint64_t revision =
      ((generation * 16u + std::uint64_t(c.scene)) * 10000000u + std::uint64_t(c.triangles)) * 2u +
      (c.plain ? 1u : 0u) + 1u;
  if (revision == revision_) return false;
  if (model && !currentModel())
    throw std::runtime_error("scene=model: no model loaded; start with --model FILE (OBJ + MTL, glTF 2.0)");
  scene_ = model ? placeOnGround(*currentModel()) : makeScene(name, 1, std::size_t(c.triangles));
  if (c.plain) makePlain(scene_);
  gpu_ = gl::uploadScene(scene_, label_);
  boxes_.clear();
  casts_.clear();
  for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
    boxes_.push_back(scene_.objectBounds(i));
    casts_.push_back(scene_.objects[i].castsShadow);
  }
  bounds_ = scene_.bounds();
  revision_ = revision;
  return true;
}

}  // namespace shadowlab::tech
