// The GPU half of the PSM stress suite (the CPU half is tests/stress/stress_psm.cpp): seeded random
// camera and light configurations rendered through lesson 09 (PSM with every fix) and measured
// against ground truth, each one frame of a generated camera/light path replayed in one lesson
// process per group (--replay, --measure FILE_%d.json). Every configuration must give: no GL error
// (the process runs with --strict-gl), no non-finite visibility or texel Jacobian, and at most
// `--max-edge` % misclassified away from shadow boundaries and `--max-leak` % of the truly
// shadowed pixels leaked (no vanished shadow). The worst configurations are printed with the seed
// and their index; replay one with --seed S --only I.
//   psm_stress LESSON --out DIR [--configs N] [--seed S] [--size WxH] [--only I] [--max-edge P] [--max-leak P]
//              [--set NAME=VALUE]...   (passed to the lesson: a control run with a broken setting)
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/process.hpp"
#include "core/scene_gen.hpp"
#include "measure/paths.hpp"

namespace fs = std::filesystem;
using namespace shadowlab;

namespace {

struct Rng {  // splitmix64: a configuration depends on (seed, index) only
  std::uint64_t s;
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform(double a = 0, double b = 1) { return a + (b - a) * double(next() >> 11) * (1.0 / 9007199254740992.0); }
  double logUniform(double a, double b) { return a * std::pow(b / a, uniform()); }
};

// One process renders a group: a scene, a light kind and the camera's near and far planes (the
// parameters a replayed path cannot change), over many configurations.
struct Group {
  const char* scene;
  bool point;
  double zNear, zFar;
  glm::vec3 lo, hi;  // where targets and lights go
};
const Group kGroups[] = {
    {"city", false, 1.0, 200.0, {-30, 0, -30}, {30, 20, 30}},   {"city", false, 0.01, 1e4, {-30, 0, -30}, {30, 20, 30}},
    {"terrain", false, 0.5, 500.0, {-40, 0, -40}, {40, 6, 40}}, {"city", true, 0.2, 300.0, {-30, 1, -30}, {30, 25, 30}},
    {"room", true, 0.05, 50.0, {-6, 0.3, -6}, {6, 5, 6}},       {"showcase", false, 5.0, 50.0, {-8, 0, -8}, {8, 3, 8}},
};
constexpr int kGroupCount = int(sizeof kGroups / sizeof kGroups[0]);
constexpr int kTriangles = 20000;  // the lessons' scene size in every group (--set triangles)

struct Config {
  int index = 0, group = 0;
  std::string kind;  // which nasty case
  measure::PathKey key;
};

glm::vec3 unitVector(Rng& r) {
  const double z = r.uniform(-1, 1), a = r.uniform(0, 6.283185307179586), s = std::sqrt(1 - z * z);
  return glm::vec3(float(s * std::cos(a)), float(z), float(s * std::sin(a)));
}

// The eye and a point light stay in free space: inside an object's box the eye would see through
// its back faces and a light would be sealed in (no light at all), which says nothing about PSM.
// The boxes come from the very scene the lesson builds (the same name, seed and size).
bool insideAny(const glm::vec3& p, const std::vector<Aabb>& boxes) {
  for (const Aabb& b : boxes)
    if (glm::all(glm::greaterThan(p, b.min - 0.05f)) && glm::all(glm::lessThan(p, b.max + 0.05f))) return true;
  return false;
}

Config drawConfig(Rng& r, int index, int group);

Config makeConfig(std::uint64_t seed, int index, int group, const std::vector<Aabb>& boxes) {
  Rng r{seed ^ (std::uint64_t(index) * 0xD1B54A32D192ED03ull)};
  Config c;
  for (int attempt = 0; attempt < 200; ++attempt) {
    c = drawConfig(r, index, group);
    if (!insideAny(c.key.cameraPosition, boxes) && (!kGroups[group].point || !insideAny(c.key.lightPosition, boxes)))
      break;
  }
  return c;
}

Config drawConfig(Rng& r, int index, int group) {
  const Group& g = kGroups[group];
  Config c;
  c.index = index;
  c.group = group;
  auto inBox = [&] {
    return glm::vec3(float(r.uniform(g.lo.x, g.hi.x)), float(r.uniform(g.lo.y, g.hi.y)),
                     float(r.uniform(g.lo.z, g.hi.z)));
  };
  c.key.cameraTarget = inBox();
  glm::vec3 d = unitVector(r);
  d.y = std::abs(d.y) * 0.8f + 0.05f;  // the eye above the target
  c.key.cameraPosition = c.key.cameraTarget + glm::normalize(d) * float(r.logUniform(2.0, 0.8 * (g.hi.x - g.lo.x)));
  c.key.cameraPosition.y = std::max(c.key.cameraPosition.y, g.lo.y + 0.5f);
  const glm::vec3 forward = glm::normalize(c.key.cameraTarget - c.key.cameraPosition);
  const glm::vec3 side = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)) + glm::vec3(1e-4f, 0, 0));
  const int pick = int(r.next() % 8);
  if (!g.point) {
    static const char* kinds[] = {"random",       "random",        "random",  "along view",
                                  "against view", "perpendicular", "grazing", "random"};
    c.kind = kinds[pick];
    glm::vec3 l = unitVector(r);
    l.y = -std::abs(l.y);  // from above, mostly
    if (pick == 3) l = forward;
    if (pick == 4) l = -forward;
    if (pick == 5) l = glm::normalize(glm::cross(forward, side));
    if (pick == 6) l = glm::normalize(glm::vec3(l.x, -0.02f, l.z));
    if (glm::length(l) < 1e-3f) l = glm::vec3(0, -1, 0);
    c.key.lightDirection = l;
    c.key.lightPosition = glm::vec3(0, 10, 0);
  } else {
    static const char* kinds[] = {"random", "random",          "random", "at the eye", "on the camera plane",
                                  "random", "near the target", "random"};
    c.kind = kinds[pick];
    c.key.lightPosition = inBox();
    if (pick == 3) c.key.lightPosition = c.key.cameraPosition;
    if (pick == 4) c.key.lightPosition = c.key.cameraPosition + side * float(r.uniform(0.5, 8.0));
    if (pick == 6) c.key.lightPosition = c.key.cameraTarget + glm::vec3(0, float(r.uniform(0.3, 3.0)), 0);
    c.key.lightDirection = glm::vec3(0, -1, 0);
  }
  return c;
}

struct Outcome {
  Config config;
  double edgePct = 0, leakShare = 0, misPct = 0;
  std::size_t facing = 0, shadowed = 0, nonFinite = 0;
  std::string counters, failure;
};

std::string describe(const Config& c) {
  const Group& g = kGroups[c.group];
  char b[512];
  std::snprintf(
      b, sizeof b,
      "%s, %s light (%s), near %g far %g, eye (%.3f %.3f %.3f) target (%.3f %.3f %.3f), light %s (%.4f %.4f %.4f)",
      g.scene, g.point ? "point" : "directional", c.kind.c_str(), g.zNear, g.zFar, c.key.cameraPosition.x,
      c.key.cameraPosition.y, c.key.cameraPosition.z, c.key.cameraTarget.x, c.key.cameraTarget.y, c.key.cameraTarget.z,
      g.point ? "at" : "toward", g.point ? c.key.lightPosition.x : c.key.lightDirection.x,
      g.point ? c.key.lightPosition.y : c.key.lightDirection.y,
      g.point ? c.key.lightPosition.z : c.key.lightDirection.z);
  return b;
}

// Renders one group's configurations in one lesson process; appends an outcome per configuration.
bool runGroup(const std::string& lesson, const fs::path& dir, int group, const std::vector<Config>& configs,
              const std::string& size, const std::vector<std::string>& extra, std::vector<Outcome>& out) {
  measure::CameraLightPath path;
  for (std::size_t k = 0; k < configs.size(); ++k) {
    measure::PathKey key = configs[k].key;
    key.time = double(k);
    path.add(key);
  }
  if (configs.size() == 1) {  // a path needs one key; hold it for two frames
    measure::PathKey key = configs[0].key;
    key.time = 1.0;
    path.add(key);
  }
  const std::string stem = "group" + std::to_string(group);
  path.save((dir / (stem + ".path")).string());
  const Group& g = kGroups[group];
  const int frames = int(std::max<std::size_t>(configs.size(), 2));
  std::vector<std::string> args = {lesson,
                                   "--headless",
                                   "--strict-gl",
                                   "--size",
                                   size,
                                   "--frames",
                                   std::to_string(frames),
                                   "--replay",
                                   (dir / (stem + ".path")).string(),
                                   "--measure",
                                   (dir / (stem + "_%d.json")).string(),
                                   "--set",
                                   std::string("scene=") + g.scene,
                                   "--set",
                                   "triangles=" + std::to_string(kTriangles),
                                   "--set",
                                   "map_size=2048",
                                   "--set",
                                   "camera.near=" + std::to_string(g.zNear),
                                   "--set",
                                   "camera.far=" + std::to_string(g.zFar),
                                   "--set",
                                   std::string("light0.kind=") + (g.point ? "point" : "directional")};
  args.insert(args.end(), extra.begin(), extra.end());
  const std::string log = (dir / (stem + ".log")).string();
  if (const int rc = runProcess(args, {log}); rc != 0) {
    std::ifstream in(log);
    std::cerr << "psm_stress: group " << group << " (" << g.scene << ") exited " << rc << ":\n" << in.rdbuf() << '\n';
    return false;
  }
  for (std::size_t k = 0; k < configs.size(); ++k) {
    Outcome o;
    o.config = configs[k];
    std::ifstream in(dir / (stem + "_" + std::to_string(k) + ".json"));
    const auto j = nlohmann::json::parse(in);
    const auto& h = j.at("hard");
    o.facing = h.at("facing_pixels");
    o.shadowed = h.at("reference_shadowed");
    o.misPct = h.at("misclassified_pct");
    o.edgePct = h.at("edge_tolerant_pct");
    o.leakShare = o.shadowed > 0 ? 100.0 * double(h.at("leaks").get<std::size_t>()) / double(o.shadowed) : 0.0;
    o.nonFinite = j.at("nonfinite").at("visibility").get<std::size_t>() +
                  j.at("nonfinite").at("texel_jacobian").get<std::size_t>();
    for (const auto& [name, value] : j.at("counters").items())
      if (name.rfind("light0 ", 0) == 0)
        o.counters += (o.counters.empty() ? "" : ", ") + name.substr(7) + ": " + value.get<std::string>();
    out.push_back(o);
  }
  return true;
}

double argNumber(const std::string& flag, const char* v) {
  char* end = nullptr;
  const double d = std::strtod(v, &end);
  if (end == v || *end) {
    std::cerr << "psm_stress: " << flag << " '" << v << "' is not a number\n";
    std::exit(2);
  }
  return d;
}

}  // namespace

int main(int argc, char** argv) {
  const char* usage =
      "usage: psm_stress LESSON [--out DIR] [--configs N] [--seed S] [--size WxH] [--only I] [--max-edge P] "
      "[--max-leak P] [--set name=value]...\n";
  if (const int code = checkProgramArgument("psm_stress", argc, argv, usage); code >= 0) return code;
  const std::string lesson = argv[1];
  std::string out = "psm_stress", size = "160x90";
  int configs = 240, only = -1;
  std::uint64_t seed = 12;
  double maxEdge = 4.0, maxLeak = 25.0;
  std::vector<std::string> extra;
  if (const char* s = std::getenv("SHADOWLAB_SEED")) seed = std::strtoull(s, nullptr, 10);
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (i + 1 >= argc) {
      std::cerr << "psm_stress: " << a << " needs a value\n";
      return 2;
    }
    const char* v = argv[++i];
    if (a == "--set") extra.insert(extra.end(), {"--set", v});
    else if (a == "--out") out = v;
    else if (a == "--configs") configs = int(argNumber(a, v));
    else if (a == "--seed") seed = std::uint64_t(argNumber(a, v));
    else if (a == "--size") size = v;
    else if (a == "--only") only = int(argNumber(a, v));
    else if (a == "--max-edge") maxEdge = argNumber(a, v);
    else if (a == "--max-leak") maxLeak = argNumber(a, v);
    else {
      std::cerr << "psm_stress: unknown flag '" << a
                << "'; valid: --out --configs --seed --size --only --max-edge --max-leak --set\n";
      return 2;
    }
  }
  if (configs < 1) {
    std::cerr << "psm_stress: --configs must be at least 1\n";
    return 2;
  }
  const fs::path dir(out);
  fs::create_directories(dir);
  std::vector<std::vector<Config>> byGroup(kGroupCount);
  std::vector<std::vector<Aabb>> boxes(kGroupCount);
  for (int g = 0; g < kGroupCount; ++g) {
    const Scene scene = makeScene(kGroups[g].scene, 1, kTriangles);
    for (std::size_t k = 0; k < scene.objects.size(); ++k)
      if (scene.meshes[scene.objects[k].mesh].triangleCount() > 0)
        boxes[std::size_t(g)].push_back(scene.objectBounds(k));
  }
  for (int i = 0; i < configs; ++i)
    if (only < 0 || i == only)
      byGroup[std::size_t(i % kGroupCount)].push_back(
          makeConfig(seed, i, i % kGroupCount, boxes[std::size_t(i % kGroupCount)]));
  std::vector<Outcome> outcomes;
  bool ok = true;
  for (int g = 0; g < kGroupCount; ++g)
    if (!byGroup[std::size_t(g)].empty())
      ok = runGroup(lesson, dir, g, byGroup[std::size_t(g)], size, extra, outcomes) && ok;
  int failed = 0, empty = 0;
  for (Outcome& o : outcomes) {
    if (o.nonFinite > 0) o.failure = std::to_string(o.nonFinite) + " non-finite pixels";
    else if (o.facing > 200 && o.edgePct > maxEdge) o.failure = "misclassified away from boundaries";
    else if (o.shadowed > 200 && o.leakShare > maxLeak) o.failure = "the shadow leaked";
    failed += !o.failure.empty();
    empty += o.facing <= 200;
  }
  // Worst first: failures, then by the share misclassified away from boundaries (a leak share of a
  // handful of shadowed pixels says little).
  auto badness = [](const Outcome& o) {
    return (o.failure.empty() ? 0.0 : 1000.0) + (o.facing > 200 ? o.edgePct : 0.0) +
           (o.shadowed > 200 ? o.leakShare / 10.0 : 0.0);
  };
  std::sort(outcomes.begin(), outcomes.end(),
            [&](const Outcome& a, const Outcome& b) { return badness(a) > badness(b); });
  std::printf("psm_stress: %zu configurations (seed %llu, %s), %d failed, %d with under 200 facing pixels\n",
              outcomes.size(), (unsigned long long)seed, size.c_str(), failed, empty);
  std::printf("bounds: %.1f %% misclassified away from boundaries, %.1f %% of the true shadow leaked; worst:\n",
              maxEdge, maxLeak);
  for (std::size_t k = 0; k < outcomes.size() && k < 6; ++k) {
    const Outcome& o = outcomes[k];
    std::printf(
        "  #%d: %.2f %% (edge-tolerant %.2f %%), leaked %.1f %% of %zu shadowed of %zu facing%s%s\n      %s\n      "
        "%s\n",
        o.config.index, o.misPct, o.edgePct, o.leakShare, o.shadowed, o.facing, o.failure.empty() ? "" : ": FAILED, ",
        o.failure.c_str(), describe(o.config).c_str(), o.counters.c_str());
  }
  for (const Outcome& o : outcomes)
    if (!o.failure.empty())
      std::printf("FAILED #%d (replay: --seed %llu --only %d): %s\n", o.config.index, (unsigned long long)seed,
                  o.config.index, o.failure.c_str());
  return ok && failed == 0 && !outcomes.empty() ? 0 : 1;
}
