// The loop every lesson runs in: command line, context, presets, input, timing, UI, screenshots,
// benchmark CSV and the GL-error verdict. Lessons only see the hooks in lesson.hpp. runLesson is
// four stages, each a method of Runner below: parse (the command line, the registry, presets; exit
// 2 on bad input), open (the context, the lesson's init, the output files), the frame loop (input,
// the lesson, the framework's views, the UI, the outputs) and teardown (the GL verdict, the lesson
// released before its context).
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iostream>
#include <optional>
#include <sstream>

#include "app/ab_split.hpp"
#include "app/context.hpp"
#include "app/frame_budget.hpp"
#include "app/frame_loop.hpp"
#include "app/god_view.hpp"
#include "app/input.hpp"
#include "app/lesson.hpp"
#include "app/lesson_setup.hpp"
#include "app/model_choice.hpp"
#include "app/outputs.hpp"
#include "app/reference_picture.hpp"
#include "app/ui.hpp"
#include "core/cli.hpp"
#include "core/model_file.hpp"
#include "core/param_checks.hpp"
#include "core/paths.hpp"
#include "core/shader_files.hpp"
#include "gl/caps.hpp"
#include "gl/debug.hpp"
#include "gl/gl.hpp"
#include "gl/program.hpp"
#include "measure/paths.hpp"

namespace shadowlab {
namespace {

double nowSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

using Exit = std::optional<int>;  // a process exit code, or nothing: go on

class Runner {
 public:
  explicit Runner(std::unique_ptr<Lesson> lesson)
      : owned_(std::move(lesson)), lesson_(*owned_), info_(lesson_.info()) {}

  // Everything before the first frame; an exit code ends the run there.
  Exit start(int argc, char** argv) {
    if (Exit e = parse(argc, argv)) return e;
    if (!cl_.model.empty()) {
      if (!loadModelReporting(cl_.model, info_.name)) return 1;  // a bad file: exit 1
      if (!cameraSetOnCommandLine(cl_.sets)) aimAtModel();
    }
    if (Exit e = openContext()) return e;
    if (Exit e = initLesson()) return e;
    if (Exit e = startExercises()) return e;
    return openOutputs();
  }
  // One frame, or the run's exit code once it is over (--frames done, the window closed, Esc).
  Exit step(int frame) {
    if ((cl_.frames >= 0 && frame >= cl_.frames) || context_->shouldClose() || input_.quit) return teardown();
    return runFrame(frame);
  }

 private:
  // ==== 1. parse: the command line, the parameters, the presets (exit 2 on bad input) ============
  Exit parse(int argc, char** argv) {
    try {
      cl_ = parseCommandLine(argc, argv);
      lesson_.declare(params_);                // may set the camera's starting pose...
      declareCamera(params_, lesson_.camera);  // ...which then is the camera's default
      godView_.declare(params_);
      budget_.declare(params_);
      if (info_.measurable) measurement_.declare(params_);
      else if (!cl_.measure.empty())
        throw CliError("--measure: lesson " + info_.name + " computes no shadows to measure");
      presets_ = PresetFile::load(sourceRoot() + "/lessons/" + info_.name + "/presets.txt");
      ab_.declare(params_, presets_);
      params_.validate();  // the defaults, then every preset, pass the registry's checks
      exposeParams(&params_), presets_.validate(params_);  // a browser page reads them (frame_loop.hpp)
      checkHotkeys(params_);
      if (answerQuery(cl_, info_, params_, presets_, lesson_.exercises, argv[0])) return 0;
      if (!cl_.preset.empty()) presets_.apply(cl_.preset, params_);
      if (!cl_.model.empty()) cl_.sets.insert(cl_.sets.begin(), modelSceneAssignment(params_, info_.name));
      params_.assignAll(cl_.sets);            // one change: checked once, whatever the order
      ui_.panelOnly(cl_.panelOnly, params_);  // --panel: names the lesson has
      if (cl_.model.empty() && sceneIsModel(params_))
        throw CliError("scene=model draws the file given with --model FILE (OBJ + MTL, glTF 2.0); none given");
      homeCamera_ = lesson_.camera;  // Home comes back here
      keys_ = KeyScript(cl_.keys);
    } catch (const std::exception& e) {  // CliError, ParamError
      std::cerr << info_.name << ": " << e.what() << '\n';
      return 2;
    }
    return std::nullopt;
  }

  void aimAtModel() {  // model_choice.hpp: where the camera looks at the model; Home comes back here
    aimCameraAtModel(lesson_.camera);
    homeCamera_ = lesson_.camera;
  }

  // A key bound twice (framework keys included) or on a kind it cannot drive: the lesson is wrong,
  // and a lecturer would find out in front of the class. Every lesson's tests run this.
  // ==== 2. open: the context, the lesson's GL resources, the files the run reads and writes ======
  Exit openContext() {
    try {
      ContextOptions options{cl_.width, cl_.height, info_.number + " " + info_.title, true, cl_.fullscreen};
      if (!cl_.headless && !displayAvailable()) {
        std::cerr << info_.name << ": no display (DISPLAY / WAYLAND_DISPLAY unset); use --headless\n";
        return 1;
      }
      context_ = cl_.headless ? createHeadlessContext(options) : createWindowContext(options);
    } catch (const FramebufferSizeError& e) {
      std::cerr << info_.name << ": " << e.what() << '\n';
      return 2;
    } catch (const std::exception& e) {
      std::cerr << info_.name << ": " << e.what() << '\n';
      return 1;
    }
    gl::installDebugOutput(cl_.strictGl);
    // Software renderers rasterise deferred: time passes synchronously there (see GpuTimers).
    const gl::Caps& caps = gl::caps();
    bool sync = !caps.timerQuery || caps.renderer.find("llvmpipe") != std::string::npos ||
                caps.renderer.find("softpipe") != std::string::npos;  // no timestamps, or deferred ones
    if (const char* s = std::getenv("SHADOWLAB_SYNC_TIMERS")) sync = std::string(s) == "1";
    lesson_.timers.setSynchronous(sync);
    // A window compiles specialised shaders in the background; headless frames must not depend on
    // how fast the driver compiles, so they wait for every program.
    gl::setAsyncCompile(!cl_.headless);

    installInputCallbacks(context_->window(), &input_);
    uiVisible_ = !cl_.headless || cl_.showUi;
    input_.help = helpOpen_ = cl_.showHelp;
    input_.stats = statsOpen_ = cl_.showStats;
    input_.panel = panelOpen_ = cl_.showPanel;
    if (uiVisible_) ui_.init(*context_, cl_.uiScale > 0 ? cl_.uiScale : context_->contentScale());
    installInputCallbacks(context_->window(), &input_);  // chain ImGui's callbacks after ours
    return std::nullopt;
  }

  void tryInit() {
    try {
      lesson_.init();
      initError_.clear();
    } catch (const std::exception& e) { initError_ = e.what(); }
  }

  // Headless, a missing file or a broken shader ends the run (exit 1); a window shows it instead.
  Exit initLesson() {
    tryInit();
    if (!cl_.headless) return std::nullopt;
    std::vector<std::string> errors = gl::shaderErrors(/*requiredOnly=*/true);
    if (!initError_.empty()) errors.insert(errors.begin(), initError_);
    for (const auto& e : errors) std::cerr << info_.name << ": " << e << '\n';
    return errors.empty() ? Exit() : Exit(1);
  }

  // ==== exercises: the panel's states from the public cases, and the stub banner =================
  bool studentCode() const {
    const Exercises& ex = lesson_.exercises;
    return !ex.empty() && params_.has(ex.param()) && params_.get(ex.param()) == ex.studentValue();
  }

  // The cases run at start (headless only when their verdicts are shown); --exercises prints them.
  Exit startExercises() {
    Exercises& ex = lesson_.exercises;
    if (cl_.exercises) {
      if (!ex.empty()) ex.evaluate(info_.name);
      std::cout << (ex.empty() ? info_.name + ": no exercises in this lesson\n" : ex.report());
      return 0;
    }
    if (!ex.empty() && (!cl_.headless || cl_.showUi || studentCode())) ex.evaluate(info_.name);
    return std::nullopt;
  }

  // Every 30 frames: the cases again when asked or exercises.glsl was saved; the banner: the stubs
  // (the student's code in use), whose GLSL draws where the handout withholds the reference's, and a
  // camera that sees none of the scene (headless: once; on stderr with the camera's).
  void watchExercises(const FrameInfo& fi, int frame) {
    Exercises& ex = lesson_.exercises;
    if (ex.empty() || (frame % 30 != 0 && !rerunExercises_)) return;
    if (std::exchange(rerunExercises_, false) || ex.glslChanged()) ex.evaluate(info_.name);
    banner_ =
        studentCode() && !ex.stubBanner(0).empty() ? ex.stubBanner(blackShare(fi.framebuffer, width_, height_)) : "";
    const std::string sight = sightBanner(lesson_, float(width_) / float(height_));
    for (const std::string& more : {withheldBanner(takeWithheldDrawn(), ex.glslInUse(params_), info_.name), sight})
      if (!more.empty()) banner_ += (banner_.empty() ? "" : "\n") + more;
    if (cl_.headless && !banner_.empty() && !bannerPrinted_)
      (sight.empty() ? std::cout : std::cerr) << info_.name << ": " << banner_ << '\n';
    bannerPrinted_ = bannerPrinted_ || !banner_.empty();
  }

  // Recorded camera and light paths (--replay FILE[@T|@T0..T1]) and the --bench CSV.
  Exit openOutputs() {
    if (!cl_.replay.empty()) {
      measure::ReplaySpec spec;
      try {
        spec = measure::parseReplaySpec(cl_.replay);
      } catch (const std::invalid_argument& e) {
        std::cerr << info_.name << ": --replay " << cl_.replay << ": " << e.what() << '\n';
        return 2;
      }
      replaySpan_ = spec;
      try {  // a missing or malformed path file: exit 1, naming file:line
        replay_ = measure::CameraLightPath::load(spec.file);
        if (replay_.empty()) throw std::runtime_error(spec.file + ": the path has no keys");
      } catch (const std::exception& e) {
        std::cerr << info_.name << ": --replay: " << e.what() << '\n';
        return 1;
      }
    }
    if (!cl_.bench.empty()) {
      if (!bench_.open(cl_.bench)) {
        std::cerr << info_.name << ": cannot write --bench file " << cl_.bench << '\n';
        return 1;
      }
      lesson_.timers.keepSamples(true);
    }
    width_ = context_->width();
    height_ = context_->height();
    lesson_.resize(width_, height_);
    last_ = nowSeconds();
    return std::nullopt;
  }

  // ==== 3. the frame loop ============================================================================
  Exit runFrame(int frame) {
    context_->pollEvents();
    const double start = nowSeconds();
    const double dt = cl_.headless ? 1.0 / 60.0 : std::min(start - last_, 0.1);
    if (const double before = std::exchange(last_, start); before > 0) sinceLast_ = (start - before) * 1000.0;
    time_ += dt;
    keys_.beginFrame(input_);
    if (frame == cl_.dropFrame && !cl_.drop.empty()) dropFiles(input_, {cl_.drop});
    if (context_->window() || !keys_.empty() || !cl_.drop.empty()) handleInput(float(dt));
    reportScriptedKey(keys_.endFrame());
    for (gl::Program* p : gl::livePrograms()) p->reloadIfChanged();
    if (context_->width() != width_ || context_->height() != height_) {
      width_ = context_->width();
      height_ = context_->height();
      if (width_ > 0 && height_ > 0) lesson_.resize(width_, height_);
    }
    if (width_ == 0 || height_ == 0) {  // minimised
      context_->present();
      return std::nullopt;
    }
    const bool lastFrame = cl_.frames > 0 && frame + 1 == cl_.frames;
    // Screenshots and measured frames are drawn at the requested size, never at a budget's scale.
    const bool fullSize =
        input_.screenshot || measurement_.active() || (lastFrame && (!cl_.screenshot.empty() || !cl_.measure.empty()));
    budget_.setAllowed(!cl_.headless, gl::caps().softwareRenderer, fullSize);
    gl::resetDrawCalls();
    FrameInfo fi = beginFrame(frame, dt, lastFrame);
    if (Exit e = drawFrame(fi)) return e;
    drawCalls_ = gl::drawCalls();
    budget_.end(context_->framebuffer(), width_, height_);
    fi.framebuffer = context_->framebuffer();
    reference_.frame(input_.referencePicture, params_, presets_, info_.name, fi.framebuffer, width_, height_);  // F4
    watchExercises(fi, frame);
    lesson_.timers.collect();
    if (uiVisible_ && input_.uiHidden < 2) {
      // Headless, the last frame's UI is laid out once without drawing first: ImGui sizes an
      // auto-fit window (the header) from the frame before, so a header whose lines changed came
      // out a line short in the screenshot and --ui-layout.
      if (cl_.headless && lastFrame) drawUi(fi, dt, false);
      drawUi(fi, dt, true);
    }
    if (Exit e = writeOutputs(fi, lastFrame)) return e;
    context_->present();
    // Frame time includes present (llvmpipe works there); the browser's is the time since the last frame.
    const double frameMs = context_->drawsAfterFrame() ? sinceLast_ : (nowSeconds() - start) * 1000.0;
    frameMsAvg_ = frameMsAvg_ == 0 ? frameMs : 0.9 * frameMsAvg_ + 0.1 * frameMs;
    budget_.record(frameMs);
    if (bench_.isOpen()) bench_.frame(frame, frameMs, drawCalls_, budget_.scale(), lesson_.timers);
    return std::nullopt;
  }

  // --keys: what a step did, on stderr (tests read it): the camera, and the parameter its key drives.
  void reportScriptedKey(const std::string& step) const {
    if (!step.empty()) std::cerr << scriptedKeyReport(info_.name, step, lesson_.camera, input_.fly, params_) << '\n';
  }

  // Mouse onto the camera (or the A/B divider), keys onto the framework and the hotkeys. Headless,
  // --keys and --drop feed the same Input (no mouse).
  void handleInput(float dt) {
    GLFWwindow* w = context_->window();
    float divider = ab_.divider();
    if (w) applyMouse(w, input_, ui_.wantsMouse(), lesson_.camera, ab_.enabled() ? &divider : nullptr);
    const auto held = [&](int key) { return (w && glfwGetKey(w, key) == GLFW_PRESS) || keys_.held(key); };
    if (!ui_.wantsKeyboard()) applyFlyKeys(held, input_, lesson_.camera, dt);
    if (input_.resetCamera) {
      lesson_.camera = homeCamera_;
      input_.resetCamera = false;
      status_ = "camera reset";
    }
    if (divider != ab_.divider()) ab_.setDivider(divider);
    if (!input_.dropped.empty()) {
      const std::uint64_t generation = currentModelGeneration();
      status_ = loadDroppedModel(input_.dropped.back(), params_, info_.name);
      if (currentModelGeneration() != generation) aimAtModel();
    }
    input_.dropped.clear();
    if (input_.uiScaleSteps != 0) {
      ui_.setScale(ui_.scale() * std::pow(1.15f, float(input_.uiScaleSteps)));
      input_.uiScaleSteps = 0;
    }
    if (input_.toggleFullscreen) {
      context_->setFullscreen(!context_->fullscreen());
      input_.toggleFullscreen = false;
    }
    helpOpen_ = input_.help;
    statsOpen_ = input_.stats;
    panelOpen_ = input_.panel;
    if (!ui_.wantsKeyboard()) {
      for (int key : input_.pressed) {
        if (!isReloadKey(key)) {
          try {
            applyHotkey(params_, keyName(key));
          } catch (const ParamError& e) { status_ = e.what(); }
          continue;
        }
        for (gl::Program* p : gl::livePrograms()) p->build();
        if (!initError_.empty()) tryInit();
        status_ = "reloaded shaders";
      }
    }
    input_.pressed.clear();
  }

  // --measure FILE: the last frame; a FILE with %d: every frame, into FILE with %d its index (a
  // stress run measures many configurations in one process). "" when this frame is not measured.
  std::string measurePath(int frame, bool lastFrame) const {
    const auto at = cl_.measure.find("%d");
    if (at == std::string::npos) return lastFrame ? cl_.measure : "";
    return cl_.measure.substr(0, at) + std::to_string(frame) + cl_.measure.substr(at + 2);
  }

  // The replayed pose, then the viewer's camera as the frame's.
  FrameInfo beginFrame(int frame, double dt, bool lastFrame) {
    if (!measurePath(frame, lastFrame).empty()) {
      measurement_.requestFullResolution();
      ab_.requestFullResolution();
    }
    if (!replay_.empty()) {
      const double t0 = replay_.keys().front().time;
      const double t = t0 + replaySpan_.timeAt(replay_.duration(), frame, cl_.frames, time_);
      const measure::PathKey key = replay_.sample(t);
      lesson_.camera.lookFrom(key.cameraPosition, key.cameraTarget);
      lesson_.applyPathLight(key.lightPosition, key.lightDirection);
    }
    // The frame budget may hand the lesson a smaller target; the projection keeps the window's aspect.
    int w = width_, h = height_;
    const unsigned fbo = budget_.begin(context_->framebuffer(), width_, height_, w, h);
    FrameInfo fi{frame, time_, dt, w, h, budget_.scale(), fbo};
    fi.view = lesson_.camera.view();
    fi.projection = lesson_.camera.projection(float(width_) / float(height_));
    fi.eye = lesson_.camera.position();
    lesson_.timers.setFrame(frame);
    lesson_.debug.clear();
    lesson_.insets.clear();
    lesson_.legends.clear();
    return fi;
  }

  // The lesson (through the measurement target when measuring), then the A/B half and the god
  // view. A throw headless ends the run; a window keeps running and shows it until a reload.
  Exit drawFrame(FrameInfo& fi) {
    const unsigned frameFbo = fi.framebuffer;
    const bool ready = initError_.empty() && gl::programsReady();
    glBindFramebuffer(GL_FRAMEBUFFER, fi.framebuffer);
    glViewport(0, 0, fi.width, fi.height);
    if (ready) {
      try {
        drawLessonAndViews(fi, frameFbo);
      } catch (const std::exception& e) {
        if (cl_.headless) {
          std::cerr << info_.name << ": " << e.what() << '\n';
          return 1;
        }
        initError_ = e.what();
      }
      // Programs built on first use (specialised variants) report here: headless, a broken or
      // missing shader ends the run as it does at init.
      if (cl_.headless && !gl::shaderErrors(/*requiredOnly=*/true).empty()) {
        for (const auto& e : gl::shaderErrors(true)) std::cerr << info_.name << ": " << e << '\n';
        return 1;
      }
    }
    if (!ready || !initError_.empty()) {  // nothing valid to draw with: a dark red frame
      glClearColor(0.25f, 0.05f, 0.05f, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }
    return std::nullopt;
  }

  void drawLessonAndViews(FrameInfo& fi, unsigned frameFbo) {
    lesson_.update(fi);
    fi.framebuffer = measurement_.begin(frameFbo, fi);
    fi.measureLight = measurement_.measuredLight();
    glBindFramebuffer(GL_FRAMEBUFFER, fi.framebuffer);
    glViewport(0, 0, fi.width, fi.height);
    lesson_.render(fi);
    // Re-measure when anything the picture depends on moved: the camera or any parameter.
    const glm::mat4 view = lesson_.camera.view();
    const bool viewChanged = view != lastView_ || params_.revision() != lastRevision_;
    lastView_ = view;
    lastRevision_ = params_.revision();
    measurement_.end(lesson_.measureSource(), frameFbo, viewChanged,
                     [&](const FrameInfo& f) { return lesson_.redrawLitUntimed(f); });
    fi.framebuffer = frameFbo;
    if (ab_.enabled()) {
      ab_.draw(fi, params_, presets_, lesson_, info_.measurable ? &measurement_ : nullptr,
               [&](const FrameInfo& b) { lesson_.render(b); });
      lastRevision_ = params_.revision();  // switching to B and back is not a change
      glViewport(0, 0, fi.width, fi.height);
    }
    if (godView_.enabled()) godView_.show(fi, lesson_, info_.measurable);
  }

  // The UI; after one H the panels are hidden, not what explains the picture: the A/B labels, the
  // legends, the lesson's own labels (gui() with panelsHidden), the stub banner.
  void drawUi(const FrameInfo& fi, double dt, bool draw) {
    glBindFramebuffer(GL_FRAMEBUFFER, fi.framebuffer);
    glViewport(0, 0, width_, height_);
    ui_.newFrame(dt, width_, height_);
    const bool panels = input_.uiHidden == 0;
    lesson_.panelsHidden = !panels;
    std::vector<Counter> shown = lesson_.counters;
    shown.push_back({"draw calls", std::to_string(drawCalls_)});
    for (auto& [name, value] : measurement_.summary()) shown.push_back({name, value});
    std::vector<std::string> errors = gl::shaderErrors();
    if (!initError_.empty()) errors.insert(errors.begin(), initError_);
    std::vector<Legend> legends = lesson_.legends;
    if (const auto l = measurement_.legend()) legends.push_back(*l);
    ui_.reserve(lesson_.insets, height_);  // first: the legend, the header and the panels stop above the insets
    const Measurement* measured = info_.measurable ? &measurement_ : nullptr;
    if (ab_.enabled())  // then: the legends and the exercises stay above the labels
      ui_.splitLabels(ab_.divider(), ab_.labelA(measured, keyFigures(info_, lesson_.counters, false)),
                      ab_.labelB(info_.keyFigures));
    ui_.legends(legends);  // bottom right, above the labels and the insets there; the panel stops above it
    if (panels) drawPanels(shown, errors);
    lesson_.gui();
    ui_.banner(reference_.label().empty() ? banner_ : reference_.label());
    if (panels) ui_.help(info_, params_, &helpOpen_);
    input_.help = helpOpen_;
    ui_.render(draw);
  }

  void drawPanels(const std::vector<Counter>& shown, const std::vector<std::string>& errors) {
    if (!lesson_.exercises.empty()) rerunExercises_ = ui_.exercisesPanel(lesson_.exercises) || rerunExercises_;
    const Ui::HeaderData header{&info_,
                                gl::caps().summary(),
                                frameMsAvg_,
                                &lesson_.timers.passes(),
                                &shown,
                                keyFigures(info_, shown),
                                errors,
                                status_,
                                gl::caps().softwareRenderer,
                                budget_.label()};
    ui_.header(header);
    ui_.stats(header, &statsOpen_);
    input_.stats = statsOpen_;
    ui_.paramPanel(params_, presets_, info_.name, status_, &panelOpen_);
    input_.panel = panelOpen_;
  }

  // F12, --measure and --screenshot on the last frame, and the --record path.
  Exit writeOutputs(const FrameInfo& fi, bool lastFrame) {
    if (input_.screenshot) {
      const std::string path = screenshotName(info_);
      saveScreenshot(path, fi.framebuffer, width_, height_);
      status_ = "saved " + path;
      input_.screenshot = false;
    }
    if (!gl::caps().khrDebug) gl::checkErrors("end of frame");
    try {
      if (const std::string path = measurePath(fi.index, lastFrame); !path.empty()) {
        const SplitFigures b{ab_.enabled() ? ab_.presetB() : "", ab_.measurementB().result()};
        std::vector<Counter> counters = lesson_.counters;
        counters.push_back({"draw calls", std::to_string(drawCalls_)});
        writeMeasurementJson(path, info_, measurement_.result(), counters, lesson_.timers,
                             ab_.enabled() ? &b : nullptr);
      }
      if (lastFrame && !cl_.screenshot.empty()) saveScreenshot(cl_.screenshot, fi.framebuffer, width_, height_);
      if (lastFrame && !cl_.uiLayout.empty()) {
        const bool drawn = uiVisible_ && input_.uiHidden < 2;  // hidden (H twice): no rectangle of an older frame
        writeUiLayout(cl_.uiLayout, width_, height_, drawn ? ui_.layout() : std::vector<Ui::Rect>{});
      }
    } catch (const std::exception& e) {
      std::cerr << info_.name << ": " << e.what() << '\n';
      return 1;
    }
    if (!cl_.record.empty()) recordKey();
    return std::nullopt;
  }

  void recordKey() {
    const MeasureSource source = lesson_.measureSource();
    const int which = std::max(0, measurement_.measuredLight());
    measure::PathKey key;
    key.time = time_;
    key.cameraPosition = lesson_.camera.position();
    key.cameraTarget = lesson_.camera.target;
    if (which < int(source.lights.size())) {
      key.lightPosition = source.lights[std::size_t(which)].position;
      key.lightDirection = source.lights[std::size_t(which)].direction;
    }
    recording_.add(key);
  }

  // ==== 4. teardown: the recorded path, the last timings, the GL verdict ========================
  int teardown() {
    if (!cl_.record.empty()) {
      try {
        const std::filesystem::path p(cl_.record);
        if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
        recording_.save(cl_.record);
        std::cout << info_.name << ": recorded " << recording_.keys().size() << " keys to " << cl_.record << '\n';
      } catch (const std::exception& e) {
        std::cerr << info_.name << ": --record: " << e.what() << '\n';
        return 1;
      }
    }
    // Let outstanding timer queries resolve so the benchmark has every frame.
    glFinish();
    lesson_.timers.collect();
    int status = 0;
    try {
      if (bench_.isOpen()) bench_.flush(lesson_.timers), bench_.close();
    } catch (const std::exception& e) {  // a full disk: the CSV is incomplete
      std::cerr << info_.name << ": " << e.what() << '\n';
      status = 1;
    }
    gl::checkErrors("exit");
    const int glErrors = gl::errorCount();
    if (uiVisible_) ui_.shutdown();
    uninstallInputCallbacks();
    if (glErrors > 0) {
      std::cerr << info_.name << ": " << glErrors << " OpenGL error(s); first: " << gl::errorMessages().front() << '\n';
      if (cl_.strictGl) return 3;
    }
    return status;
  }

  // Declaration order matters: members are destroyed bottom-up, so everything holding GL objects
  // (the lesson, the measurement, the views) goes before the context.
  std::unique_ptr<Context> context_;
  std::unique_ptr<Lesson> owned_;
  Lesson& lesson_;
  const LessonInfo info_;
  CommandLine cl_;
  ParamRegistry params_;
  PresetFile presets_;
  Measurement measurement_;
  ReferencePicture reference_;
  GodView godView_;
  AbSplit ab_;
  FrameBudget budget_;
  Ui ui_;
  Input input_;
  KeyScript keys_;  // --keys
  BenchLog bench_;
  measure::CameraLightPath recording_, replay_;
  measure::ReplaySpec replaySpan_;
  bool uiVisible_ = false, helpOpen_ = false, statsOpen_ = false, panelOpen_ = false, bannerPrinted_ = false,
       rerunExercises_ = false;
  OrbitCamera homeCamera_;  // the pose after the preset and --set: Home returns to it
  std::string initError_, status_, banner_;
  int width_ = 0, height_ = 0, drawCalls_ = 0;
  glm::mat4 lastView_{0.0f};
  unsigned lastRevision_ = ~0u;
  double frameMsAvg_ = 0, time_ = 0, last_ = 0, sinceLast_ = 0;  // sinceLast_: ms since the frame before
};

}  // namespace

// The runner lives as long as its frames: in a browser the page calls them after this returns.
int runLesson(const std::function<std::unique_ptr<Lesson>()>& make, int argc, char** argv) {
  auto runner = std::make_shared<Runner>(make());
  if (Exit e = runner->start(argc, argv)) return runFrames([e](int) { return e; });
  return runFrames([runner](int frame) mutable {
    Exit e = runner->step(frame);
    if (e) runner.reset();  // the context and the lesson's GL objects go now, in order
    return e;
  });
}

}  // namespace shadowlab
