// What every lesson declares the same way (its camera, lights and impl), and the command line's
// questions about a lesson (--help, --info, --list-*), answered before any context opens.
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

#include "app/lesson.hpp"
#include "app/lesson_setup.hpp"
#include "app/measurement.hpp"
#include "core/hotkeys.hpp"
#include "core/param_checks.hpp"

namespace shadowlab {
namespace {

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

}  // namespace

void declareCamera(ParamRegistry& params, OrbitCamera& c) {
  params.add("camera.yaw", &c.yaw, -1000.0f, 1000.0f, "orbit angle around +y (radians)").hidden = true;
  params.add("camera.pitch", &c.pitch, -1.57f, 1.57f, "angle above the horizon (radians)").hidden = true;
  params.add("camera.distance", &c.distance, 0.01f, 10000.0f, "distance from the target").hidden = true;
  params.add("camera.target", &c.target, -10000.0f, 10000.0f, "the point the camera orbits").hidden = true;
  params.add("camera.fov", &c.fovY, 0.1f, 3.0f, "vertical field of view (radians)").hidden = true;
  params.add("camera.near", &c.nearZ, 1e-4f, 100.0f, "near plane distance").hidden = true;
  params.add("camera.far", &c.farZ, 0.1f, 1e7f, "far plane distance").hidden = true;
  addCameraChecks(params, c);
}

void declareImpl(ParamRegistry& r, Impl* impl, const std::string& why) {
  r.addChoice("impl", impl, {"reference", "student"}, why);
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
  addLightChecks(r, n, l);
}

void declareLights(ParamRegistry& r, std::span<Light> lights) {
  for (std::size_t i = 0; i < lights.size(); ++i) declareLight(r, int(i), lights[i]);
}

void checkHotkeys(const ParamRegistry& params) {
  const std::vector<std::string> problems = hotkeyProblems(params);
  if (problems.empty()) return;
  std::string all;
  for (const std::string& p : problems) all += (all.empty() ? "" : "; ") + p;
  throw ParamError("hotkeys: " + all);
}

std::string infoJson(const LessonInfo& info, const Exercises& exercises) {
  std::string prerequisites, list, key;
  for (const std::string& p : info.prerequisites) prerequisites += (prerequisites.empty() ? "\"" : ",\"") + p + "\"";
  for (const std::string& k : info.keyFigures) key += (key.empty() ? "\"" : ",\"") + jsonEscape(k) + "\"";
  for (const Exercise& e : exercises.list()) {
    const ExerciseLocation at = exerciseLocation(info.name, e);
    list += std::string(list.empty() ? "" : ",") + "{\"id\":\"" + e.id + "\",\"function\":\"" +
            jsonEscape(e.function()) + "\",\"title\":\"" + jsonEscape(e.title) +
            "\",\"glsl\":" + (e.glsl ? "true" : "false") + ",\"file\":\"" + at.file +
            "\",\"line\":" + std::to_string(at.line) + "}";
  }
  return "{\"number\":\"" + info.number + "\",\"name\":\"" + info.name + "\",\"title\":\"" + jsonEscape(info.title) +
         "\",\"summary\":\"" + jsonEscape(info.summary) + "\",\"help\":\"" + jsonEscape(info.help) +
         "\",\"difficulty\":" + std::to_string(info.difficulty) + ",\"minutes\":" + std::to_string(info.minutes) +
         ",\"prerequisites\":[" + prerequisites + "],\"key_figures\":[" + key + "],\"exercises\":[" + list +
         "],\"grade\":\"" + (exercises.empty() ? std::string() : gradeCommand(info.name)) + "\"}";
}

bool answerQuery(const CommandLine& cl, const LessonInfo& info, const ParamRegistry& params, const PresetFile& presets,
                 const Exercises& exercises, const char* program) {
  if (cl.help) {
    std::cout << info.number << " " << info.title << ": " << info.summary << "\n\n" << commandLineHelp(program);
  } else if (cl.info) {
    std::cout << infoJson(info, exercises) << "\n";
  } else if (cl.listParams) {
    std::cout << params.describe();
  } else if (cl.listPresets) {
    for (const auto& n : presets.names()) std::cout << n << '\n';
  } else if (cl.listHotkeys) {
    std::cout << describeHotkeys(params);
  } else {
    return false;
  }
  return true;
}

std::vector<Counter> keyFigures(const LessonInfo& info, const std::vector<Counter>& all, bool measured) {
  static const char* const kMeasured[] = {"measure", "misclassified", "aliasing m", "soft error", "umbra", "shimmer"};
  std::vector<Counter> key;
  for (const std::string& name : info.keyFigures)
    for (const Counter& c : all)
      if (c.name == name) key.push_back(c);
  if (!measured) return key;
  for (const char* name : kMeasured)
    for (const Counter& c : all)
      if (c.name == name) key.push_back(c);
  return key;
}

std::string scriptedKeyReport(const std::string& lesson, const std::string& step, const OrbitCamera& camera, bool fly,
                              const ParamRegistry& params) {
  const glm::vec3 eye = camera.position(), ahead = camera.forward();
  std::ostringstream line;
  line << std::fixed << std::setprecision(4) << lesson << ": --keys " << step << ": eye " << eye.x << ' ' << eye.y
       << ' ' << eye.z << ", forward " << ahead.x << ' ' << ahead.y << ' ' << ahead.z << ", camera "
       << (fly ? "fly" : "orbit");
  for (const Param& p : params.params())
    if (!p.hotkey.empty() && step.rfind(p.hotkey, 0) == 0 && (step.size() == 1 || step[1] == '*'))
      line << ", " << p.name << '=' << params.get(p.name);
  return line.str();
}

std::string sightBanner(Lesson& lesson, float aspect) {
  const MeasureSource source = lesson.measureSource();
  if (!source.scene) return "";
  const Aabb box = source.scene->bounds();
  const std::string why = box.empty() ? "" : sightProblem(lesson.camera, aspect, box.min, box.max);
  return why.empty() ? "" : "The camera sees none of the scene: " + why + ". Home resets the camera.";
}

}  // namespace shadowlab
