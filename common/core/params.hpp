#pragma once
// One parameter registry per lesson. Each field of a lesson's Params is registered once, with its
// range and a one-line why; the registry then drives the UI (common/app/ui), the command line
// (--set name=value, --list-params), presets (named snapshots in a text file) and tests.
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

namespace shadowlab {

// Bad names, values or preset files. what() is a one-line message naming the value and the valid
// choices; the command line turns it into exit code 2.
struct ParamError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class ParamKind { Float, Int, Bool, Choice, Vec3, Color };

struct Param {
  std::string name;  // dotted, e.g. "light1.intensity"
  std::string why;   // one line: why the parameter exists, shown as the UI tooltip
  ParamKind kind = ParamKind::Float;
  void* target = nullptr;
  float min = 0, max = 1;            // Float, Int, Vec3 range (inclusive)
  std::vector<std::string> choices;  // Choice
  std::string defaultValue;          // captured at registration, in text form
  bool hidden = false;               // camera and light poses: in presets, not in the panel
  std::string hotkey;                // "" or a key name shown in help ("1".."9", "B", ...)
};

class ParamRegistry {
 public:
  Param& add(const std::string& name, float* v, float min, float max, const std::string& why);
  Param& add(const std::string& name, int* v, int min, int max, const std::string& why);
  Param& add(const std::string& name, bool* v, const std::string& why);
  Param& add(const std::string& name, glm::vec3* v, float min, float max, const std::string& why);
  Param& addColor(const std::string& name, glm::vec3* v, const std::string& why);
  // An enum (or int) picked by name; the stored value is the index into `choices`.
  template <class E>
  Param& addChoice(const std::string& name, E* v, std::vector<std::string> choices, const std::string& why) {
    static_assert(sizeof(E) == sizeof(int), "choices are stored as int-sized enums");
    return addChoiceRaw(name, reinterpret_cast<int*>(v), std::move(choices), why);
  }

  // Binds a hotkey to a registered parameter (a holder's choice, e.g. for a technique's parameters).
  // Throws ParamError for an unknown name.
  void setHotkey(const std::string& name, const std::string& key);

  const std::vector<Param>& params() const { return params_; }
  const Param* find(const std::string& name) const;
  bool has(const std::string& name) const { return find(name) != nullptr; }

  // Text form of the current value ("0.5", "true", "spot", "1 0.5 0").
  std::string get(const std::string& name) const;
  // Parses and range-checks `value`; throws ParamError naming the parameter, the value and the
  // valid range or choices. Nothing is changed when it throws.
  void set(const std::string& name, const std::string& value);
  // "name=value"
  void assign(const std::string& assignment);
  void resetDefaults();
  std::map<std::string, std::string> snapshot() const;
  // A table for --list-params: name, type, range/choices, default, why.
  std::string describe() const;
  // Names joined for error messages ("a, b, c").
  std::string names() const;
  // Bumped on every successful set(); lessons compare it to know when to redo work.
  unsigned revision() const { return revision_; }
  void touch() { ++revision_; }

 private:
  Param& addChoiceRaw(const std::string& name, int* v, std::vector<std::string> choices, const std::string& why);
  Param& insert(Param p);
  std::vector<Param> params_;
  unsigned revision_ = 0;
};

// Named presets: snapshots of camera, light and parameters kept in one text file per lesson:
//   # comment
//   [three_lights]
//   light1.enabled = true
// Names are [a-z0-9_]+. Values not named in a preset keep their defaults.
struct Preset {
  std::string name;
  std::vector<std::pair<std::string, std::string>> values;
  int line = 0;  // where its header is, for error messages
};

class PresetFile {
 public:
  // Missing file: no presets. Syntax errors throw ParamError "file:line: ...".
  static PresetFile load(const std::string& path);
  // Every value must name a registered parameter and parse: throws ParamError "file:line: ...".
  void validate(const ParamRegistry& registry) const;
  const Preset* find(const std::string& name) const;
  std::vector<std::string> names() const;
  // Resets the registry to its defaults, then applies the preset. Unknown name: ParamError listing
  // the valid presets.
  void apply(const std::string& name, ParamRegistry& registry) const;
  // Adds or replaces a preset holding every value that differs from its default.
  void capture(const std::string& name, const ParamRegistry& registry);
  void save(const std::string& path) const;

  std::vector<Preset> presets;
  std::string path;
};

}  // namespace shadowlab
