// shadowlab: the course launcher.
//   shadowlab              with a display: a window listing every lesson; Start runs the chosen one
//                          without one: the tour (below)
//   shadowlab --tour DIR   every lesson rendered headless at its defaults and at each preset into
//                          DIR (one PNG each) plus DIR/index.html with the lesson titles
//   shadowlab --list       per lesson: its presets, README, slide deck and exercise status
// In the window each lesson has a preset to start from, Start, README and Slides (opened with
// the desktop's viewer) and its exercise status (the public cases, `lesson --exercises`, run in the background).
// Lessons describe themselves (`lesson --info`, `--list-presets`), so nothing here is duplicated.
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>
#include <nlohmann/json.hpp>

#include <array>
#include <atomic>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "app/context.hpp"
#include "core/image.hpp"
#include "core/paths.hpp"
#include "core/process.hpp"
#include "gl/gl.hpp"
#include "gl/texture.hpp"
#include "lesson_list.hpp"

namespace fs = std::filesystem;

namespace {

struct LessonEntry {
  std::string program;  // full path
  std::string number, name, title, summary;
  int difficulty = 1;
  int minutes = 0;            // time in class
  std::string prerequisites;  // "02, 03", or "none"
  std::vector<std::string> presets;
  std::string readme, deck;  // lessons/NN_name/README.md; the deck NN_name.html (make slides)
  std::string exercises;     // `lesson --exercises`: one line per exercise, or why there is none
  std::string exerciseSummary = "exercises: checking...";
  int preset = 0;  // the window's choice: 0 = defaults, else presets[preset - 1]
};

// A lesson's output (`--info`, `--list-presets`, `--exercises`, with stderr when asked), through a
// temporary file: no shell, so no quoting that differs between sh and cmd.exe.
std::string capture(const std::vector<std::string>& args, int& status, bool withStderr = false) {
  // Unique to this process (two launchers run at once in the tests) and to this call (threads).
  static const std::string token = std::to_string(std::random_device{}()) + std::to_string(std::random_device{}());
  static std::atomic<int> serial{0};
  const fs::path file =
      fs::temp_directory_path() / ("shadowlab_launcher_" + token + "_" + std::to_string(serial++) + ".txt");
  shadowlab::ProcessOptions options;
  options.stdoutPath = file.string();
  if (!withStderr) options.stderrPath = file.string() + ".err";
  status = shadowlab::runProcess(args, options);
  std::ifstream in(file);
  std::stringstream out;
  out << in.rdbuf();
  std::error_code ignored;
  fs::remove(file, ignored);
  fs::remove(file.string() + ".err", ignored);
  return out.str();
}

std::string sourceRootPath() { return shadowlab::sourceRoot(); }

// "3 of 5 pass, 2 stubs" from the lines of `lesson --exercises` ("01.1 passing  title (4 of 4 ...").
std::string summariseExercises(const std::string& report) {
  int total = 0, passing = 0, stubs = 0, failing = 0;
  std::istringstream lines(report);
  std::string line;
  while (std::getline(lines, line)) {
    const auto gap = line.find(' ');
    // State lines start with the exercise's id; the lines under them say where to write it, the
    // last ones how to grade.
    if (line.empty() || !std::isdigit(static_cast<unsigned char>(line[0])) || gap == std::string::npos) continue;
    const std::string state = line.substr(line.find_first_not_of(' ', gap));
    ++total;
    if (state.rfind("passing", 0) == 0) ++passing;
    else if (state.rfind("stub", 0) == 0) ++stubs;
    else if (state.rfind("failing", 0) == 0) ++failing;
  }
  if (total == 0) return "exercises: none in this lesson";
  std::string s = "exercises: " + std::to_string(passing) + " of " + std::to_string(total) + " pass";
  if (stubs) s += ", " + std::to_string(stubs) + " still stubs";
  if (failing) s += ", " + std::to_string(failing) + " failing";
  return s;
}

// The public cases of the student's exercises.cpp, as the lesson reports them.
void checkExercises(LessonEntry& e) {
  int status = 0;
  const std::string out = capture({e.program, "--exercises"}, status, true);
  if (status != 0) {
    e.exercises = out;
    e.exerciseSummary = "exercises: unknown (--exercises exited " + std::to_string(status) + ")";
    return;
  }
  e.exercises = out;
  e.exerciseSummary =
      out.find("no exercises") != std::string::npos ? "exercises: none in this lesson" : summariseExercises(out);
}

std::vector<LessonEntry> discoverLessons(const fs::path& binDir) {
  std::vector<LessonEntry> lessons;
  for (const char* name : kLessonPrograms) {
    if (!*name) continue;
    LessonEntry e;
    e.program = (binDir / name).string();
    int status = 0;
    const std::string info = capture({e.program, "--info"}, status);
    if (status != 0) {
      std::cerr << "shadowlab: " << e.program << " --info failed (exit " << status << ")\n";
      continue;
    }
    const auto j = nlohmann::json::parse(info);
    e.number = j.at("number");
    e.name = j.at("name");
    e.title = j.at("title");
    e.summary = j.at("summary");
    e.difficulty = j.at("difficulty");
    e.minutes = j.at("minutes");
    for (const auto& p : j.at("prerequisites"))
      e.prerequisites += (e.prerequisites.empty() ? "" : ", ") + p.get<std::string>();
    if (e.prerequisites.empty()) e.prerequisites = "none";
    std::string line;
    std::istringstream presets(capture({e.program, "--list-presets"}, status));
    while (std::getline(presets, line))
      if (!line.empty()) e.presets.push_back(line);
    e.readme = sourceRootPath() + "/lessons/" + e.name + "/README.md";
    // `make slides` writes out/slides; the test suite's build writes <build>/slides.
    e.deck = sourceRootPath() + "/out/slides/" + e.name + ".html";
    const fs::path built = binDir.parent_path() / "slides" / (e.name + ".html");
    if (!fs::exists(e.deck) && fs::exists(built)) e.deck = built.string();
    lessons.push_back(std::move(e));
  }
  return lessons;
}

int runProgram(const std::vector<std::string>& args, bool wait) {
  shadowlab::ProcessOptions options;
  options.wait = wait;
  return shadowlab::runProcess(args, options);
}

// Opens a README or a deck with the desktop's viewer; the message says what happened.
std::string openDocument(const std::string& path, const std::string& missingHint) {
  if (!fs::exists(path)) return path + " does not exist" + missingHint;
  if (!shadowlab::openWithDesktop(path)) return "no desktop viewer here: open " + path + " yourself";
  return "opened " + path;
}

int list(std::vector<LessonEntry>& lessons) {
  for (auto& l : lessons) {
    checkExercises(l);
    std::cout << l.number << "  " << l.title << "  (" << l.name << ", difficulty " << l.difficulty << ", " << l.minutes
              << " minutes in class, " << (l.prerequisites == "none" ? "no prerequisites" : "after " + l.prerequisites)
              << ")\n";
    std::string presets;
    for (const auto& p : l.presets) presets += (presets.empty() ? "" : ", ") + p;
    std::cout << "    presets: " << (presets.empty() ? "none" : presets) << "\n"
              << "    README: " << l.readme << (fs::exists(l.readme) ? "" : " (missing)") << "\n"
              << "    slides: " << l.deck << (fs::exists(l.deck) ? "" : " (not built: make slides)") << "\n"
              << "    " << l.exerciseSummary << "\n";
  }
  return 0;
}

std::string htmlEscape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

int tour(const std::vector<LessonEntry>& lessons, const fs::path& dir) {
  fs::create_directories(dir);
  std::ofstream html(dir / "index.html");
  html << "<!doctype html><html><head><meta charset=\"utf-8\"><title>shadowlab tour</title><style>"
          "body{font-family:sans-serif;background:#111;color:#ddd;margin:2em}figure{display:inline-block;margin:.5em}"
          "img{width:384px;border:1px solid #444}figcaption{font-size:.9em;color:#aaa}</style></head><body>"
          "<h1>shadowlab: every lesson at its defaults and presets</h1>\n";
  int failures = 0, images = 0;
  for (const auto& l : lessons) {
    html << "<h2>" << htmlEscape(l.number + " " + l.title) << "</h2><p>" << htmlEscape(l.summary) << "</p><p>"
         << l.minutes << " minutes in class; after lessons: " << htmlEscape(l.prerequisites) << "</p>\n";
    std::vector<std::string> shots = {""};
    shots.insert(shots.end(), l.presets.begin(), l.presets.end());
    for (const auto& preset : shots) {
      const std::string file = l.name + "_" + (preset.empty() ? "defaults" : preset) + ".png";
      std::vector<std::string> args = {l.program, "--headless", "--frames", "3", "--screenshot", (dir / file).string()};
      if (!preset.empty()) args.insert(args.end(), {"--preset", preset});
      std::cout << "  " << l.name << " " << (preset.empty() ? "(defaults)" : preset) << std::flush;
      const int rc = runProgram(args, true);
      std::cout << (rc == 0 ? "  ok\n" : "  FAILED (exit " + std::to_string(rc) + ")\n");
      if (rc != 0) {
        ++failures;
        continue;
      }
      ++images;
      html << "<figure><img src=\"" << file << "\" alt=\"" << htmlEscape(file) << "\"><figcaption>"
           << htmlEscape(preset.empty() ? "defaults" : "preset " + preset) << "</figcaption></figure>\n";
    }
  }
  html << "</body></html>\n";
  std::cout << "shadowlab: tour of " << lessons.size() << " lesson(s), " << images
            << " image(s): " << fs::absolute(dir / "index.html").string() << '\n';
  return failures == 0 ? 0 : 1;
}

// One lesson in the window: number, title, summary and exercise status, difficulty, the preset to
// start from, Start / README / Slides.
void lessonRow(LessonEntry& l, std::string& status, bool exercisesKnown) {
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(l.number.c_str());
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(l.title.c_str());
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("%s", l.summary.c_str());
  ImGui::TextUnformatted(exercisesKnown ? l.exerciseSummary.c_str() : "exercises: checking...");
  ImGui::PopStyleColor();
  if (exercisesKnown && !l.exercises.empty() && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", l.exercises.c_str());
  ImGui::TableNextColumn();
  ImGui::Text("%s", std::string(std::size_t(l.difficulty), '*').c_str());
  ImGui::TextDisabled("%d min", l.minutes);  // in class
  if (l.prerequisites != "none") ImGui::TextDisabled("after %s", l.prerequisites.c_str());
  ImGui::TableNextColumn();
  ImGui::PushID(l.name.c_str());
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 10);
  const char* current = l.preset == 0 ? "defaults" : l.presets[std::size_t(l.preset - 1)].c_str();
  if (ImGui::BeginCombo("##preset", current)) {
    for (int i = 0; i <= int(l.presets.size()); ++i)
      if (ImGui::Selectable(i == 0 ? "defaults" : l.presets[std::size_t(i - 1)].c_str(), i == l.preset)) l.preset = i;
    ImGui::EndCombo();
  }
  ImGui::TableNextColumn();
  if (ImGui::Button("Start")) {
    std::vector<std::string> args = {l.program};
    if (l.preset > 0) args.insert(args.end(), {"--preset", l.presets[std::size_t(l.preset - 1)]});
    status = runProgram(args, false) == 0 ? "started " + l.name + (l.preset > 0 ? " --preset " + args.back() : "")
                                          : "could not start " + l.program;
  }
  ImGui::SameLine();
  if (ImGui::Button("README")) status = openDocument(l.readme, "");
  ImGui::SameLine();
  if (ImGui::Button("Slides")) status = openDocument(l.deck, ": build the decks with `make slides`");
  ImGui::PopID();
}

// `frames` > 0 (tests): close after that many frames, saving the last one to `screenshot`.
int launcherWindow(std::vector<LessonEntry>& lessons, int frames, const std::string& screenshot) {
  // The exercise states take a lesson run each: in the background, the window shows "checking".
  std::atomic<bool> exercisesDone{false};
  std::thread checker([&] {
    for (auto& l : lessons) checkExercises(l);
    exercisesDone = true;
  });
  auto context = shadowlab::createWindowContext({960, 640, "shadowlab: lessons", false, false});
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui::StyleColorsDark();
  const float scale = std::max(1.0f, context->contentScale());
  ImGui::GetStyle().ScaleAllSizes(scale);
  ImGui::GetIO().FontGlobalScale = scale;
  ImGui_ImplGlfw_InitForOpenGL(context->window(), true);
  ImGui_ImplOpenGL3_Init("#version 410 core");
  std::string status = "Choose a lesson. Each opens in its own window; F1 there shows its help.";
  for (int frame = 0; !context->shouldClose() && (frames <= 0 || frame < frames); ++frame) {
    context->pollEvents();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImGui::GetIO().DisplaySize);
    ImGui::Begin("shadowlab", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove);
    ImGui::Text("shadowlab: real-time shadows and texture filtering");
    ImGui::Separator();
    // The table scrolls (nine lessons do not fit); the status line stays below it.
    const float footer = ImGui::GetFrameHeightWithSpacing() + ImGui::GetStyle().ItemSpacing.y;
    if (ImGui::BeginTable("lessons", 5,
                          ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_ScrollY,
                          ImVec2(0, -footer))) {
      ImGui::TableSetupScrollFreeze(0, 1);
      ImGui::TableSetupColumn("#", ImGuiTableColumnFlags_WidthFixed);
      ImGui::TableSetupColumn("lesson");
      ImGui::TableSetupColumn("level, time", ImGuiTableColumnFlags_WidthFixed);
      ImGui::TableSetupColumn("start from", ImGuiTableColumnFlags_WidthFixed);
      ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed);
      ImGui::TableHeadersRow();
      for (auto& l : lessons) lessonRow(l, status, exercisesDone.load());
      ImGui::EndTable();
    }
    ImGui::Separator();
    ImGui::TextDisabled("%s", status.c_str());
    ImGui::End();
    ImGui::Render();
    glViewport(0, 0, context->width(), context->height());
    glClearColor(0.08f, 0.08f, 0.1f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    if (frames > 0 && frame + 1 == frames && !screenshot.empty())
      shadowlab::savePng(screenshot, shadowlab::gl::readPixels(0, context->width(), context->height()));
    context->present();
    shadowlab::reapFinishedProcesses();  // lessons that were closed
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  checker.join();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const fs::path binDir = fs::canonical("/proc/self/exe").parent_path();
  std::string tourDir, screenshot;
  int frames = 0;
  bool listOnly = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--tour" && i + 1 < argc) tourDir = argv[++i];
    else if (a == "--list") listOnly = true;
    else if (a == "--frames" && i + 1 < argc) {
      const std::string n = argv[++i];
      char* end = nullptr;
      const long v = std::strtol(n.c_str(), &end, 10);
      if (end == n.c_str() || *end != '\0' || v < 1 || v > 100000000) {
        std::cerr << "shadowlab: --frames: '" << n << "' is not a whole number in [1, 100000000]\n";
        return 2;
      }
      frames = int(v);
    } else if (a == "--screenshot" && i + 1 < argc) screenshot = argv[++i];
    else if (a == "--help") {
      std::cout << "usage: shadowlab [--tour DIR] [--list] [--frames N] [--screenshot FILE]\n"
                   "  with a display: the lesson launcher\n"
                   "  without one, or with --tour: render every lesson and preset into DIR (default out/tour)\n"
                   "  --tour DIR         render the tour into DIR\n"
                   "  --list             per lesson: presets, README, slide deck, exercise status\n"
                   "  --frames N         the launcher window closes after N frames (tests)\n"
                   "  --screenshot FILE  with --frames: the launcher's last frame as PNG\n"
                   "  --help             this text\n";
      return 0;
    } else {
      std::cerr << "shadowlab: unknown argument '" << a
                << "'; valid: --tour DIR, --list, --frames N, --screenshot FILE, --help\n";
      return 2;
    }
  }
  auto lessons = discoverLessons(binDir);
  if (lessons.empty()) {
    std::cerr << "shadowlab: no lesson programs found beside " << binDir << '\n';
    return 1;
  }
  if (listOnly) return list(lessons);
  if (!tourDir.empty() || !shadowlab::displayAvailable()) {
    if (tourDir.empty()) {
      tourDir = "out/tour";
      std::cout << "shadowlab: no display (DISPLAY / WAYLAND_DISPLAY unset): rendering the tour headless\n";
    }
    return tour(lessons, tourDir);
  }
  try {
    return launcherWindow(lessons, frames, screenshot);
  } catch (const std::exception& e) {
    std::cerr << "shadowlab: " << e.what() << "\n";
    return 1;
  }
}
