#include "app/model_choice.hpp"

#include <algorithm>
#include <iostream>

#include "core/cli.hpp"
#include "core/model_file.hpp"

namespace shadowlab {
namespace {

// What was generated, skipped or substituted, on one line ("lesson: model 'FILE': a; b").
void reportNotes(const ModelFile& m, const std::string& lesson) {
  if (m.notes.empty()) return;
  std::string line;
  for (const std::string& note : m.notes) line += (line.empty() ? "" : "; ") + note;
  std::cerr << lesson << ": model '" << m.path << "': " << line << '\n';
}

}  // namespace

std::string modelSceneAssignment(const ParamRegistry& params, const std::string& lesson) {
  const Param* scene = params.find("scene");
  if (!scene || std::find(scene->choices.begin(), scene->choices.end(), "model") == scene->choices.end())
    throw CliError("--model: lesson " + lesson + " has no scene choice 'model' (it draws its own scenes)");
  return "scene=model";
}

bool sceneIsModel(const ParamRegistry& params) {
  const Param* scene = params.find("scene");
  return scene && scene->kind == ParamKind::Choice && !scene->choices.empty() && scene->choices.back() == "model" &&
         *static_cast<const int*>(scene->target) == int(scene->choices.size() - 1);
}

bool loadModelReporting(const std::string& path, const std::string& lesson) {
  try {
    reportNotes(loadCurrentModel(path), lesson);
    return true;
  } catch (const std::exception& e) {
    std::cerr << lesson << ": " << e.what() << '\n';
    return false;
  }
}

std::string loadDroppedModel(const std::string& path, ParamRegistry& params, const std::string& lesson) {
  std::string status;
  try {
    const std::string assignment = modelSceneAssignment(params, lesson);
    const ModelFile& m = loadCurrentModel(path);
    params.assign(assignment);
    status = "model " + m.scene.name + ": " + std::to_string(m.scene.triangleCount()) + " triangles";
    reportNotes(m, lesson);
    if (!m.notes.empty()) status += " (" + m.notes.front() + ")";
  } catch (const std::exception& e) { status = e.what(); }
  std::cerr << lesson << ": " << status << '\n';
  return status;
}

void aimCameraAtModel(OrbitCamera& camera) {
  const ModelFraming f = frameModel(placeOnGround(*currentModel()), camera.fovY);
  camera.target = f.target;
  camera.distance = f.distance;
}

bool cameraSetOnCommandLine(const std::vector<std::string>& sets) {
  return std::any_of(sets.begin(), sets.end(), [](const std::string& a) {
    return a.rfind("camera.target", 0) == 0 || a.rfind("camera.distance", 0) == 0;
  });
}

}  // namespace shadowlab
