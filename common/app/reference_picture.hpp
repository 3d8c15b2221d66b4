#pragma once
// F4: the reference's picture of the preset in view, as the instructor rendered it, in place of the
// live frame. The student handout draws its GLSL exercises with the student's exercises.glsl (the
// reference GLSL is withheld, core/shader_files.hpp), so this is where a student sees what the
// lesson should look like: the golden image of that preset (tests/data/golden/<lesson>/<preset>.png,
// rendered with the reference at 320x180 and shipped with the handout). The preset in view is the
// one whose values (camera included) equal the current parameters; with none, or no image, the
// label says so and the live frame stays.
#include <string>

#include "core/params.hpp"
#include "gl/objects.hpp"
#include "gl/program.hpp"

namespace shadowlab {

class ReferencePicture {
 public:
  // Called every frame with F4's state: on a change to on, finds the preset and loads its image;
  // while one is shown, draws it over the frame in `fbo` (width x height).
  void frame(bool wanted, ParamRegistry& params, const PresetFile& presets, const std::string& lesson, unsigned fbo,
             int width, int height);
  bool shown() const { return texture_.id() != 0; }
  // What is on screen, for the banner: "" while off.
  const std::string& label() const { return label_; }

 private:
  void update(bool wanted, ParamRegistry& params, const PresetFile& presets, const std::string& lesson);
  void draw(unsigned fbo, int width, int height);
  bool on_ = false;
  std::string label_;
  gl::Texture texture_;
  gl::VertexArray vao_;
  gl::Program program_{"reference picture", {"common/fullscreen.vert", "common/overlay.frag"}};
};

// The preset whose values, over the defaults, equal the current parameters ("" for none). The
// parameters are applied and restored to compare (one change each way).
std::string presetInView(ParamRegistry& params, const PresetFile& presets);

}  // namespace shadowlab
