// frame_bench: every lesson's frame time on this machine, against its floor. `make bench` runs it.
//
//   frame_bench --bin build/default/bin --out out/bench [--lessons 01_lighting,03_shadow_quality]
//               [--size 1280x720] [--repeat 3] [--frames 8] [--window] [--quick] [--default-only]
//               [--markdown docs/benchmarks.md]
//
// Per lesson: the default view and its heaviest preset (the slowest of all its presets in a quick
// pass at a quarter of the pixels), each at --size, headless: the median frame ms of frames 2 and
// on (the first frames compile and upload), and the floor, the same frame with every fragment
// shader replaced by a trivial one (SHADOWLAB_FLOOR_SHADER=1). Runs are interleaved and repeated;
// the medians and the ratio to the floor are reported. With --window (a display, or under
// xvfb-run) the default view also runs in a window with the frame budget on: the frames per
// second a student sees and the render scale the budget settled on. Writes DIR/frames.csv and
// DIR/frames.html; a progress line on the terminal. --markdown FILE also writes the table as
// Markdown with the machine (CPU, threads, system, OpenGL renderer) and the date it ran on: the
// README's one benchmark table, docs/benchmarks.md, is this file.
#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "app/context.hpp"
#include "core/process.hpp"
#include "gl/caps.hpp"

namespace fs = std::filesystem;
using namespace shadowlab;

namespace {

struct Options {
  std::string bin, out, size = "1280x720", markdown;
  std::vector<std::string> lessons;
  int repeat = 3, frames = 8;
  bool window = false, quick = false, heaviest = true;
};

constexpr const char* kUsage =
    "usage: frame_bench --bin DIR --out DIR [--lessons a,b] [--size WxH] [--repeat N] [--frames N] [--window] "
    "[--quick] [--default-only] [--markdown FILE]\n";

[[noreturn]] void usage(const std::string& error) {
  std::cerr << "frame_bench: " << error << "\n" << kUsage;
  std::exit(2);
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage(a + " needs a value");
      return argv[++i];
    };
    auto number = [&](int lo) {
      const std::string v = value();
      char* end = nullptr;
      const long n = std::strtol(v.c_str(), &end, 10);
      if (end == v.c_str() || *end || n < lo) usage(a + ": '" + v + "' is not a whole number >= " + std::to_string(lo));
      return int(n);
    };
    if (a == "--help" || a == "-h") {
      std::cout << kUsage;
      std::exit(0);
    } else if (a == "--bin") o.bin = value();
    else if (a == "--out") o.out = value();
    else if (a == "--size") o.size = value();
    else if (a == "--repeat") o.repeat = number(1);
    else if (a == "--frames") o.frames = number(3);
    else if (a == "--window") o.window = true;
    else if (a == "--quick") o.quick = true;
    else if (a == "--default-only") o.heaviest = false;
    else if (a == "--markdown") o.markdown = value();
    else if (a == "--lessons") {
      std::istringstream in(value());
      for (std::string s; std::getline(in, s, ',');)
        if (!s.empty()) o.lessons.push_back(s);
    } else
      usage("unknown argument '" + a +
            "'; valid: --bin --out --lessons --size --repeat --frames --window --quick --default-only --markdown");
  }
  if (o.bin.empty() || o.out.empty()) usage("--bin and --out are required");
  std::error_code error;
  if (!fs::is_directory(o.bin, error)) usage("--bin " + o.bin + ": not a directory");
  std::vector<std::string> found;  // the lessons built in --bin
  for (const auto& e : fs::directory_iterator(o.bin)) {
    const std::string name = e.path().filename().string();
    if (name.rfind("lesson_", 0) == 0 && name != "lesson_check") found.push_back(name.substr(7));
  }
  std::sort(found.begin(), found.end());
  if (found.empty()) usage("--bin " + o.bin + ": no lesson_* programs there (build first)");
  if (o.lessons.empty()) o.lessons = found;
  for (const auto& l : o.lessons)
    if (!std::binary_search(found.begin(), found.end(), l)) {
      std::string valid;
      for (const auto& f : found) valid += (valid.empty() ? "" : ", ") + f;
      usage("--lessons: no lesson '" + l + "' in " + o.bin + "; valid: " + valid);
    }
  std::sort(o.lessons.begin(), o.lessons.end());
  if (o.quick) {
    o.repeat = 1;
    o.frames = 4;
  }
  return o;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

// What one run's --bench CSV says: the median frame ms of frames >= `from`, the last frame's draw
// calls and render scale.
struct Frames {
  double ms = 0;
  int drawCalls = 0;
  double scale = 1;
  bool ok = false;
};

Frames readBench(const std::string& csv, int from) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  std::map<int, double> ms;
  Frames f;
  while (std::getline(in, line)) {
    std::vector<std::string> c;
    std::stringstream row(line);
    for (std::string v; std::getline(row, v, ',');) c.push_back(v);
    if (c.size() < 7) continue;
    const int frame = std::stoi(c[0]);
    ms[frame] = std::stod(c[4]);
    f.drawCalls = std::stoi(c[5]);
    f.scale = std::stod(c[6]);
  }
  std::vector<double> v;
  for (const auto& [frame, t] : ms)
    if (frame >= from) v.push_back(t);
  f.ms = median(v);
  f.ok = !v.empty();
  return f;
}

struct Runner {
  const Options& o;
  int done = 0, total = 0;
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();

  void progress(const std::string& what) {
    ++done;
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double eta = done > 0 ? s / done * std::max(0, total - done) : 0;
    std::cerr << "\rframe_bench: " << done << "/" << total << " (eta " << int(eta) << " s) " << what << "          "
              << std::flush;
  }

  std::vector<std::string> failures;  // runs that exited non-zero or wrote no frames

  // One run of `lesson` with `args`; its frames from frame 2 on.
  Frames run(const std::string& lesson, const std::vector<std::string>& args, bool floor, bool window,
             const std::string& size, int frames) {
    const std::string csv = o.out + "/frames_run.csv";
    std::vector<std::string> cmd = {
        o.bin + "/lesson_" + lesson, "--frames", std::to_string(frames), "--size", size, "--bench", csv};
    if (!window) cmd.push_back("--headless");
    cmd.insert(cmd.end(), args.begin(), args.end());
    ProcessOptions po;
    po.stdoutPath = o.out + "/frames_run.log";
    if (floor) po.setEnv.push_back("SHADOWLAB_FLOOR_SHADER=1");
    fs::remove(csv);
    const int rc = runProcess(cmd, po);
    const Frames f = rc == 0 ? readBench(csv, window ? frames / 2 : 2) : Frames{};
    if (!f.ok) {
      std::string line;
      for (const auto& c : cmd) line += (line.empty() ? "" : " ") + c;
      failures.push_back((floor ? "SHADOWLAB_FLOOR_SHADER=1 " : "") + line + ": " +
                         (rc != 0 ? "exit " + std::to_string(rc) : std::string("no frames in the CSV")) + " (log " +
                         po.stdoutPath + ")");
    }
    return f;
  }

  std::vector<std::string> presets(const std::string& lesson) {
    const std::string list = o.out + "/frames_presets.txt";
    runProcess({o.bin + "/lesson_" + lesson, "--list-presets"}, {list});
    std::ifstream in(list);
    std::vector<std::string> names;
    for (std::string n; std::getline(in, n);)
      if (!n.empty() && n != "default") names.push_back(n);
    return names;
  }
};

struct Row {
  std::string lesson, preset;
  double ms = 0, floorMs = 0, windowFps = 0, windowScale = 1;
  int drawCalls = 0;
};

std::string fixed(double v, int digits) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(digits);
  s << v;
  return s.str();
}

void writeReport(const Options& o, const std::vector<Row>& rows) {
  std::ofstream csv(o.out + "/frames.csv");
  csv << "lesson,preset,size,frame_ms,floor_ms,ratio_to_floor,draw_calls,window_fps,window_render_scale\n";
  for (const Row& r : rows)
    csv << r.lesson << ',' << r.preset << ',' << o.size << ',' << fixed(r.ms, 1) << ',' << fixed(r.floorMs, 1) << ','
        << fixed(r.floorMs > 0 ? r.ms / r.floorMs : 0, 2) << ',' << r.drawCalls << ','
        << (r.windowFps > 0 ? fixed(r.windowFps, 1) : "") << ',' << (r.windowFps > 0 ? fixed(r.windowScale, 2) : "")
        << '\n';
  std::ofstream html(o.out + "/frames.html");
  html << "<!doctype html><html><head><meta charset=\"utf-8\"><title>shadowlab frame times</title><style>"
          "body{font-family:sans-serif;margin:2em}table{border-collapse:collapse}td,th{padding:4px 10px;"
          "border-bottom:1px solid #ccc;text-align:right}td:first-child,td:nth-child(2){text-align:left}"
          ".bad{color:#b00;font-weight:bold}</style></head><body><h1>Frame times</h1><p>"
       << o.size << ", headless, median of frames 2 to " << o.frames - 1 << " over " << o.repeat
       << " interleaved repeat(s); the floor is the same frame with a trivial fragment shader. Goals: the "
          "default view under 100 ms and under 3x its floor, the heaviest preset under 1 s, 15 fps or better in "
          "a window with the frame budget.</p><table><tr><th>lesson</th><th>preset</th><th>frame ms</th>"
          "<th>floor ms</th><th>ratio</th><th>draw calls</th><th>window fps</th><th>render scale</th></tr>\n";
  for (const Row& r : rows) {
    const bool isDefault = r.preset == "default";
    const double ratio = r.floorMs > 0 ? r.ms / r.floorMs : 0;
    auto mark = [](bool bad, const std::string& text) {
      return bad ? "<span class=\"bad\">" + text + "</span>" : text;
    };
    html << "<tr><td>" << r.lesson << "</td><td>" << r.preset << "</td><td>"
         << mark(isDefault ? r.ms > 100 : r.ms > 1000, fixed(r.ms, 1)) << "</td><td>" << fixed(r.floorMs, 1)
         << "</td><td>" << mark(isDefault && ratio > 3, fixed(ratio, 2)) << "</td><td>" << r.drawCalls << "</td><td>"
         << (r.windowFps > 0 ? mark(r.windowFps < 15, fixed(r.windowFps, 1)) : "") << "</td><td>"
         << (r.windowFps > 0 ? fixed(r.windowScale, 2) : "") << "</td></tr>\n";
  }
  html << "</table></body></html>\n";
}

// The first line of /proc/cpuinfo's `key : value` for key, or "" (not Linux).
std::string procValue(const std::string& file, const std::string& key) {
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(key, 0) != 0) continue;
    std::string v = line.substr(line.find_first_of(":=") + 1);
    v.erase(0, v.find_first_not_of(" \t\""));
    while (!v.empty() && (v.back() == '"' || v.back() == ' ')) v.pop_back();
    return v;
  }
  return "";
}

// What ran the table: the CPU, its hardware threads, the system and the OpenGL renderer (a headless
// context of the lessons' own kind).
std::string machine() {
  std::string renderer = "unknown";
  try {
    auto context = createHeadlessContext({64, 64, "frame_bench", false, false});
    renderer = gl::caps().renderer + ", OpenGL " + gl::caps().version;
  } catch (const std::exception& e) { renderer = std::string("unknown (") + e.what() + ")"; }
  const std::string cpu = procValue("/proc/cpuinfo", "model name");
  const std::string os = procValue("/etc/os-release", "PRETTY_NAME");
  return (cpu.empty() ? "an unknown CPU" : cpu) + ", " + std::to_string(std::thread::hardware_concurrency()) +
         " hardware threads, " + (os.empty() ? "an unknown system" : os) + "; renderer " + renderer;
}

void writeMarkdown(const Options& o, const std::vector<Row>& rows) {
  char date[16];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
  std::ofstream md(o.markdown);
  md << "# Benchmarks\n\n"
     << "Generated by `make bench` (`frame_bench`) on " << date << ", on " << machine() << ". Do not edit: run "
     << "`make bench` again. Compare figures within this table only: on a shared or software-rendered machine the "
     << "same build's times swing by a third between runs.\n\n"
     << "Each lesson at " << o.size << ", headless: the median frame time of frames 2 to " << o.frames - 1 << " over "
     << o.repeat << " interleaved repeat(s); the floor is the same frame with every fragment shader replaced by a "
     << "trivial one (what the scene's geometry costs); the heaviest preset is the slowest of the lesson's presets "
     << "in a quick pass at a quarter of the pixels. The window column is the frames per second a student sees with "
     << "the frame budget on, and the render scale it settled on. Goals: the default view under 100 ms and under 3x "
     << "its floor, the heaviest preset under 1 s, 15 fps or better in a window.\n\n"
     << "| lesson | frame ms | floor ms | ratio | heaviest preset | its frame ms | window fps (render scale) |\n"
     << "|---|---|---|---|---|---|---|\n";
  for (const Row& d : rows) {
    if (d.preset != "default") continue;
    const Row* heavy = nullptr;
    for (const Row& h : rows)
      if (h.lesson == d.lesson && h.preset != "default") heavy = &h;
    md << "| " << d.lesson << " | " << fixed(d.ms, 1) << " | " << fixed(d.floorMs, 1) << " | "
       << (d.floorMs > 0 ? fixed(d.ms / d.floorMs, 2) : "") << " | " << (heavy ? "`" + heavy->preset + "`" : "")
       << " | " << (heavy ? fixed(heavy->ms, 1) : "") << " | "
       << (d.windowFps > 0 ? fixed(d.windowFps, 1) + " (" + fixed(d.windowScale, 2) + ")" : "") << " |\n";
  }
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  fs::create_directories(o.out);
  Runner r{o};
  // A quarter of the pixels for the search for the heaviest preset.
  const auto x = o.size.find('x');
  const std::string quarter =
      std::to_string(std::stoi(o.size.substr(0, x)) / 2) + "x" + std::to_string(std::stoi(o.size.substr(x + 1)) / 2);
  std::map<std::string, std::vector<std::string>> presets;
  for (const auto& l : o.lessons) {
    if (o.heaviest) presets[l] = r.presets(l);
    r.total += int(presets[l].size()) + 2 * 2 * o.repeat + (o.window ? 1 : 0);
  }
  std::vector<Row> rows;
  for (const auto& lesson : o.lessons) {
    std::string heaviest;
    double worst = -1;
    for (const auto& p : presets[lesson]) {
      r.progress(lesson + " " + p);
      const Frames f = r.run(lesson, {"--preset", p}, false, false, quarter, 4);
      if (f.ok && f.ms > worst) {
        worst = f.ms;
        heaviest = p;
      }
    }
    for (const std::string& preset : {std::string("default"), heaviest}) {
      if (preset.empty()) continue;
      std::vector<double> ms, floorMs;
      Row row{lesson, preset};
      for (int k = 0; k < o.repeat; ++k)
        for (bool floor : {false, true}) {
          r.progress(lesson + " " + preset + (floor ? " floor" : ""));
          const Frames f = r.run(lesson, {"--preset", preset}, floor, false, o.size, o.frames);
          if (!f.ok) continue;
          (floor ? floorMs : ms).push_back(f.ms);
          if (!floor) row.drawCalls = f.drawCalls;
        }
      row.ms = median(ms);
      row.floorMs = median(floorMs);
      if (o.window && preset == "default") {
        r.progress(lesson + " window");
        const Frames w = r.run(lesson, {}, false, true, o.size, 24);
        if (w.ok && w.ms > 0) {
          row.windowFps = 1000.0 / w.ms;
          row.windowScale = w.scale;
        }
      }
      rows.push_back(row);
    }
  }
  std::cerr << '\n';
  writeReport(o, rows);
  if (!o.markdown.empty()) writeMarkdown(o, rows);
  for (const Row& row : rows)
    std::cout << row.lesson << " " << row.preset << ": " << fixed(row.ms, 1) << " ms, floor " << fixed(row.floorMs, 1)
              << " ms" << (row.windowFps > 0 ? ", window " + fixed(row.windowFps, 1) + " fps" : "") << '\n';
  std::cout << "frame_bench: " << o.out << "/frames.csv, " << o.out << "/frames.html"
            << (o.markdown.empty() ? "" : ", " + o.markdown) << "\n";
  for (const auto& f : r.failures) std::cerr << "frame_bench: a run failed: " << f << '\n';
  return r.failures.empty() ? 0 : 1;
}
