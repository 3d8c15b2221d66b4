// The loop every lesson runs in: command line, context, presets, input, timing, UI, screenshots,
// benchmark CSV and the GL-error verdict. Lessons only see the hooks in lesson.hpp.
#include <GLFW/glfw3.h>

#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>

#include "app/context.hpp"
#include "app/ab_split.hpp"
#include "app/god_view.hpp"
#include "app/lesson.hpp"
#include "app/ui.hpp"
#include "core/cli.hpp"
#include "core/image.hpp"
#include "core/paths.hpp"
#include "gl/caps.hpp"
#include "gl/debug.hpp"
#include "gl/gl.hpp"
#include "gl/program.hpp"
#include "gl/texture.hpp"
#include "measure/paths.hpp"

namespace shadowlab {
namespace {

double nowSeconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

std::string jsonEscape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out;
}

// Mouse and keys onto the camera and the framework's toggles. Input handling lives here, apart
// from the camera maths (core/camera), which stays pure and unit-tested.
struct Input {
  double lastX = 0, lastY = 0;
  bool haveLast = false;
  float scroll = 0;
  bool help = false;
  bool screenshot = false;
  bool reload = false;
  int uiScaleSteps = 0;
  bool toggleFullscreen = false;
  std::vector<int> pressed;  // plain key presses, for parameter hotkeys
  bool draggingDivider = false;
};

// Window width in the cursor's coordinates (screen coordinates, not framebuffer pixels).
double winWidth(GLFWwindow* w) {
  int ww = 1, wh = 1;
  glfwGetWindowSize(w, &ww, &wh);
  return double(std::max(ww, 1));
}
Input* g_input = nullptr;

void onScroll(GLFWwindow* w, double x, double y) {
  if (g_input) g_input->scroll += float(y);
}

void onKey(GLFWwindow* w, int key, int scancode, int action, int mods) {
  if (!g_input || action != GLFW_PRESS) return;
  const bool ctrl = mods & GLFW_MOD_CONTROL;
  if (key == GLFW_KEY_F1) g_input->help = !g_input->help;
  else if (key == GLFW_KEY_F11) g_input->toggleFullscreen = true;
  else if (key == GLFW_KEY_F12) g_input->screenshot = true;
  else if (ctrl && (key == GLFW_KEY_EQUAL || key == GLFW_KEY_KP_ADD)) ++g_input->uiScaleSteps;
  else if (ctrl && (key == GLFW_KEY_MINUS || key == GLFW_KEY_KP_SUBTRACT)) --g_input->uiScaleSteps;
  else if (key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(w, GLFW_TRUE);
  else if (!ctrl) g_input->pressed.push_back(key);
}

std::string keyName(int key) {
  if (key >= GLFW_KEY_0 && key <= GLFW_KEY_9) return std::string(1, char('0' + key - GLFW_KEY_0));
  if (key >= GLFW_KEY_A && key <= GLFW_KEY_Z) return std::string(1, char('A' + key - GLFW_KEY_A));
  return "";
}

// A hotkey toggles a bool or steps a choice to its next value.
bool applyHotkey(ParamRegistry& params, const std::string& key) {
  for (const auto& p : params.params()) {
    if (p.hotkey != key) continue;
    if (p.kind == ParamKind::Bool) params.set(p.name, params.get(p.name) == "true" ? "false" : "true");
    else if (p.kind == ParamKind::Choice) {
      const int i = *static_cast<int*>(p.target);
      params.set(p.name, p.choices[(i + 1) % p.choices.size()]);
    }
    return true;
  }
  return false;
}

std::string screenshotName(const LessonInfo& info) {
  std::time_t t = std::time(nullptr);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%d_%H%M%S", std::localtime(&t));
  return "out/screenshots/" + info.name + "_" + stamp + ".png";
}

void saveScreenshot(const std::string& path, unsigned fbo, int w, int h) {
  const std::filesystem::path p(path);
  if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
  savePng(path, gl::readPixels(fbo, w, h));
}

std::vector<std::string> shaderErrors() {
  std::vector<std::string> errors;
  for (const gl::Program* p : gl::livePrograms())
    if (!p->error().empty()) errors.push_back(p->error());
  return errors;
}

// --bench FILE: one row per pass per frame (GPU ms arrive a few frames late; each row carries the
// frame that issued it), plus the CPU time of each whole frame.
struct BenchLog {
  std::ofstream out;
  std::vector<double> frameMs;
  void write(gl::GpuTimers& timers) {
    for (const auto& s : timers.takeSamples())
      out << s.frame << ',' << s.pass << ',' << s.gpuMs << ',' << s.cpuMs << ','
          << (s.frame < int(frameMs.size()) ? frameMs[s.frame] : 0.0) << '\n';
  }
};

// --measure FILE: the last frame's figures against ground truth as JSON, and its heatmaps as PNGs
// beside it (FILE minus .json, plus _error.png / _aliasing.png), for benchmark runners.
void writeMeasurement(const std::string& path, const LessonInfo& info, const MeasureResult& r,
                      const std::vector<Counter>& counters, const gl::GpuTimers& timers) {
  if (!r.valid) throw std::runtime_error("--measure: nothing was measured (does the lesson describe its scene?)");
  const std::string stem =
      path.size() > 5 && path.substr(path.size() - 5) == ".json" ? path.substr(0, path.size() - 5) : path;
  const std::filesystem::path p(path);
  if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
  std::ofstream out(path);
  if (!out) throw std::runtime_error("--measure: cannot write " + path);
  out << "{\n  \"lesson\": \"" << info.name << "\",\n  \"width\": " << r.width << ", \"height\": " << r.height << ",\n";
  if (r.soft) {
    out << "  \"soft\": {\"pixels\": " << r.soft_.pixels << ", \"rmse\": " << r.soft_.rmse
        << ", \"max_abs\": " << r.soft_.maxAbs << "},\n";
  } else {
    const auto& h = r.hard;
    out << "  \"hard\": {\"facing_pixels\": " << h.facingPixels << ", \"misclassified\": " << h.misclassified
        << ", \"leaks\": " << h.leaks << ", \"false_shadows\": " << h.falseShadows
        << ", \"edge_pixels\": " << h.edgePixels << ", \"misclassified_pct\": " << h.misclassifiedPct
        << ", \"leak_pct\": " << h.leakPct << ", \"false_shadow_pct\": " << h.falseShadowPct
        << ", \"edge_tolerant_pct\": " << h.edgeTolerantPct << "},\n";
  }
  if (r.hasAliasing) {
    const auto& a = r.aliasing;
    out << "  \"aliasing\": {\"pixels\": " << a.pixels << ", \"mean\": " << a.mean << ", \"rms\": " << a.rms
        << ", \"p95\": " << a.p95 << ", \"max\": " << a.max << ", \"share_above_1\": " << a.shareAbove1 << "},\n";
  }
  out << "  \"ground_truth_ms\": " << r.groundTruthMs << ",\n  \"gpu_ms\": {";
  bool first = true;
  for (const auto& t : timers.passes()) {
    out << (first ? "" : ", ") << "\"" << jsonEscape(t.name) << "\": " << t.gpuMs;
    first = false;
  }
  out << "},\n  \"cpu_ms\": {";
  first = true;
  for (const auto& t : timers.passes()) {
    out << (first ? "" : ", ") << "\"" << jsonEscape(t.name) << "\": " << t.cpuMs;
    first = false;
  }
  out << "},\n  \"counters\": {";
  first = true;
  for (const auto& c : counters) {
    out << (first ? "" : ", ") << "\"" << jsonEscape(c.name) << "\": \"" << jsonEscape(c.value) << "\"";
    first = false;
  }
  out << "}\n}\n";
  savePng(stem + "_error.png", r.errorHeatmap);
  if (r.hasAliasing) savePng(stem + "_aliasing.png", r.aliasingHeatmap);
}

}  // namespace

void declareCamera(ParamRegistry& params, OrbitCamera& c) {
  params.add("camera.yaw", &c.yaw, -1000.0f, 1000.0f, "orbit angle around +y (radians)").hidden = true;
  params.add("camera.pitch", &c.pitch, -1.57f, 1.57f, "angle above the horizon (radians)").hidden = true;
  params.add("camera.distance", &c.distance, 0.01f, 10000.0f, "distance from the target").hidden = true;
  params.add("camera.target", &c.target, -10000.0f, 10000.0f, "the point the camera orbits").hidden = true;
  params.add("camera.fov", &c.fovY, 0.1f, 3.0f, "vertical field of view (radians)").hidden = true;
  params.add("camera.near", &c.nearZ, 1e-4f, 100.0f, "near plane distance").hidden = true;
  params.add("camera.far", &c.farZ, 0.1f, 1e7f, "far plane distance").hidden = true;
}

void declareLight(ParamRegistry& r, int index, Light& l) {
  const std::string n = "light" + std::to_string(index) + ".";
  r.add(n + "enabled", &l.enabled, "switch this light on or off").hotkey = std::to_string(index + 1);
  r.addChoice(n + "kind", &l.kind, {"point", "spot", "directional"}, "point, spot (a cone) or directional (the sun)");
  r.add(n + "position", &l.position, -50, 50, "where a point or spot light is");
  r.add(n + "direction", &l.direction, -1, 1, "spot axis, or the direction sunlight travels");
  r.addColor(n + "color", &l.color, "I_i: the light's colour");
  r.add(n + "intensity", &l.intensity, 0, 20, "I_i: the light's strength");
  r.add(n + "attenuation", &l.attenuation, 0, 10, "c0 c1 c2 of f_att = 1 / (c0 + c1 d + c2 d^2)");
  r.add(n + "spot_inner", &l.spotInner, 0.01f, 1.5f, "half-angle of the spot's full-strength core (radians)");
  r.add(n + "spot_outer", &l.spotOuter, 0.01f, 1.5f, "half-angle where the spot fades to zero (radians)");
  // (AreaShape::Rectangle needs a size and a tangent as well; no lesson exposes it yet.)
  r.addChoice(n + "area", &l.area, {"none", "sphere"}, "a spherical emitter: soft shadows, and the soft ground truth");
  r.add(n + "radius", &l.radius, 0.0f, 10.0f, "the spherical emitter's radius");
}

int runLesson(const std::function<std::unique_ptr<Lesson>()>& make, int argc, char** argv) {
  // Declaration order matters: the lesson (and its GL objects) is destroyed before the context.
  std::unique_ptr<Context> context;
  std::unique_ptr<Lesson> owned = make();
  Lesson& lesson = *owned;
  const LessonInfo info = lesson.info();
  CommandLine cl;
  ParamRegistry params;
  PresetFile presets;
  Measurement measurement;  // holds GL objects: declared after the context, destroyed before it
  GodView godView;
  AbSplit ab;
  try {
    cl = parseCommandLine(argc, argv);
    lesson.declare(params);                // may set the camera's starting pose...
    declareCamera(params, lesson.camera);  // ...which then is the camera's default
    godView.declare(params);
    if (info.measurable) measurement.declare(params);
    else if (!cl.measure.empty()) throw CliError("--measure: lesson " + info.name + " computes no shadows to measure");
    presets = PresetFile::load(sourceRoot() + "/lessons/" + info.name + "/presets.txt");
    ab.declare(params, presets);
    presets.validate(params);
    if (cl.help) {
      std::cout << info.number << " " << info.title << ": " << info.summary << "\n\n" << commandLineHelp(argv[0]);
      return 0;
    }
    if (cl.info) {
      std::cout << "{\"number\":\"" << info.number << "\",\"name\":\"" << info.name << "\",\"title\":\""
                << jsonEscape(info.title) << "\",\"summary\":\"" << jsonEscape(info.summary)
                << "\",\"difficulty\":" << info.difficulty << "}\n";
      return 0;
    }
    if (cl.listParams) {
      std::cout << params.describe();
      return 0;
    }
    if (cl.listPresets) {
      for (const auto& n : presets.names()) std::cout << n << '\n';
      return 0;
    }
    if (!cl.preset.empty()) presets.apply(cl.preset, params);
    for (const auto& s : cl.sets) params.assign(s);
  } catch (const std::exception& e) {  // CliError, ParamError
    std::cerr << info.name << ": " << e.what() << '\n';
    return 2;
  }

  try {
    ContextOptions options{cl.width, cl.height, info.number + " " + info.title, true, cl.fullscreen};
    if (!cl.headless && !displayAvailable()) {
      std::cerr << info.name << ": no display (DISPLAY / WAYLAND_DISPLAY unset); use --headless\n";
      return 1;
    }
    context = cl.headless ? createHeadlessContext(options) : createWindowContext(options);
  } catch (const std::exception& e) {
    std::cerr << info.name << ": " << e.what() << '\n';
    return 1;
  }
  gl::installDebugOutput();
  const gl::Caps& caps = gl::caps();
  // Software renderers rasterise deferred: time passes synchronously there (see GpuTimers).
  bool syncTimers =
      caps.renderer.find("llvmpipe") != std::string::npos || caps.renderer.find("softpipe") != std::string::npos;
  if (const char* s = std::getenv("SHADOWLAB_SYNC_TIMERS")) syncTimers = std::string(s) == "1";
  lesson.timers.setSynchronous(syncTimers);

  Input input;
  g_input = &input;
  if (GLFWwindow* w = context->window()) {
    glfwSetScrollCallback(w, onScroll);
    glfwSetKeyCallback(w, onKey);
  }
  Ui ui;
  const bool uiVisible = !cl.headless || cl.showUi;
  if (uiVisible) ui.init(*context, cl.uiScale > 0 ? cl.uiScale : context->contentScale());
  if (GLFWwindow* w = context->window()) {  // chain ImGui's callbacks after ours
    glfwSetScrollCallback(w, onScroll);
    glfwSetKeyCallback(w, onKey);
  }

  std::string initError;
  auto tryInit = [&] {
    try {
      lesson.init();
      initError.clear();
    } catch (const std::exception& e) { initError = e.what(); }
  };
  tryInit();
  if (cl.headless) {
    std::vector<std::string> errors = shaderErrors();
    if (!initError.empty()) errors.insert(errors.begin(), initError);
    if (!errors.empty()) {
      for (const auto& e : errors) std::cerr << info.name << ": " << e << '\n';
      return 1;
    }
  }

  // Recorded camera and light paths: --record while moving (windowed), --replay FILE[@T].
  measure::CameraLightPath recording, replay;
  double replayAt = -1;
  if (!cl.replay.empty()) {
    std::string file = cl.replay;
    if (const auto at = file.rfind('@'); at != std::string::npos) {
      char* end = nullptr;
      replayAt = std::strtod(file.c_str() + at + 1, &end);
      if (end == file.c_str() + at + 1 || *end != '\0' || !(replayAt >= 0)) {
        std::cerr << info.name << ": --replay " << cl.replay << ": '" << file.substr(at + 1)
                  << "' is not a time >= 0\n";
        return 2;
      }
      file = file.substr(0, at);
    }
    try {
      replay = measure::CameraLightPath::load(file);
      if (replay.empty()) throw std::runtime_error(file + ": the path has no keys");
    } catch (const std::exception& e) {
      std::cerr << info.name << ": --replay: " << e.what() << '\n';
      return 2;
    }
  }

  BenchLog bench;
  if (!cl.bench.empty()) {
    bench.out.open(cl.bench);
    if (!bench.out) {
      std::cerr << info.name << ": cannot write --bench file " << cl.bench << '\n';
      return 1;
    }
    bench.out << "frame,pass,gpu_ms,cpu_ms,frame_ms\n";
    lesson.timers.keepSamples(true);
  }

  int width = context->width(), height = context->height();
  lesson.resize(width, height);
  bool helpOpen = false;
  glm::mat4 lastView(0.0f);
  unsigned lastRevision = ~0u;
  std::string status;
  double frameMsAvg = 0;
  double time = 0;
  double last = nowSeconds();
  for (int frame = 0; cl.frames < 0 || frame < cl.frames; ++frame) {
    if (context->shouldClose()) break;
    context->pollEvents();
    const double start = nowSeconds();
    const double dt = cl.headless ? 1.0 / 60.0 : std::min(start - last, 0.1);
    last = start;
    time += dt;

    // ---- input -----------------------------------------------------------------------------
    if (GLFWwindow* w = context->window()) {
      double x, y;
      glfwGetCursorPos(w, &x, &y);
      if (input.haveLast && !ui.wantsMouse()) {
        const float dx = float(x - input.lastX), dy = float(y - input.lastY);
        const bool left = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
        if (left && ab.enabled() && (input.draggingDivider || std::abs(x - ab.divider() * winWidth(w)) < 8)) {
          input.draggingDivider = true;  // the A/B divider follows the mouse
          ab.setDivider(float(x / winWidth(w)));
        } else if (left) {
          lesson.camera.orbit(-dx * 0.005f, dy * 0.005f);
        }
        if (!left) input.draggingDivider = false;
        if (glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS) lesson.camera.pan({-dx, dy});
        if (input.scroll != 0) lesson.camera.zoom(std::pow(0.9f, input.scroll));
      }
      input.scroll = 0;
      input.lastX = x;
      input.lastY = y;
      input.haveLast = true;
      if (input.uiScaleSteps != 0) {
        ui.setScale(ui.scale() * std::pow(1.15f, float(input.uiScaleSteps)));
        input.uiScaleSteps = 0;
      }
      if (input.toggleFullscreen) {
        context->setFullscreen(!context->fullscreen());
        input.toggleFullscreen = false;
      }
      helpOpen = input.help;
      if (!ui.wantsKeyboard()) {
        for (int key : input.pressed) {
          if (key == GLFW_KEY_R) {
            for (gl::Program* p : gl::livePrograms()) p->build();
            if (!initError.empty()) tryInit();
            status = "reloaded shaders";
          } else {
            applyHotkey(params, keyName(key));
          }
        }
      }
      input.pressed.clear();
    }
    for (gl::Program* p : gl::livePrograms()) p->reloadIfChanged();

    if (context->width() != width || context->height() != height) {
      width = context->width();
      height = context->height();
      if (width > 0 && height > 0) lesson.resize(width, height);
    }
    if (width == 0 || height == 0) {  // minimised
      context->present();
      continue;
    }

    // ---- the lesson ------------------------------------------------------------------------
    const bool lastFrame = cl.frames > 0 && frame + 1 == cl.frames;
    if (lastFrame && !cl.measure.empty()) measurement.requestFullResolution();
    if (!replay.empty()) {
      const double t0 = replay.keys().front().time;
      const double t = replayAt >= 0   ? t0 + replayAt
                       : cl.frames > 1 ? t0 + replay.duration() * double(frame) / double(cl.frames - 1)
                                       : t0 + time;
      const measure::PathKey key = replay.sample(t);
      lesson.camera.lookFrom(key.cameraPosition, key.cameraTarget);
      lesson.applyPathLight(key.lightPosition, key.lightDirection);
    }
    FrameInfo fi{frame, time, dt, width, height, context->framebuffer()};
    fi.view = lesson.camera.view();
    fi.projection = lesson.camera.projection(float(width) / float(height));
    fi.eye = lesson.camera.position();
    lesson.timers.setFrame(frame);
    lesson.debug.clear();
    const unsigned frameFbo = fi.framebuffer;
    std::vector<std::string> errors = shaderErrors();
    if (!initError.empty()) errors.insert(errors.begin(), initError);
    bool programsReady = true;
    for (const gl::Program* p : gl::livePrograms()) programsReady = programsReady && p->valid();
    glBindFramebuffer(GL_FRAMEBUFFER, fi.framebuffer);
    glViewport(0, 0, width, height);
    if (initError.empty() && programsReady) {
      try {
        lesson.update(fi);
        fi.framebuffer = measurement.begin(frameFbo, width, height);
        fi.measureLight = measurement.measuredLight();
        glBindFramebuffer(GL_FRAMEBUFFER, fi.framebuffer);
        glViewport(0, 0, width, height);
        lesson.render(fi);
        // Re-measure when anything the picture depends on moved: the camera or any parameter.
        const glm::mat4 view = lesson.camera.view();
        const bool viewChanged = view != lastView || params.revision() != lastRevision;
        lastView = view;
        lastRevision = params.revision();
        measurement.end(lesson.measureSource(), frameFbo, viewChanged);
        fi.framebuffer = frameFbo;
        if (ab.enabled()) {
          ab.draw(fi, params, presets, lesson, info.measurable ? &measurement : nullptr,
                  [&](const FrameInfo& b) { lesson.render(b); });
          lastRevision = params.revision();  // switching to B and back is not a change
          glViewport(0, 0, width, height);
        }
        if (godView.enabled()) {
          lesson.timers.setEnabled(false);
          godView.draw(fi, lesson.camera, lesson.debug, [&](const FrameInfo& g) { lesson.render(g); });
          lesson.timers.setEnabled(true);
          glViewport(0, 0, width, height);
        }
      } catch (const std::exception& e) {
        // A file that cannot be read, a scene that cannot be built: headless runs fail with the
        // message; a window keeps running and shows it until a reload (R) succeeds.
        if (cl.headless) {
          std::cerr << info.name << ": " << e.what() << '\n';
          return 1;
        }
        initError = e.what();
      }
    }
    if (!initError.empty() || !programsReady) {
      // Nothing valid to draw with: a dark red frame, and the error in the header.
      glClearColor(0.25f, 0.05f, 0.05f, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }
    lesson.timers.collect();

    if (uiVisible) {
      glBindFramebuffer(GL_FRAMEBUFFER, fi.framebuffer);
      glViewport(0, 0, width, height);
      ui.newFrame(dt, width, height);
      std::vector<Counter> shown = lesson.counters;
      for (auto& [name, value] : measurement.summary()) shown.push_back({name, value});
      ui.header({&info, caps.summary(), frameMsAvg, &lesson.timers.passes(), &shown, errors, status});
      ui.paramPanel(params, presets, status);
      if (ab.enabled()) ui.splitLabels(ab.divider(), ab.labelA(info.measurable ? &measurement : nullptr), ab.labelB());
      lesson.gui();
      ui.help(info, params, &helpOpen);
      input.help = helpOpen;
      ui.render();
    }

    if (input.screenshot) {
      const std::string path = screenshotName(info);
      saveScreenshot(path, fi.framebuffer, width, height);
      status = "saved " + path;
      input.screenshot = false;
    }
    if (!caps.khrDebug) gl::checkErrors("end of frame");

    if (lastFrame && !cl.measure.empty()) {
      try {
        writeMeasurement(cl.measure, info, measurement.result(), lesson.counters, lesson.timers);
      } catch (const std::exception& e) {
        std::cerr << info.name << ": " << e.what() << '\n';
        return 1;
      }
    }
    if (lastFrame && !cl.screenshot.empty()) {
      try {
        saveScreenshot(cl.screenshot, fi.framebuffer, width, height);
      } catch (const std::exception& e) {
        std::cerr << info.name << ": " << e.what() << '\n';
        return 1;
      }
    }
    if (!cl.record.empty()) {
      const MeasureSource source = lesson.measureSource();
      const int which = std::max(0, measurement.measuredLight());
      measure::PathKey key;
      key.time = time;
      key.cameraPosition = lesson.camera.position();
      key.cameraTarget = lesson.camera.target;
      if (which < int(source.lights.size())) {
        key.lightPosition = source.lights[std::size_t(which)].position;
        key.lightDirection = source.lights[std::size_t(which)].direction;
      }
      recording.add(key);
    }
    context->present();
    // Frame time includes present: software rasterisers (llvmpipe) do much of their work there.
    const double frameMs = (nowSeconds() - start) * 1000.0;
    frameMsAvg = frameMsAvg == 0 ? frameMs : 0.9 * frameMsAvg + 0.1 * frameMs;
    if (bench.out.is_open()) {
      bench.frameMs.resize(std::size_t(frame) + 1);
      bench.frameMs[std::size_t(frame)] = frameMs;
      bench.write(lesson.timers);
    }
  }
  if (!cl.record.empty()) {
    try {
      const std::filesystem::path p(cl.record);
      if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
      recording.save(cl.record);
      std::cout << info.name << ": recorded " << recording.keys().size() << " keys to " << cl.record << '\n';
    } catch (const std::exception& e) {
      std::cerr << info.name << ": --record: " << e.what() << '\n';
      return 1;
    }
  }
  // Let outstanding timer queries resolve so the benchmark has every frame.
  glFinish();
  lesson.timers.collect();
  if (bench.out.is_open()) bench.write(lesson.timers);
  gl::checkErrors("exit");
  const int glErrors = gl::errorCount();
  if (uiVisible) ui.shutdown();
  owned.reset();
  g_input = nullptr;
  if (glErrors > 0) {
    std::cerr << info.name << ": " << glErrors << " OpenGL error(s); first: " << gl::errorMessages().front() << '\n';
    if (cl.strictGl) return 3;
  }
  return 0;
}

}  // namespace shadowlab
