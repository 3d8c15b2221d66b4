// shadowlab_bench: runs a lesson headless over parameter sets, scenes and a recorded camera/light
// path, measures every run against ground truth (--measure), and writes a report: CSV, JSON and an
// HTML page with a run-time-against-error scatter per scene (Pareto front marked), tables and
// thumbnails of the image and its error heatmap.
//
//   shadowlab_bench build/default/bin/lesson_03_shadow_quality --out out/bench/l03
//       --config "pcf 3x3: filter=pcf_nxn map_size=2048" --preset acne --scenes city,forest
//       --path paths/city.path --path-samples 4 --repeat 3 --size 1280x720 --frames 8
//       --shimmer "camera=paths/walk.path@0.50..0.51" --shimmer-frames 9
//
// Each configuration is a label and `--set` assignments ("label: name=value name=value"), or a
// preset. GPU and CPU ms are the median over the repeats; the error figures come from the first
// repeat (the render is deterministic). Repeats go round-robin over the configurations, so their
// timings share the load of a busy machine. A progress bar shows on the terminal.
//
// --shimmer NAME=FILE@T0..T1 (repeatable): every (scene, configuration) also plays that short span of
// a path over --shimmer-frames consecutive frames (a slow camera drift, the sun turning a fraction
// of a degree a frame), each frame measured against the one before (the lesson's temporal figures);
// the mean and worst over the frame pairs go into the configuration's rows as shimmer_*:NAME.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/process.hpp"
#include "measure/paths.hpp"
#include "measure/report.hpp"

namespace fs = std::filesystem;
using namespace shadowlab;

namespace {

struct Config {
  std::string label;
  std::vector<std::string> args;  // --preset NAME or --set k=v ...
};

struct Options {
  std::string lesson, out, path, title = "shadowlab benchmark", size = "1280x720";
  std::string model;  // --model FILE for every run (scene=model unless --scenes says otherwise)
  std::vector<Config> configs;
  std::vector<std::string> scenes;
  int pathSamples = 1, repeat = 3, frames = 6;
  std::vector<std::pair<std::string, std::string>> shimmer;  // name, FILE@T0..T1
  int shimmerFrames = 9;
};

constexpr const char* kUsage =
    "usage: shadowlab_bench LESSON_PROGRAM --out DIR [--config \"label: name=value ...\"]... [--preset NAME]...\n"
    "       [--scenes a,b] [--model FILE] [--path FILE [--path-samples N]] [--repeat N] [--frames N] [--size WxH] "
    "[--title T]\n"
    "       [--shimmer NAME=FILE@T0..T1]... [--shimmer-frames N]\n";

[[noreturn]] void usage(const std::string& error) {
  std::cerr << "shadowlab_bench: " << error << "\n" << kUsage;
  std::exit(2);
}

int toInt(const std::string& flag, const std::string& v, int lo) {
  char* end = nullptr;
  const long n = std::strtol(v.c_str(), &end, 10);
  if (end == v.c_str() || *end || n < lo) usage(flag + ": '" + v + "' is not a whole number >= " + std::to_string(lo));
  return int(n);
}

// --shimmer NAME=FILE@T0..T1: a name of letters, digits and '_', and a span of a path that exists.
std::pair<std::string, std::string> shimmerSpan(const std::string& v) {
  const auto eq = v.find('=');
  const std::string name = v.substr(0, eq == std::string::npos ? 0 : eq);
  if (name.empty() || name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_") != std::string::npos)
    usage("--shimmer '" + v + "' is not NAME=FILE@T0..T1 (NAME: lower-case letters, digits, '_')");
  const std::string spec = v.substr(eq + 1);
  try {
    const measure::ReplaySpec span = measure::parseReplaySpec(spec);
    if (span.from < 0) throw std::invalid_argument("needs a span @T0..T1 (consecutive frames of a slow move)");
    measure::CameraLightPath::load(span.file);
  } catch (const std::exception& e) { usage("--shimmer " + v + ": " + e.what()); }
  return {name, spec};
}

Options parse(int argc, char** argv) {
  Options o;
  if (argc < 2) usage("no lesson program given");
  o.lesson = argv[1];
  if (o.lesson == "--help" || o.lesson == "-h") {
    std::cout << kUsage;
    std::exit(0);
  }
  if (o.lesson.empty() || o.lesson[0] == '-') usage("the first argument is the lesson program, not '" + o.lesson + "'");
  if (!fs::exists(o.lesson)) usage("no lesson program at " + o.lesson);
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage(a + " needs a value");
      return argv[++i];
    };
    if (a == "--out") o.out = value();
    else if (a == "--config") {
      const std::string c = value();
      const auto colon = c.find(':');
      if (colon == std::string::npos) usage("--config '" + c + "' is not \"label: name=value ...\"");
      Config config{c.substr(0, colon), {}};
      std::istringstream in(c.substr(colon + 1));
      for (std::string kv; in >> kv;) {
        if (kv.find('=') == std::string::npos) usage("--config '" + c + "': '" + kv + "' is not name=value");
        config.args.insert(config.args.end(), {"--set", kv});
      }
      o.configs.push_back(config);
    } else if (a == "--preset") {
      const std::string p = value();
      o.configs.push_back({"preset " + p, {"--preset", p}});
    } else if (a == "--scenes") {
      std::istringstream in(value());
      for (std::string s; std::getline(in, s, ',');)
        if (!s.empty()) o.scenes.push_back(s);
    } else if (a == "--model") o.model = value();
    else if (a == "--path") o.path = value();
    else if (a == "--path-samples") o.pathSamples = toInt(a, value(), 1);
    else if (a == "--repeat") o.repeat = toInt(a, value(), 1);
    else if (a == "--frames") o.frames = toInt(a, value(), 1);
    else if (a == "--size") o.size = value();
    else if (a == "--title") o.title = value();
    else if (a == "--shimmer") o.shimmer.push_back(shimmerSpan(value()));
    else if (a == "--shimmer-frames") o.shimmerFrames = toInt(a, value(), 2);
    else
      usage("unknown argument '" + a +
            "'; valid: --out --config --preset --scenes --model --path --path-samples --repeat --frames --size --title "
            "--shimmer --shimmer-frames");
  }
  if (o.out.empty()) usage("--out DIR is required");
  if (o.configs.empty()) o.configs.push_back({"defaults", {}});
  if (o.scenes.empty()) o.scenes.push_back("");
  return o;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

std::uint64_t leadingNumber(const std::string& s) {
  std::string digits;
  for (char c : s) {
    if (c >= '0' && c <= '9') digits += c;
    else if (!digits.empty() && c != ',') break;
  }
  return digits.empty() ? 0 : std::stoull(digits);
}

// The counts a --measure JSON's "hard" and "edge_band" share (their pixels under `pixelsKey`).
measure::HardShadowErrors countsFrom(const nlohmann::json& h, const char* pixelsKey) {
  measure::HardShadowErrors e;
  e.facingPixels = h.at(pixelsKey);
  e.misclassified = h.at("misclassified");
  e.leaks = h.at("leaks");
  e.falseShadows = h.at("false_shadows");
  e.misclassifiedPct = h.at("misclassified_pct");
  return e;
}

// The aliasing figures of a --measure JSON ("aliasing", or an edge band's).
measure::AliasingStats aliasingFrom(const nlohmann::json& a) {
  measure::AliasingStats s;
  s.pixels = a.at("pixels");
  s.mean = a.at("mean");
  s.rms = a.at("rms");
  s.p95 = a.at("p95");
  s.max = a.at("max");
  s.shareAbove1 = a.at("share_above_1");
  return s;
}

// The figures of one measured run into its report row (the first repeat's: renders are deterministic).
void readFigures(const nlohmann::json& j, measure::ReportRow& row) {
  if (j.contains("hard")) {
    const auto& h = j["hard"];
    row.hasHard = true;
    row.hard = countsFrom(h, "facing_pixels");
    row.hard.referenceShadowed = h.value("reference_shadowed", std::size_t(0));
    row.hard.edgePixels = h.at("edge_pixels");
    row.hard.leakPct = h.at("leak_pct");
    row.hard.falseShadowPct = h.at("false_shadow_pct");
    row.hard.edgeTolerantPct = h.at("edge_tolerant_pct");
  }
  if (j.contains("soft")) {
    row.hasSoft = true;
    row.soft.pixels = j["soft"].at("pixels");
    row.soft.rmse = j["soft"].at("rmse");
    row.soft.maxAbs = j["soft"].at("max_abs");
    row.soft.umbraOverPct = j["soft"].value("umbra_over_pct", 0.0);
    row.soft.umbraUnderPct = j["soft"].value("umbra_under_pct", 0.0);
    row.soft.bleedPct = j["soft"].value("bleed_pct", 0.0);
    row.soft.noiseFloor = j["soft"].value("reference_noise_rmse", -1.0);
  }
  if (j.contains("aliasing")) {
    row.hasAliasing = true;
    row.aliasing = aliasingFrom(j["aliasing"]);
  }
  if (j.contains("edge_band")) {
    const auto& b = j["edge_band"];
    row.hasBand = true;
    row.band = countsFrom(b, "pixels");
    if (b.contains("aliasing")) row.bandAliasing = aliasingFrom(b["aliasing"]);
  }
  for (const auto& [name, value] : j.at("counters").items()) {
    if (name == "shadow triangles") {
      row.shadowTriangles = leadingNumber(value.get<std::string>());
      row.reusedMaps = std::max<std::int64_t>(row.reusedMaps, 0);  // a technique's counters: none reused unless said
    }
    if (name == "shadow texels") row.shadowTexels = leadingNumber(value.get<std::string>());
    if (name == "culled casters") row.culledCasters = std::int64_t(leadingNumber(value.get<std::string>()));
    if (name == "cube faces skipped") row.skippedFaces = std::int64_t(leadingNumber(value.get<std::string>()));
    if (name == "maps reused") row.reusedMaps = std::int64_t(leadingNumber(value.get<std::string>()));
    if (name == "draw calls") row.drawCalls = std::int64_t(leadingNumber(value.get<std::string>()));
  }
}

// A run's log, whole (what the lesson said when it failed).
std::string readText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// One (scene, configuration, path sample): its row and the timings of its repeats.
struct Job {
  std::string scene, id;
  const Config* config = nullptr;
  double pathTime = -1;
  measure::ReportRow row;
  std::map<std::string, std::vector<double>> gpu;
  std::vector<double> cpu;
};

// Runs one repeat of a job; false (with the lesson's output on stderr) when it failed.
bool runRepeat(const Options& o, const fs::path& runs, Job& job, int r) {
  std::vector<std::string> args = {o.lesson,    "--headless",
                                   "--size",    o.size,
                                   "--frames",  std::to_string(o.frames),
                                   "--measure", (runs / (job.id + ".json")).string()};
  if (r == 0) args.insert(args.end(), {"--screenshot", (runs / (job.id + ".png")).string()});
  if (!o.model.empty()) args.insert(args.end(), {"--model", o.model});
  if (!job.scene.empty()) args.insert(args.end(), {"--set", "scene=" + job.scene});
  args.insert(args.end(), job.config->args.begin(), job.config->args.end());
  if (job.pathTime >= 0) args.insert(args.end(), {"--replay", o.path + "@" + std::to_string(job.pathTime)});
  const std::string log = (runs / (job.id + ".log")).string();
  if (runProcess(args, {log}) != 0) {
    std::cerr << "\nshadowlab_bench: " << job.row.scene << " / " << job.config->label << " failed:\n" << readText(log);
    return false;
  }
  std::ifstream in(runs / (job.id + ".json"));
  const auto j = nlohmann::json::parse(in);
  double cpuTotal = 0;
  for (const auto& [pass, ms] : j.at("gpu_ms").items()) job.gpu[pass].push_back(ms.get<double>());
  for (const auto& [pass, ms] : j.at("cpu_ms").items()) cpuTotal += ms.get<double>();
  job.cpu.push_back(cpuTotal);
  if (r == 0) {
    std::string params;
    for (std::size_t a = 1; a < job.config->args.size(); a += 2)
      params += (params.empty() ? "" : " ") + job.config->args[a];
    job.row.parameters = params + (job.pathTime >= 0 ? " path@" + std::to_string(job.pathTime) : "");
    readFigures(j, job.row);
    job.row.imageThumbnail = "runs/" + job.id + ".png";
    job.row.errorThumbnail = "runs/" + job.id + "_error.png";
  }
  return true;
}

// Plays one shimmer span for (scene, configuration); false (the lesson's output on stderr) on failure.
bool runShimmer(const Options& o, const fs::path& runs, const Job& job, const std::string& name,
                const std::string& spec, measure::ShimmerFigures& f) {
  const std::string stem = job.id + "_shimmer_" + name;
  std::vector<std::string> args = {o.lesson,    "--headless",
                                   "--size",    o.size,
                                   "--frames",  std::to_string(o.shimmerFrames),
                                   "--replay",  spec,
                                   "--measure", (runs / (stem + "_%d.json")).string()};
  if (!o.model.empty()) args.insert(args.end(), {"--model", o.model});
  if (!job.scene.empty()) args.insert(args.end(), {"--set", "scene=" + job.scene});
  args.insert(args.end(), job.config->args.begin(), job.config->args.end());
  const std::string log = (runs / (stem + ".log")).string();
  bool ok = runProcess(args, {log}) == 0;
  double unmatched = 0;
  for (int frame = 1; ok && frame < o.shimmerFrames; ++frame) {
    std::ifstream in(runs / (stem + "_" + std::to_string(frame) + ".json"));
    const auto j = nlohmann::json::parse(in, nullptr, false);
    if (j.is_discarded() || !j.contains("temporal")) {
      ok = false;  // every frame after the first is compared with the one before
      break;
    }
    const auto& t = j["temporal"];
    const double pct = t.at("extra_flip_pct");
    f.extraFlipPct += pct;
    f.maxExtraFlipPct = std::max(f.maxExtraFlipPct, pct);
    f.referenceFlipPct += t.at("reference_flip_pct").get<double>();
    f.extraChange += t.at("extra_change").get<double>();
    f.redrawn = f.redrawn || t.value("redrawn", false);
    f.reprojected = f.reprojected || t.at("reprojected").get<bool>();
    const double pixels = t.at("pixels").get<double>() + t.at("unmatched").get<double>();
    unmatched += pixels > 0 ? 100.0 * t.at("unmatched").get<double>() / pixels : 0.0;
    ++f.frames;
  }
  if (!ok) {
    std::cerr << "\nshadowlab_bench: shimmer " << name << ", " << job.row.scene << " / " << job.config->label
              << ": no temporal figures for every frame:\n"
              << readText(log);
    return false;
  }
  f.extraFlipPct /= f.frames;
  f.referenceFlipPct /= f.frames;
  f.extraChange /= f.frames;
  f.unmatchedPct = unmatched / f.frames;
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  std::vector<double> pathTimes = {-1};
  if (!o.path.empty()) {
    try {
      const auto path = measure::CameraLightPath::load(o.path);
      pathTimes.clear();
      for (int k = 0; k < o.pathSamples; ++k)
        pathTimes.push_back(o.pathSamples == 1 ? 0.0 : path.duration() * k / (o.pathSamples - 1));
    } catch (const std::exception& e) { usage(std::string("--path: ") + e.what()); }
  }
  const fs::path runs = fs::path(o.out) / "runs";
  fs::create_directories(runs);
  std::vector<Job> jobs;
  for (const auto& scene : o.scenes)
    for (const auto& config : o.configs)
      for (std::size_t k = 0; k < pathTimes.size(); ++k) {
        Job job{scene, "run" + std::to_string(jobs.size()), &config, pathTimes[k]};
        job.row.scene = scene.empty() ? "default" : scene;
        job.row.technique = config.label;
        job.row.frame = int(k);
        jobs.push_back(std::move(job));
      }
  // Repeats go round-robin over the jobs, so that every configuration's timings see the same mix
  // of the machine's load (ratios between configurations are what the timings are good for).
  const std::size_t shimmerRuns = o.shimmer.size() * o.scenes.size() * o.configs.size();
  measure::ProgressBar progress(jobs.size() * std::size_t(o.repeat) + shimmerRuns, "benchmark");
  int failures = 0;
  for (int r = 0; r < o.repeat; ++r)
    for (Job& job : jobs) {
      if (r > 0 && job.cpu.empty()) continue;  // its first run failed already
      failures += !runRepeat(o, runs, job, r);
      progress.advance();
    }
  // Shimmer: once per (scene, configuration) and span, into each of its rows (the path samples').
  for (Job& job : jobs) {
    if (job.row.frame != 0) continue;  // once per (scene, configuration)
    if (job.cpu.empty()) {             // its first run failed already
      progress.advance(o.shimmer.size());
      continue;
    }
    for (const auto& [name, spec] : o.shimmer) {
      measure::ShimmerFigures f;
      if (!runShimmer(o, runs, job, name, spec, f)) {
        ++failures;
        continue;
      }
      for (Job& other : jobs)
        if (other.scene == job.scene && other.config == job.config) other.row.shimmer[name] = f;
    }
    progress.advance(o.shimmer.size());
  }
  progress.finish();
  std::vector<measure::ReportRow> rows;
  for (Job& job : jobs) {
    if (job.cpu.empty()) continue;
    for (const auto& [pass, samples] : job.gpu) job.row.gpuMs[pass] = median(samples);
    job.row.cpuMs = median(job.cpu);
    rows.push_back(job.row);
  }
  const std::string html = measure::writeReport(o.out, "report", rows, o.title);
  std::cout << "shadowlab_bench: " << rows.size() << " row(s), " << failures
            << " failed run(s): " << fs::absolute(html).string() << '\n';
  return failures == 0 && !rows.empty() ? 0 : 1;
}
