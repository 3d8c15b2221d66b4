#include "app/filtering_readout.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "gl/caps.hpp"

namespace shadowlab {

namespace {

double mib(std::uint64_t bytes) { return double(bytes) / (1024.0 * 1024.0); }

std::string fmt(const char* f, double a, double b = 0, double c = 0, double d = 0) {
  char buf[160];
  std::snprintf(buf, sizeof buf, f, a, b, c, d);
  return buf;
}

// levelColour() of shaders/06_texture_filtering/scene.frag, as drawn.
glm::vec3 levelColour(float level) {
  static const glm::vec3 palette[8] = {{0.2f, 0.2f, 1.0f}, {0.0f, 0.8f, 1.0f}, {0.0f, 0.9f, 0.3f}, {0.8f, 1.0f, 0.0f},
                                       {1.0f, 0.7f, 0.0f}, {1.0f, 0.2f, 0.0f}, {0.9f, 0.0f, 0.6f}, {1.0f, 1.0f, 1.0f}};
  const float l = std::clamp(level, 0.0f, 7.0f);
  const int i = int(l);
  return glm::mix(palette[i], palette[std::min(i + 1, 7)], l - float(i));
}

}  // namespace

glm::ivec2 probePixel(int x, int yFromTop, int width, int height) {
  return {std::clamp(x, 0, width - 1), height - 1 - std::clamp(yFromTop, 0, height - 1)};
}

void followMouse(int& x, int& yFromTop) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureMouse || io.MousePos.x < 0 || io.MousePos.y < 0) return;
  // Only when it moves: a preset's or a link's probe holds until the reader moves the mouse (the
  // browser's cursor sits at 0,0 until the mouse enters the page).
  if (io.MouseDelta.x == 0 && io.MouseDelta.y == 0) return;
  x = int(io.MousePos.x * io.DisplayFramebufferScale.x);
  yFromTop = int(io.MousePos.y * io.DisplayFramebufferScale.y);
}

FootprintSample readFootprint(const gl::FootprintTarget& target, glm::ivec2 pixel) {
  const glm::vec4 uv = gl::readFloatPixels(target.fbo.id(), 1, pixel.x, pixel.y, 1, 1)[0];
  const glm::vec4 d = gl::readFloatPixels(target.fbo.id(), 2, pixel.x, pixel.y, 1, 1)[0];
  return {uv.z >= 0.5f, {uv.x, uv.y}, {d.x, d.y}, {d.z, d.w}, uv.w};
}

std::vector<Counter> textureMemoryCounters(glm::ivec2 size, int levels, int n, float aniso) {
  const std::uint64_t base = std::uint64_t(size.x) * size.y * 4;
  const std::uint64_t chain = sampling::mipChainBytes(size.x, size.y, 4),
                      rip = sampling::ripMapBytes(size.x, size.y, 4);
  return {{"texture", fmt("%.0fx%.0f RGBA8, %.0f levels", size.x, size.y, double(levels))},
          {"mip chain", fmt("%.3f MiB = %.4f x base (lecture: 1.5)", mib(chain), double(chain) / double(base))},
          {"RIP map", fmt("%.3f MiB = %.4f x base", mib(rip), double(rip) / double(base))},
          {"3D texture", fmt("%.0f^3 x 4 B = %.2f MiB (lecture: 256^3 x 4 = %.0f MiB)", n,
                             mib(sampling::volumeBytes(n, n, n, 4)), mib(sampling::volumeBytes(256, 256, 256, 4)))},
          {"anisotropy", gl::caps().anisotropic ? fmt("%.0fx (max %.0fx)", aniso, gl::caps().maxAnisotropy)
                                                : std::string("extension missing: 1x only")}};
}

void appendProbeCounters(std::vector<Counter>& counters, glm::ivec2 probe, const FootprintSample& s,
                         const sampling::Footprint& fp, glm::ivec2 size, float lodBias) {
  const std::string at = fmt("(%.0f, %.0f)", probe.x, probe.y);
  if (!s.covered) {
    counters.push_back({"probe " + at, "sky: no texture"});
    return;
  }
  counters.push_back({"probe " + at + " uv", fmt("%.3f, %.3f", s.uv.x, s.uv.y)});
  counters.push_back({"probe d(uv)/dx,dy texels", fmt("(%.2f, %.2f) (%.2f, %.2f)", s.dx.x * size.x, s.dx.y * size.y,
                                                      s.dy.x * size.x, s.dy.y * size.y)});
  counters.push_back({"probe Px, Py", fmt("%.2f, %.2f texels", fp.px, fp.py)});
  counters.push_back(
      {"probe lambda CPU / GPU", fmt("%.2f / %.2f (+ bias %.2f)", fp.lambda, s.hardwareLambda, lodBias)});
  counters.push_back(
      {"probe anisotropic", fmt("N = %.0f probes at lambda' = %.2f", fp.probes, fp.lambdaAniso + lodBias)});
}

Counter referenceCounter(const FootprintReference::Result& r) {
  return {"CPU vs GPU RMSE", fmt("%.2f of 255 over %.0f pixels", r.rmse, double(r.pixels))};
}

Counter supersampledCounter(const SupersampledError::Result& r) {
  return {"RMSE vs supersampled",
          fmt("%.2f of 255 (%.0fx%.0f reference)", r.rmse, r.referenceWidth, r.referenceHeight)};
}

void printMeasureLine(int frame, const SupersampledError::Result& r) {
  std::printf("measure frame=%d rmse=%.4f flicker=%.4f ref_flicker=%.4f\n", frame, r.rmse, r.flicker,
              r.referenceFlicker);
  std::fflush(stdout);
}

Legend mipLevelLegend() {
  Legend key{"mip level the hardware picks", {}};
  for (int i = 0; i < 8; ++i)
    key.entries.push_back({levelColour(float(i)), "level " + std::to_string(i) + (i == 7 ? "+" : "")});
  return key;
}

Legend anisotropyLegend() {
  Legend key{"anisotropic probes N", {}};
  for (int i = 0; i < 5; ++i) key.entries.push_back({levelColour(float(i) * 1.75f), "N = " + std::to_string(1 << i)});
  return key;
}

void markPixel(GLuint framebuffer, glm::ivec2 pixel) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glEnable(GL_SCISSOR_TEST);
  glClearColor(1, 0.1f, 0.9f, 1);
  glScissor(pixel.x - 8, pixel.y, 17, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glScissor(pixel.x, pixel.y - 8, 1, 17);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
}

}  // namespace shadowlab
