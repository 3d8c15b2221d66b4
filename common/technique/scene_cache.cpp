#include "technique/scene_cache.hpp"

#include "core/scene_gen.hpp"

namespace shadowlab::tech {

bool SceneCache::update(int sceneIndex, int triangles) {
  const std::uint64_t revision = std::uint64_t(sceneIndex) * 10000000u + std::uint64_t(triangles) + 1u;
  if (revision == revision_) return false;
  scene_ = makeScene(sceneNames().at(std::size_t(sceneIndex)), 1, std::size_t(triangles));
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
