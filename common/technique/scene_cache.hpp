#pragma once
// The scene a lesson draws, built from a procedural scene choice (core/scene_gen) and uploaded
// once: rebuilt only when the choice or the size changes, never per frame. It also keeps what every
// shadow technique culls against (each object's world box, which objects cast, the bounds) and a
// revision that names the content, so the ground truth rebuilds its BVH only when the scene does.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "algorithms/light_cameras.hpp"
#include "core/model_file.hpp"
#include "core/params.hpp"
#include "core/scene.hpp"
#include "gl/mesh_gpu.hpp"

namespace shadowlab::tech {

// Which procedural scene, and how big: the parameters `scene` and `triangles` every scene lesson has.
// The last choice, "model", is the model file given with --model (or dropped on the window), placed
// on the ground (core/model_file's placeOnGround); `triangles` does not change it.
struct SceneChoice {
  int scene = 0;           // index into SceneCache::choices()
  int triangles = 100000;  // target size (10k to 1M)
  bool plain = false;      // opaque surfaces without their textures (makePlain): the shadows stand out
};

class SceneCache {
 public:
  explicit SceneCache(std::string label = "scene") : label_(std::move(label)) {}
  // Registers `scene` (a choice among sceneNames()) and `triangles` on `choice`, with the lesson's
  // reasons for its defaults.
  static void declare(ParamRegistry& r, SceneChoice* choice, const std::string& whyScene,
                      const std::string& whyTriangles);
  // Builds makeScene(name, seed 1, triangles), or the placed model, when the choice or the model
  // changed. Returns true when it did. Throws std::runtime_error for "model" with none loaded.
  bool update(const SceneChoice& choice);

  // sceneNames(), then "model" (core/model_file's currentModel()).
  static std::vector<std::string> choices();
  static bool isModel(const SceneChoice& choice) { return std::size_t(choice.scene) + 1 == choices().size(); }

  const Scene& scene() const { return scene_; }
  const gl::GpuScene& gpu() const { return gpu_; }
  std::span<const Aabb> boxes() const { return boxes_; }
  std::span<const char> casts() const { return casts_; }
  const Aabb& bounds() const { return bounds_; }
  shadow::CasterBoxes casterBoxes() const { return {boxes_, casts_, bounds_}; }
  // Names the content (scene and size): equal revisions are equal scenes. 0 before the first build.
  std::uint64_t revision() const { return revision_; }

 private:
  std::string label_;
  Scene scene_;
  gl::GpuScene gpu_;
  std::vector<Aabb> boxes_;
  std::vector<char> casts_;
  Aabb bounds_;
  std::uint64_t revision_ = 0;
};

}  // namespace shadowlab::tech
