#include "core/params.hpp"

#include "core/decimal.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace shadowlab {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

std::string formatFloat(float v) {
  std::ostringstream os;
  os << std::setprecision(6) << v;
  return os.str();
}

bool parseFloat(const std::string& text, float& out) {
  const std::string t = trim(text);
  if (t.empty()) return false;
  return parseDecimal(t, out);
}

bool parseInt(const std::string& text, int& out) {
  const std::string t = trim(text);
  if (t.empty()) return false;
  auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), out);
  return ec == std::errc() && ptr == t.data() + t.size();
}

std::string kindName(const Param& p) {
  switch (p.kind) {
    case ParamKind::Float: return "float";
    case ParamKind::Int: return "int";
    case ParamKind::Bool: return "bool";
    case ParamKind::Choice: return "choice";
    case ParamKind::Vec3: return "vec3";
    case ParamKind::Color: return "color";
  }
  return "?";
}

std::string rangeText(const Param& p) {
  switch (p.kind) {
    case ParamKind::Float:
    case ParamKind::Vec3:
    case ParamKind::Color: return "[" + formatFloat(p.min) + ", " + formatFloat(p.max) + "]";
    case ParamKind::Int: return "[" + std::to_string(int(p.min)) + ", " + std::to_string(int(p.max)) + "]";
    case ParamKind::Bool: return "true|false";
    case ParamKind::Choice: {
      std::string s;
      for (const auto& c : p.choices) s += (s.empty() ? "" : "|") + c;
      return s;
    }
  }
  return "";
}

// A parameter's value as bytes: undoing a refused change restores it exactly (the text form keeps
// only six digits).
struct RawValue {
  unsigned char bytes[sizeof(glm::vec3)] = {};
  static std::size_t size(const Param& p) {
    switch (p.kind) {
      case ParamKind::Bool: return sizeof(bool);
      case ParamKind::Vec3:
      case ParamKind::Color: return sizeof(glm::vec3);
      default: return sizeof(int);  // float, int and choices are all 4 bytes
    }
  }
  static RawValue of(const Param& p) {
    RawValue v;
    std::memcpy(v.bytes, p.target, size(p));
    return v;
  }
  void restore(const Param& p) const { std::memcpy(p.target, bytes, size(p)); }
};

bool validName(const std::string& n) {
  if (n.empty()) return false;
  return std::all_of(n.begin(), n.end(),
                     [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '.'; });
}

}  // namespace

Param& ParamRegistry::insert(Param p) {
  if (!validName(p.name)) throw ParamError("parameter name '" + p.name + "' must be [a-z0-9_.]+");
  if (find(p.name)) throw ParamError("parameter '" + p.name + "' is registered twice");
  index_.emplace(p.name, params_.size());
  params_.push_back(std::move(p));
  params_.back().defaultValue = get(params_.back().name);
  return params_.back();
}

void ParamRegistry::setHotkey(const std::string& name, const std::string& key) {
  for (Param& p : params_)
    if (p.name == name) {
      p.hotkey = key;
      return;
    }
  throw ParamError("setHotkey: unknown parameter '" + name + "'");
}

Param& ParamRegistry::add(const std::string& name, float* v, float min, float max, const std::string& why) {
  return insert({name, why, ParamKind::Float, v, min, max});
}
Param& ParamRegistry::add(const std::string& name, int* v, int min, int max, const std::string& why) {
  return insert({name, why, ParamKind::Int, v, float(min), float(max)});
}
Param& ParamRegistry::add(const std::string& name, bool* v, const std::string& why) {
  return insert({name, why, ParamKind::Bool, v, 0, 1});
}
Param& ParamRegistry::add(const std::string& name, glm::vec3* v, float min, float max, const std::string& why) {
  return insert({name, why, ParamKind::Vec3, v, min, max});
}
Param& ParamRegistry::addColor(const std::string& name, glm::vec3* v, const std::string& why) {
  return insert({name, why, ParamKind::Color, v, 0, 1});
}
Param& ParamRegistry::addChoiceRaw(const std::string& name, int* v, std::vector<std::string> choices,
                                   const std::string& why) {
  if (choices.empty()) throw ParamError("parameter '" + name + "' has no choices");
  Param p{name, why, ParamKind::Choice, v, 0, float(choices.size() - 1)};
  p.choices = std::move(choices);
  return insert(std::move(p));
}

Param& ParamRegistry::addNumberChoice(const std::string& name, int* v, const std::vector<int>& values,
                                      const std::string& why) {
  if (values.empty()) throw ParamError("parameter '" + name + "' has no choices");
  Param p{name, why, ParamKind::Choice, v, 0, float(values.size() - 1)};
  for (int value : values) p.choices.push_back(std::to_string(value));
  p.values = values;
  return insert(std::move(p));
}

int choiceIndex(const Param& p) {
  const int v = *static_cast<const int*>(p.target);
  if (p.values.empty()) return v >= 0 && v < int(p.choices.size()) ? v : -1;
  const auto it = std::find(p.values.begin(), p.values.end(), v);
  return it == p.values.end() ? -1 : int(it - p.values.begin());
}

const Param* ParamRegistry::find(const std::string& name) const {
  const auto it = index_.find(name);
  return it == index_.end() ? nullptr : &params_[it->second];
}

const Param& ParamRegistry::require(const std::string& name) const {
  const Param* p = find(name);
  if (!p) throw ParamError("unknown parameter '" + name + "'; valid: " + names());
  return *p;
}

std::string ParamRegistry::names() const {
  std::vector<std::string> n;
  for (const auto& p : params_) n.push_back(p.name);
  return join(n);
}

std::string ParamRegistry::get(const std::string& name) const {
  const Param* p = &require(name);
  switch (p->kind) {
    case ParamKind::Float: return formatFloat(*static_cast<float*>(p->target));
    case ParamKind::Int: return std::to_string(*static_cast<int*>(p->target));
    case ParamKind::Bool: return *static_cast<bool*>(p->target) ? "true" : "false";
    case ParamKind::Choice: {
      const int i = choiceIndex(*p);
      return i >= 0 ? p->choices[std::size_t(i)] : std::to_string(*static_cast<int*>(p->target));
    }
    case ParamKind::Vec3:
    case ParamKind::Color: {
      const glm::vec3 v = *static_cast<glm::vec3*>(p->target);
      return formatFloat(v.x) + " " + formatFloat(v.y) + " " + formatFloat(v.z);
    }
  }
  return "";
}

void ParamRegistry::write(const Param& param, const std::string& rawValue) {
  const Param* p = &param;
  const std::string& name = param.name;
  const std::string value = trim(rawValue);
  auto bad = [&](const std::string& expected) {
    return ParamError("bad value '" + value + "' for " + name + " (" + kindName(*p) + "); valid: " + expected);
  };
  switch (p->kind) {
    case ParamKind::Float: {
      float f;
      if (!parseFloat(value, f) || f < p->min || f > p->max) throw bad(rangeText(*p));
      *static_cast<float*>(p->target) = f;
      break;
    }
    case ParamKind::Int: {
      int i;
      if (!parseInt(value, i) || i < int(p->min) || i > int(p->max)) throw bad(rangeText(*p));
      *static_cast<int*>(p->target) = i;
      break;
    }
    case ParamKind::Bool: {
      bool b;
      if (value == "true" || value == "1" || value == "on") b = true;
      else if (value == "false" || value == "0" || value == "off") b = false;
      else throw bad("true, false, 1, 0, on, off");
      *static_cast<bool*>(p->target) = b;
      break;
    }
    case ParamKind::Choice: {
      const auto it = std::find(p->choices.begin(), p->choices.end(), value);
      if (it == p->choices.end()) throw bad(join(p->choices));
      const int i = int(it - p->choices.begin());
      *static_cast<int*>(p->target) = p->values.empty() ? i : p->values[std::size_t(i)];
      break;
    }
    case ParamKind::Vec3:
    case ParamKind::Color: {
      std::istringstream is(value);
      std::string a, b, c, extra;
      is >> a >> b >> c;
      glm::vec3 v;
      const bool ok = parseFloat(a, v.x) && parseFloat(b, v.y) && parseFloat(c, v.z) && !(is >> extra);
      if (!ok || glm::any(glm::lessThan(v, glm::vec3(p->min))) || glm::any(glm::greaterThan(v, glm::vec3(p->max))))
        throw bad("three numbers in " + rangeText(*p) + ", e.g. '0.5 1 0'");
      *static_cast<glm::vec3*>(p->target) = v;
      break;
    }
  }
}

void ParamRegistry::set(const std::string& name, const std::string& value) {
  const Param& p = require(name);
  const RawValue before = RawValue::of(p);
  write(p, value);
  if (std::optional<ParamCheckError> failed = failingCheck(name)) {
    before.restore(p);
    throw *failed;
  }
  ++revision_;
}

void ParamRegistry::setAll(const ParamValues& values, std::size_t* failedAt) {
  std::vector<RawValue> before;
  before.reserve(params_.size());
  for (const Param& p : params_) before.push_back(RawValue::of(p));
  auto undo = [&] {
    for (std::size_t i = 0; i < params_.size(); ++i) before[i].restore(params_[i]);
  };
  std::size_t i = 0;
  try {
    for (; i < values.size(); ++i) write(require(values[i].first), values[i].second);
  } catch (const ParamError&) {
    undo();
    if (failedAt) *failedAt = i;
    throw;
  }
  if (std::optional<ParamCheckError> failed = failingCheck("")) {
    undo();
    throw *failed;
  }
  ++revision_;
}

void ParamRegistry::restore(const std::map<std::string, std::string>& saved) {
  setAll(ParamValues(saved.begin(), saved.end()));
}

void ParamRegistry::addCheck(std::vector<std::string> reads, ParamCheck check) {
  for (const std::string& name : reads) require(name);
  checks_.push_back({std::move(reads), std::move(check)});
}

std::optional<ParamCheckError> ParamRegistry::failingCheck(const std::string& name) const {
  for (const Check& c : checks_) {
    if (!name.empty() && std::find(c.reads.begin(), c.reads.end(), name) == c.reads.end()) continue;
    if (std::string why = c.check(*this); !why.empty()) return ParamCheckError(why, c.reads);
  }
  return std::nullopt;
}

void ParamRegistry::validate() const {
  if (std::optional<ParamCheckError> failed = failingCheck("")) throw *failed;
}

namespace {
std::pair<std::string, std::string> splitAssignment(const std::string& assignment, const std::string& names) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos) throw ParamError("'" + assignment + "' is not name=value; parameters: " + names);
  return {trim(assignment.substr(0, eq)), assignment.substr(eq + 1)};
}
}  // namespace

void ParamRegistry::assign(const std::string& assignment) {
  const auto [name, value] = splitAssignment(assignment, names());
  set(name, value);
}

void ParamRegistry::assignAll(const std::vector<std::string>& assignments) {
  ParamValues values;
  for (const std::string& a : assignments) values.push_back(splitAssignment(a, names()));
  setAll(values);
}

void ParamRegistry::resetDefaults() {
  ParamValues defaults;
  for (const auto& p : params_) defaults.emplace_back(p.name, p.defaultValue);
  setAll(defaults);
}

std::map<std::string, std::string> ParamRegistry::snapshot() const {
  std::map<std::string, std::string> out;
  for (const auto& p : params_) out[p.name] = get(p.name);
  return out;
}

ParamValues ParamRegistry::changed() const {
  ParamValues out;
  for (const auto& p : params_) {
    std::string v = get(p.name);
    if (v != p.defaultValue) out.emplace_back(p.name, std::move(v));
  }
  return out;
}

std::string ParamRegistry::describe() const {
  std::ostringstream os;
  for (const auto& p : params_) {
    os << std::left << std::setw(26) << p.name << ' ' << std::setw(7) << kindName(p) << ' ' << std::setw(24)
       << rangeText(p) << " default " << std::setw(10) << p.defaultValue << "  " << p.why << '\n';
  }
  return os.str();
}

// ---- presets ------------------------------------------------------------------------------------

PresetFile PresetFile::load(const std::string& path) {
  std::ifstream in(path);
  if (!in) {
    PresetFile none;
    none.path = path;
    return none;
  }
  return read(in, path);
}

PresetFile PresetFile::read(std::istream& in, const std::string& path) {
  PresetFile file;
  file.path = path;
  std::unordered_map<std::string, int> headers;  // name -> line: duplicates found in O(1)
  std::string line;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    auto where = [&] { return path + ":" + std::to_string(lineNo) + ": "; };
    if (t.front() == '[') {
      if (t.back() != ']') throw ParamError(where() + "preset header '" + t + "' must be [name]");
      const std::string name = trim(t.substr(1, t.size() - 2));
      if (name.empty() || !std::all_of(name.begin(), name.end(), [](char c) {
            return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
          }))
        throw ParamError(where() + "preset name '" + name + "' must be [a-z0-9_]+");
      if (const auto [it, fresh] = headers.emplace(name, lineNo); !fresh)
        throw ParamError(where() + "preset '" + name + "' is defined twice (first on line " +
                         std::to_string(it->second) + ")");
      file.presets.push_back({name, {}, lineNo});
      continue;
    }
    const auto eq = t.find('=');
    if (eq == std::string::npos) throw ParamError(where() + "expected 'name = value' or [preset], got '" + t + "'");
    if (file.presets.empty()) throw ParamError(where() + "'" + t + "' comes before any [preset] header");
    file.presets.back().values.push_back({trim(t.substr(0, eq)), trim(t.substr(eq + 1)), lineNo});
  }
  return file;
}

namespace {
// "file:line: in preset 'name': why" for the value on `line` (0: the preset's header).
ParamError presetError(const std::string& path, const Preset& preset, int line, const std::string& why) {
  return ParamError(path + ":" + std::to_string(line > 0 ? line : preset.line) + ": in preset '" + preset.name +
                    "': " + why);
}

// The line of the preset's last value that a failed check reads (0 when it sets none of them).
int lineOfCheck(const Preset& preset, const ParamCheckError& e) {
  int line = 0;
  for (const PresetValue& v : preset.values)
    if (std::find(e.names.begin(), e.names.end(), v.name) != e.names.end()) line = v.line;
  return line;
}

ParamValues valuesOf(const Preset& preset) {
  ParamValues out;
  out.reserve(preset.values.size());
  for (const PresetValue& v : preset.values) out.emplace_back(v.name, v.value);
  return out;
}
}  // namespace

void PresetFile::validate(const ParamRegistry& registry) const {
  // Each preset over the defaults on a scratch registry state, put back as it was at the end.
  auto& reg = const_cast<ParamRegistry&>(registry);
  const auto saved = registry.snapshot();
  try {
    for (const auto& preset : presets) applyPreset(preset, reg);
  } catch (const ParamError&) {
    reg.restore(saved);
    throw;
  }
  reg.restore(saved);
}

const Preset* PresetFile::find(const std::string& name) const {
  for (const auto& p : presets)
    if (p.name == name) return &p;
  return nullptr;
}

std::vector<std::string> PresetFile::names() const {
  std::vector<std::string> out;
  for (const auto& p : presets) out.push_back(p.name);
  return out;
}

void PresetFile::apply(const std::string& name, ParamRegistry& registry) const {
  const Preset* preset = find(name);
  if (!preset) {
    throw ParamError("unknown preset '" + name + "'" + (path.empty() ? "" : " in " + path) +
                     "; valid: " + (presets.empty() ? std::string("(none)") : join(names())));
  }
  applyPreset(*preset, registry);
}

void PresetFile::applyPreset(const Preset& p, ParamRegistry& registry) const {
  const Preset* preset = &p;
  ParamValues values;
  for (const Param& p : registry.params()) values.emplace_back(p.name, p.defaultValue);
  const ParamValues own = valuesOf(*preset);
  values.insert(values.end(), own.begin(), own.end());
  std::size_t failed = 0;
  try {
    registry.setAll(values, &failed);  // the defaults, then the preset: one change, checked once
  } catch (const ParamCheckError& e) {
    throw ParamCheckError(presetError(path, *preset, lineOfCheck(*preset, e), e.what()).what(), e.names);
  } catch (const ParamError& e) {
    const std::size_t defaults = values.size() - own.size();
    throw presetError(path, *preset, failed >= defaults ? preset->values[failed - defaults].line : 0, e.what());
  }
}

void PresetFile::capture(const std::string& name, const ParamRegistry& registry) {
  Preset p{name, {}, 0};
  for (auto& [param, value] : registry.changed()) p.values.push_back({param, std::move(value), 0});
  for (auto& existing : presets) {
    if (existing.name == name) {
      p.line = existing.line;
      existing = std::move(p);
      return;
    }
  }
  presets.push_back(std::move(p));
}

void PresetFile::save(const std::string& target) const {
  std::ofstream out(target);
  if (!out) throw ParamError("cannot write presets to " + target);
  out << "# Presets: named snapshots of camera, light and parameters. Values not listed keep their\n"
         "# defaults. Saved from the lesson's UI; edit freely ([name], then name = value lines).\n";
  for (const auto& p : presets) {
    out << "\n[" << p.name << "]\n";
    for (const PresetValue& v : p.values) out << v.name << " = " << v.value << '\n';
  }
  out.close();
  if (!out) throw ParamError("cannot write presets to " + target + ": " + std::strerror(errno));
}

std::string ParamRegistry::groupOf(const std::string& name) {
  const auto dot = name.find('.');
  return dot == std::string::npos ? std::string() : name.substr(0, dot);
}

std::vector<const Param*> ParamRegistry::panelOrder() const {
  std::vector<std::string> groups{""};
  for (const Param& p : params_)
    if (!p.hidden && std::find(groups.begin(), groups.end(), groupOf(p.name)) == groups.end())
      groups.push_back(groupOf(p.name));
  std::vector<const Param*> order;
  for (const std::string& g : groups)
    for (const Param& p : params_)
      if (!p.hidden && groupOf(p.name) == g) order.push_back(&p);
  return order;
}

}  // namespace shadowlab
