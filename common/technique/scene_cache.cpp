#include "technique/scene_cache.hpp"

#include "core/scene_gen.hpp"

namespace shadowlab::tech {

void SceneCache::declare(ParamRegistry& r, SceneChoice* c, const std::string& whyScene,
                         const std::string& whyTriangles) {
  r.addChoice("scene", &c->scene, sceneNames(), whyScene);
  r.add("triangles", &c->triangles, 10000, 1000000, whyTriangles);
}

bool SceneCache::update(const SceneChoice& c) {
  const std::uint64_t revision = std::uint64_t(c.scene) * 10000000u + std::uint64_t(c.triangles) + 1u;
  if (revision == revision_) return false;
  scene_ = makeScene(sceneNames().at(std::size_t(c.scene)), 1, std::size_t(c.triangles));
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
