#pragma once
// The lecturer's own model in a lesson: --model FILE and files dropped on the window load it as the
// process's current model (core/model_file) and pick scene=model (technique/scene_cache).
#include <string>
#include <vector>

#include "core/camera.hpp"
#include "core/params.hpp"

namespace shadowlab {

// "scene=model" for a registry whose `scene` choice has "model"; otherwise throws CliError naming
// the lesson.
std::string modelSceneAssignment(const ParamRegistry& params, const std::string& lesson);
// Whether `scene` is set to "model".
bool sceneIsModel(const ParamRegistry& params);
// Loads `path` as the current model and prints its notes on stderr, one line ("lesson: model 'FILE': a; b").
// Returns false after printing the ModelError (the run exits 1).
bool loadModelReporting(const std::string& path, const std::string& lesson);
// A dropped file: loads it and sets scene=model; the status line to show (the error when it failed:
// a window keeps running on the previous scene).
std::string loadDroppedModel(const std::string& path, ParamRegistry& params, const std::string& lesson);
// A model made the scene (--model, a dropped file): the camera looks at the current model from where
// it fills most of the view (core/model_file's frameModel), its yaw and pitch kept.
void aimCameraAtModel(OrbitCamera& camera);
// Whether the command line's --set assignments place the camera (camera.target or camera.distance),
// which then wins over aiming at the model.
bool cameraSetOnCommandLine(const std::vector<std::string>& sets);

}  // namespace shadowlab
