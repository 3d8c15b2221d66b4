#pragma once
// What a texture-filtering lesson (lesson 06) shows beside its picture: the texture's memory against
// the lecture's figures (mip chain, RIP map, 3D texture), the footprint of the pixel under the
// cursor as its scene pass wrote it into a gl::FootprintTarget, with lambda from the CPU and from
// the hardware, the colour keys of the mip-level and anisotropy views, the error lines of the CPU
// reference and of the supersampled reference, and the probed pixel marked on screen. The lesson
// computes; these say it.
#include <vector>

#include <glm/glm.hpp>

#include "algorithms/texture_sampling.hpp"
#include "app/footprint_reference.hpp"
#include "app/lesson.hpp"
#include "gl/texture_modes.hpp"

namespace shadowlab {

// The probed pixel in GL's bottom-left origin: (x, yFromTop) as the mouse or probe.x / probe.y give
// it, clamped into a width x height frame.
glm::ivec2 probePixel(int x, int yFromTop, int width, int height);
// Moves (x, yFromTop) to the mouse's framebuffer pixel when the mouse moved, unless the UI has the
// mouse or it is outside the window (from Lesson::gui()).
void followMouse(int& x, int& yFromTop);

// One pixel of a scene pass as the shader wrote it (attachments 1 and 2 of the target).
struct FootprintSample {
  bool covered = false;  // textured; false: the sky
  glm::vec2 uv{0.0f};
  glm::vec2 dx{0.0f}, dy{0.0f};  // d(uv)/dx, d(uv)/dy
  float hardwareLambda = 0;      // what textureQueryLod computed
};
FootprintSample readFootprint(const gl::FootprintTarget& target, glm::ivec2 pixel);

// The header's lines on a size.x x size.y RGBA8 texture of `levels` levels, a volumeSide^3 3D
// texture and the anisotropy the sampler got (1 without the extension).
std::vector<Counter> textureMemoryCounters(glm::ivec2 size, int levels, int volumeSide, float aniso);
// The readout of `s`, probed at `probe` (as given): uv, derivatives in texels, the footprint `fp`
// the CPU computed for it, lambda from both sides (`lodBias` the sampler's) and the probes.
void appendProbeCounters(std::vector<Counter>& counters, glm::ivec2 probe, const FootprintSample& s,
                         const sampling::Footprint& fp, glm::ivec2 size, float lodBias);
Counter referenceCounter(const FootprintReference::Result& r);    // CPU against GPU
Counter supersampledCounter(const SupersampledError::Result& r);  // against the supersampled frame
// "measure frame=N rmse=... flicker=... ref_flicker=..." on stdout: what tools/filter_sweep reads.
void printMeasureLine(int frame, const SupersampledError::Result& r);

// The colour keys of scene.frag's levelColour(): the mip level, and the anisotropic probe count.
Legend mipLevelLegend();
Legend anisotropyLegend();

// Marks `pixel` of `framebuffer` with a small magenta cross.
void markPixel(GLuint framebuffer, glm::ivec2 pixel);

}  // namespace shadowlab
