#pragma once
// One parameter registry per lesson. Each field of a lesson's Params is registered once, with its
// range and a one-line why; the registry then drives the UI (common/app/ui), the command line
// (--set name=value, --list-params), presets (named snapshots in a text file) and tests.
#include <functional>
#include <iosfwd>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

namespace shadowlab {

// Bad names, values or preset files. what() is a one-line message naming the value and the valid
// choices; the command line turns it into exit code 2.
struct ParamError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A rule over values that each pass their own range but can be degenerate together: a light
// direction of 0 0 0, attenuation 0 0 0, camera.near >= camera.far. Returns "" when the current
// values are fine, else one line naming the parameter, its value and what is wrong.
class ParamRegistry;
using ParamCheck = std::function<std::string(const ParamRegistry&)>;

// The ParamError of a failed check, with the parameters the check reads (presets use them to
// name the line that set one).
struct ParamCheckError : ParamError {
  ParamCheckError(const std::string& message, std::vector<std::string> checked)
      : ParamError(message), names(std::move(checked)) {}
  std::vector<std::string> names;
};

using ParamValues = std::vector<std::pair<std::string, std::string>>;  // (name, value text), in order

enum class ParamKind { Float, Int, Bool, Choice, Vec3, Color };

struct Param {
  std::string name;  // dotted, e.g. "light1.intensity"
  std::string why;   // one line: why the parameter exists, shown as the UI tooltip
  ParamKind kind = ParamKind::Float;
  void* target = nullptr;
  float min = 0, max = 1;            // Float, Int, Vec3 range (inclusive)
  std::vector<std::string> choices;  // Choice
  std::vector<int> values;           // Choice: the number each choice stores (empty: its index)
  std::string defaultValue;          // captured at registration, in text form
  bool hidden = false;               // camera and light poses: in presets, not in the panel
  std::string hotkey;                // "" or a key name shown in help ("1".."9", "B", ...)
};

// A Choice's position in its list for the value it stores (-1: none of them).
int choiceIndex(const Param& p);

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

  // A number picked from a list (texels per side: 256, 512, ...): the stored value is the number
  // itself, never an index; any other number is refused by name with the valid ones.
  Param& addNumberChoice(const std::string& name, int* v, const std::vector<int>& values, const std::string& why);

  // Binds a hotkey to a registered parameter (a holder's choice, e.g. for a technique's parameters).
  // Throws ParamError for an unknown name.
  void setHotkey(const std::string& name, const std::string& key);

  const std::vector<Param>& params() const { return params_; }
  // The visible parameters in the order the UI's panel lists them: the ungrouped ones first, then
  // each group (the name before its first dot) in the order of its first parameter, its members
  // together in declaration order, so that no parameter shows under another group's header.
  std::vector<const Param*> panelOrder() const;
  // The group a parameter's name puts it in: the part before its first dot ("" for none).
  static std::string groupOf(const std::string& name);
  const Param* find(const std::string& name) const;
  bool has(const std::string& name) const { return find(name) != nullptr; }

  // Text form of the current value ("0.5", "true", "spot", "1 0.5 0").
  std::string get(const std::string& name) const;
  // Parses and range-checks `value`, then runs the checks that read `name`; throws ParamError
  // naming the parameter, the value and the valid range or choices (or the check's message).
  // Nothing is changed when it throws. The UI, --set, presets and tests all come through here.
  void set(const std::string& name, const std::string& value);
  // Several values as one change: each is parsed and range-checked, then every check runs once
  // on the result, so the order does not matter (camera.far=0.05 then camera.near=0.01). On any
  // error every value is restored and ParamError is thrown (a bad value's index in `failedAt`).
  void setAll(const ParamValues& values, std::size_t* failedAt = nullptr);
  // "name=value"
  void assign(const std::string& assignment);
  // Several "name=value" as one change (setAll): --set on the command line.
  void assignAll(const std::vector<std::string>& assignments);
  void resetDefaults();
  std::map<std::string, std::string> snapshot() const;
  // The values that differ from the defaults, in registration order: what a preset saves and what
  // "copy link" puts in the URL (assignAll of them on a fresh registry gives this state again).
  ParamValues changed() const;
  // Back to a snapshot(), as one change (see setAll).
  void restore(const std::map<std::string, std::string>& snapshot);

  // Registers a check over the parameters `reads` (each must be registered). Lessons add their
  // own next to their parameters; declareLight and declareCamera add the rig's.
  void addCheck(std::vector<std::string> reads, ParamCheck check);
  // Throws ParamCheckError with the first failing check's message.
  void validate() const;
  // A table for --list-params: name, type, range/choices, default, why.
  std::string describe() const;
  // Names joined for error messages ("a, b, c").
  std::string names() const;
  // Bumped on every successful set(); lessons compare it to know when to redo work.
  unsigned revision() const { return revision_; }
  void touch() { ++revision_; }

 private:
  struct Check {
    std::vector<std::string> reads;
    ParamCheck check;
  };
  Param& addChoiceRaw(const std::string& name, int* v, std::vector<std::string> choices, const std::string& why);
  Param& insert(Param p);
  const Param& require(const std::string& name) const;   // throws the unknown-parameter error
  void write(const Param& p, const std::string& value);  // parse + range, no checks
  // The first check failing among those reading `name` ("": all of them), as an exception to throw.
  std::optional<ParamCheckError> failingCheck(const std::string& name) const;
  std::vector<Param> params_;
  std::unordered_map<std::string, std::size_t> index_;  // name -> params_ position
  std::vector<Check> checks_;
  unsigned revision_ = 0;
};

// Named presets: snapshots of camera, light and parameters kept in one text file per lesson:
//   # comment
//   [three_lights]
//   light1.enabled = true
// Names are [a-z0-9_]+. Values not named in a preset keep their defaults.
struct PresetValue {
  std::string name, value;
  int line = 0;  // in the file, for error messages (0: captured, not read)
};

struct Preset {
  std::string name;
  std::vector<PresetValue> values;
  int line = 0;  // where its header is, for error messages
};

class PresetFile {
 public:
  // Missing file: no presets. Syntax errors throw ParamError "file:line: ...". Linear in the
  // file's size (100,000 presets load in well under a second).
  static PresetFile load(const std::string& path);
  // The same from a stream; `path` names it in messages.
  static PresetFile read(std::istream& in, const std::string& path);
  // Every value must name a registered parameter and parse, and every preset over the defaults
  // must pass the registry's checks: throws ParamError "file:line: ..." (a failed check names the
  // line of the preset's last value that the check reads, else the header).
  void validate(const ParamRegistry& registry) const;
  const Preset* find(const std::string& name) const;
  std::vector<std::string> names() const;
  // Resets the registry to its defaults, then applies the preset as one change (setAll). Unknown
  // name: ParamError listing the valid presets; a bad value or failed check restores everything.
  void apply(const std::string& name, ParamRegistry& registry) const;
  // Adds or replaces a preset holding every value that differs from its default.
  void capture(const std::string& name, const ParamRegistry& registry);
  void save(const std::string& path) const;

  std::vector<Preset> presets;
  std::string path;

 private:
  void applyPreset(const Preset& preset, ParamRegistry& registry) const;
};

}  // namespace shadowlab
