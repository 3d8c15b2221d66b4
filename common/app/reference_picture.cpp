#include "app/reference_picture.hpp"

#include <filesystem>
#include <map>

#include "core/image.hpp"
#include "core/paths.hpp"
#include "gl/texture.hpp"

namespace shadowlab {

std::string presetInView(ParamRegistry& params, const PresetFile& presets) {
  const std::map<std::string, std::string> now = params.snapshot();
  std::string found;
  for (const std::string& name : presets.names()) {
    try {
      presets.apply(name, params);
    } catch (const ParamError&) {
      continue;  // validated at start; a preset that no longer applies matches nothing
    }
    const bool same = params.snapshot() == now;
    params.restore(now);
    if (same) {
      found = name;
      break;
    }
  }
  return found;
}

void ReferencePicture::frame(bool wanted, ParamRegistry& params, const PresetFile& presets, const std::string& lesson,
                             unsigned fbo, int width, int height) {
  update(wanted, params, presets, lesson);
  draw(fbo, width, height);
}

void ReferencePicture::update(bool wanted, ParamRegistry& params, const PresetFile& presets,
                              const std::string& lesson) {
  if (wanted == on_) return;
  on_ = wanted;
  texture_.reset();
  label_.clear();
  if (!on_) return;
  const std::string preset = presetInView(params, presets);
  if (preset.empty()) {
    label_ =
        "F4: your view and parameters match no preset, and the reference's pictures are per preset: "
        "apply one (F3), then F4";
    return;
  }
  const std::string file = "tests/data/golden/" + lesson + "/" + preset + ".png";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(sourceRoot() + "/" + file, ec)) {
    label_ = "F4: no reference picture of preset " + preset + " (" + file + " is missing)";
    return;
  }
  const Image8 image = loadImage(sourceRoot() + "/" + file, 4);
  // The image's bytes are the display values the reference wrote: no sRGB decode on the way.
  texture_ = gl::uploadTexture(image, "reference picture " + preset, false, gl::ColorData::Linear);
  label_ = "F4: the reference's picture of preset " + preset + " (" + file + ", " + std::to_string(image.width) + "x" +
           std::to_string(image.height) + ", rendered by the instructor); F4 again: your live picture";
}

void ReferencePicture::draw(unsigned fbo, int width, int height) {
  if (!texture_) return;
  if (!program_.valid()) program_.build();
  if (!program_.valid()) return;
  if (!vao_) vao_ = gl::makeVertexArray("reference picture triangle");
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glViewport(0, 0, width, height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  program_.use();
  program_.set("uOpacity", 1.0f);
  program_.set("uOverlay", 0);
  program_.set("uFlip", 1);  // the image is top row first; the triangle's v runs bottom to top
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, texture_.id());
  glBindVertexArray(vao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  gl::countDraws();
  glBindVertexArray(0);
}

}  // namespace shadowlab
