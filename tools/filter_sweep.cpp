// filter_sweep: lesson 06's benchmark sweep over texture filter modes. For each mode it runs the
// lesson headless over a short scripted camera move (camera.path), with measure=true so every
// frame is compared against a supersampled reference of the same frame (trilinear, 16x, box
// filtered down), and --bench for the GPU time of the scene pass. It writes
//   OUT/filter_sweep.csv   one row per mode: GPU ms (mean, and its ratio to trilinear in the same
//                          run), RMSE and flicker (mean absolute frame-to-frame change) in 0-255 units
//   OUT/filter_sweep.html  a self-contained page: an inline SVG of GPU ms against RMSE, and the table
// Timing on a shared software rasteriser is noisy: compare modes as ratios within one run.
//
//   filter_sweep --lesson build/default/bin/lesson_06_texture_filtering --out out/filter_sweep
//                [--size 320x180] [--frames 16] [--supersample 4] [--modes nearest,trilinear,...]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Mode {
  std::string name, sets;  // sets: " --set a=b --set c=d"
};

const std::vector<Mode>& allModes() {
  static const std::vector<Mode> modes = {
      {"nearest", "filter.mag=nearest filter.min=nearest filter.mip=none"},
      {"bilinear", "filter.mip=none"},
      {"nearest_mipmap_nearest", "filter.min=nearest filter.mip=nearest"},
      {"linear_mipmap_nearest", "filter.mip=nearest"},
      {"nearest_mipmap_linear", "filter.min=nearest filter.mip=linear"},
      {"trilinear", "filter.mip=linear"},
      {"trilinear_bias+1", "filter.lod_bias=1"},
      {"aniso_2x", "filter.aniso=2"},
      {"aniso_4x", "filter.aniso=4"},
      {"aniso_8x", "filter.aniso=8"},
      {"aniso_16x", "filter.aniso=16"},
      {"rip_map", "sampling=rip_map"},
  };
  return modes;
}

struct Result {
  Mode mode;
  double gpuMs = 0, rmse = 0, flicker = 0, refFlicker = 0;
  int frames = 0;
};

void printUsage(std::ostream& out) {
  out << "usage: filter_sweep --lesson PATH --out DIR [--size WxH] [--frames N] [--supersample S] [--modes a,b,...]\n"
      << "modes:";
  for (const Mode& m : allModes()) out << ' ' << m.name;
  out << '\n';
}

[[noreturn]] void usage(const std::string& error) {
  std::cerr << "filter_sweep: " << error << "\n";
  printUsage(std::cerr);
  std::exit(2);
}

std::string fmt(double v, int digits = 3) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

std::string sets(const Mode& m) {
  std::istringstream in(m.sets);
  std::string out, a;
  while (in >> a) out += " --set " + a;
  return out;
}

// Mean GPU ms of the "scene" pass over frames >= 2 (the first frames compile and upload).
double sceneGpuMs(const std::string& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // header: frame,pass,gpu_ms,cpu_ms,frame_ms
  double sum = 0;
  int n = 0;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::string frame, pass, gpu;
    std::getline(row, frame, ',');
    std::getline(row, pass, ',');
    std::getline(row, gpu, ',');
    if (pass == "scene" && std::stoi(frame) >= 2) {
      sum += std::stod(gpu);
      ++n;
    }
  }
  return n ? sum / n : NAN;
}

Result run(const std::string& lesson, const Mode& m, const std::string& out, const std::string& size, int frames,
           int ss) {
  Result r{m};
  const std::string bench = out + "/bench_" + m.name + ".csv";
  const std::string cmd = "'" + lesson + "' --headless --size " + size + " --frames " + std::to_string(frames) +
                          " --set camera.path=true --set light.animate=false --set combine=replace --set measure=true" +
                          " --set measure.supersample=" + std::to_string(ss) + sets(m) + " --bench '" + bench + "'";
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) throw std::runtime_error("cannot run " + cmd);
  char line[512];
  int flickerFrames = 0;
  while (std::fgets(line, sizeof line, p)) {
    int frame;
    double rmse, flicker, refFlicker;
    if (std::sscanf(line, "measure frame=%d rmse=%lf flicker=%lf ref_flicker=%lf", &frame, &rmse, &flicker,
                    &refFlicker) == 4) {
      r.rmse += rmse;
      ++r.frames;
      if (flicker >= 0) {
        r.flicker += flicker;
        r.refFlicker += refFlicker;
        ++flickerFrames;
      }
    }
  }
  const int status = pclose(p);
  if (status != 0 || r.frames == 0)
    throw std::runtime_error("mode " + m.name + ": the lesson failed (status " + std::to_string(status) +
                             ") or printed no measurements:\n  " + cmd);
  r.rmse /= r.frames;
  if (flickerFrames) {
    r.flicker /= flickerFrames;
    r.refFlicker /= flickerFrames;
  }
  r.gpuMs = sceneGpuMs(bench);
  return r;
}

std::string svg(const std::vector<Result>& rs) {
  const double W = 760, H = 420, L = 70, R = 20, T = 20, B = 50;
  double xmax = 0, ymax = 0;
  for (const Result& r : rs) {
    if (std::isfinite(r.gpuMs)) xmax = std::max(xmax, r.gpuMs);
    ymax = std::max(ymax, r.rmse);
  }
  xmax = xmax > 0 ? xmax * 1.1 : 1;
  ymax = ymax > 0 ? ymax * 1.1 : 1;
  auto X = [&](double v) { return L + (W - L - R) * v / xmax; };
  auto Y = [&](double v) { return H - B - (H - T - B) * v / ymax; };
  std::ostringstream s;
  s << "<svg xmlns='http://www.w3.org/2000/svg' width='" << W << "' height='" << H
    << "' font-family='sans-serif' font-size='11'>\n";
  s << "<line x1='" << L << "' y1='" << H - B << "' x2='" << W - R << "' y2='" << H - B << "' stroke='black'/>\n";
  s << "<line x1='" << L << "' y1='" << T << "' x2='" << L << "' y2='" << H - B << "' stroke='black'/>\n";
  for (int i = 0; i <= 4; ++i) {
    s << "<text x='" << X(xmax * i / 4) << "' y='" << H - B + 15 << "' text-anchor='middle'>" << fmt(xmax * i / 4, 2)
      << "</text>\n";
    s << "<text x='" << L - 6 << "' y='" << Y(ymax * i / 4) + 4 << "' text-anchor='end'>" << fmt(ymax * i / 4, 1)
      << "</text>\n";
  }
  s << "<text x='" << (L + W - R) / 2 << "' y='" << H - 12
    << "' text-anchor='middle'>GPU ms, scene pass (mean)</text>\n";
  s << "<text transform='translate(16," << (T + H - B) / 2
    << ") rotate(-90)' text-anchor='middle'>RMSE vs supersampled reference (0-255)</text>\n";
  // The curve: modes ordered by time.
  std::vector<const Result*> sorted;
  for (const Result& r : rs)
    if (std::isfinite(r.gpuMs)) sorted.push_back(&r);
  std::sort(sorted.begin(), sorted.end(), [](auto a, auto b) { return a->gpuMs < b->gpuMs; });
  s << "<polyline fill='none' stroke='#99b' stroke-dasharray='4 3' points='";
  for (const Result* r : sorted) s << X(r->gpuMs) << ',' << Y(r->rmse) << ' ';
  s << "'/>\n";
  for (const Result* r : sorted) {
    s << "<circle cx='" << X(r->gpuMs) << "' cy='" << Y(r->rmse) << "' r='4' fill='#c33'/>\n";
    s << "<text x='" << X(r->gpuMs) + 6 << "' y='" << Y(r->rmse) - 5 << "'>" << r->mode.name << "</text>\n";
  }
  s << "</svg>\n";
  return s.str();
}

}  // namespace

int main(int argc, char** argv) {
  std::string lesson, out, size = "320x180", modeList;
  int frames = 16, ss = 4;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage(a + " needs a value");
      return argv[++i];
    };
    try {
      if (a == "--lesson") lesson = value();
      else if (a == "--out") out = value();
      else if (a == "--size") size = value();
      else if (a == "--frames") frames = std::stoi(value());
      else if (a == "--supersample") ss = std::stoi(value());
      else if (a == "--modes") modeList = value();
      else if (a == "--help" || a == "-h") {
        printUsage(std::cout);
        std::exit(0);
      } else usage("unknown flag '" + a + "'");
    } catch (const std::invalid_argument&) { usage("'" + a + "' needs an integer"); }
  }
  if (lesson.empty() || out.empty()) usage("--lesson and --out are required");
  if (!std::filesystem::exists(lesson)) usage("no lesson program at '" + lesson + "'");
  if (frames < 3 || frames > 1000) usage("--frames must be in [3, 1000]");
  if (ss < 2 || ss > 8) usage("--supersample must be in [2, 8]");
  std::vector<Mode> modes;
  if (modeList.empty()) {
    modes = allModes();
  } else {
    std::istringstream in(modeList);
    std::string name;
    while (std::getline(in, name, ',')) {
      auto it = std::find_if(allModes().begin(), allModes().end(), [&](const Mode& m) { return m.name == name; });
      if (it == allModes().end()) usage("unknown mode '" + name + "'");
      modes.push_back(*it);
    }
  }
  std::filesystem::create_directories(out);
  std::vector<Result> results;
  try {
    for (const Mode& m : modes) {
      std::cerr << "filter_sweep: " << m.name << " ..." << std::flush;
      results.push_back(run(lesson, m, out, size, frames, ss));
      const Result& r = results.back();
      std::cerr << " gpu " << fmt(r.gpuMs) << " ms, rmse " << fmt(r.rmse) << ", flicker " << fmt(r.flicker) << '\n';
    }
  } catch (const std::exception& e) {
    std::cerr << "\nfilter_sweep: " << e.what() << '\n';
    return 1;
  }
  double trilinearMs = NAN;
  for (const Result& r : results)
    if (r.mode.name == "trilinear") trilinearMs = r.gpuMs;
  std::ofstream csv(out + "/filter_sweep.csv");
  csv << "mode,settings,gpu_ms,gpu_ms_vs_trilinear,rmse,flicker,reference_flicker,frames\n";
  for (const Result& r : results)
    csv << r.mode.name << ",\"" << r.mode.sets << "\"," << fmt(r.gpuMs, 4) << ',' << fmt(r.gpuMs / trilinearMs, 3)
        << ',' << fmt(r.rmse, 4) << ',' << fmt(r.flicker, 4) << ',' << fmt(r.refFlicker, 4) << ',' << r.frames << '\n';
  std::ofstream html(out + "/filter_sweep.html");
  html << "<!doctype html><html><head><meta charset='utf-8'><title>Lesson 06 filter sweep</title>"
       << "<style>body{font-family:sans-serif;margin:2em}td,th{padding:2px 10px;text-align:right}"
       << "td:first-child,th:first-child{text-align:left}</style></head><body>\n"
       << "<h1>Lesson 06: texture filter modes, GPU time against aliasing error</h1>\n"
       << "<p>" << size << " pixels, " << frames
       << " frames of a sideways camera move over the fine checker; error against the same frame rendered at " << ss
       << "x" << ss
       << " the pixels with trilinear + 16x anisotropic filtering and box-filtered down. Flicker: mean absolute "
          "frame-to-frame change "
       << "(the reference's own is the motion that should be there). Times come from GL timer queries on a shared "
          "machine: compare them as ratios within this run.</p>\n"
       << svg(results)
       << "<table><tr><th>mode</th><th>GPU ms</th><th>x trilinear</th><th>RMSE</th><th>flicker</th><th>reference "
          "flicker</th></tr>\n";
  for (const Result& r : results)
    html << "<tr><td>" << r.mode.name << "</td><td>" << fmt(r.gpuMs) << "</td><td>" << fmt(r.gpuMs / trilinearMs, 2)
         << "</td><td>" << fmt(r.rmse) << "</td><td>" << fmt(r.flicker) << "</td><td>" << fmt(r.refFlicker)
         << "</td></tr>\n";
  html << "</table></body></html>\n";
  std::cerr << "filter_sweep: wrote " << out << "/filter_sweep.csv and filter_sweep.html\n";
  return 0;
}
