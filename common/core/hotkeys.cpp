#include "core/hotkeys.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <map>
#include <sstream>

namespace shadowlab {
namespace {

constexpr std::array<FrameworkKey, 8> kFrameworkKeys{{
    {"R", "reload shaders (a broken one keeps the last good program and shows its error)"},
    {"H", "hide the panels (labels and legends stay), then all UI, then bring it back (the projector)"},
    {"W", "fly camera: forward"},
    {"S", "fly camera: back"},
    {"A", "fly camera: left"},
    {"D", "fly camera: right"},
    {"Q", "fly camera: down"},
    {"E", "fly camera: up"},
}};

bool validKey(const std::string& k) {
  return k.size() == 1 && ((k[0] >= '0' && k[0] <= '9') || (k[0] >= 'A' && k[0] <= 'Z'));
}

bool numeric(const Param& p) { return p.kind == ParamKind::Float || p.kind == ParamKind::Int; }

// A number's hotkey toggles between 0 and its default: it needs both to differ and 0 in range.
std::string numberProblem(const Param& p) {
  if (std::strtod(p.defaultValue.c_str(), nullptr) == 0.0) return "its default is 0, so the key would toggle 0 <-> 0";
  if (p.min > 0 || p.max < 0)
    return "its range [" + std::to_string(p.min) + ", " + std::to_string(p.max) + "] excludes 0";
  return "";
}

}  // namespace

std::span<const FrameworkKey> frameworkKeys() { return kFrameworkKeys; }

std::string functionKeys(const std::string& separator) {
  static const char* const kKeys[] = {
      "F1 help",          "F2 stats",       "F3 parameters",     "F4 the reference's picture of the preset in view",
      "F11 fullscreen",   "F12 screenshot", "Ctrl +/- UI scale", "Tab camera orbit <-> fly",
      "Home camera reset"};
  std::string s;
  for (const char* k : kKeys) s += (s.empty() ? "" : separator) + k;
  return s;
}

std::string hotkeyAction(const Param& p) {
  switch (p.kind) {
    case ParamKind::Bool: return "toggle";
    case ParamKind::Choice: return "next choice";
    case ParamKind::Float:
    case ParamKind::Int: return numberProblem(p).empty() ? "0 <-> " + p.defaultValue : "";
    default: return "";
  }
}

std::vector<std::string> hotkeyProblems(const ParamRegistry& params) {
  std::vector<std::string> problems;
  std::map<std::string, std::string> owner;  // key -> the first parameter bound to it
  for (const FrameworkKey& k : kFrameworkKeys) owner[k.key] = std::string("the framework (") + k.action + ")";
  for (const Param& p : params.params()) {
    if (p.hotkey.empty()) continue;
    const std::string at = "hotkey '" + p.hotkey + "' of " + p.name + ": ";
    if (!validKey(p.hotkey)) {
      problems.push_back(at + "not a key; valid: 0-9, A-Z");
      continue;
    }
    if (const auto it = owner.find(p.hotkey); it != owner.end()) {
      problems.push_back(at + "already bound to " + it->second);
      continue;
    }
    owner[p.hotkey] = p.name;
    if (numeric(p)) {
      if (const std::string why = numberProblem(p); !why.empty()) problems.push_back(at + why);
    } else if (p.kind != ParamKind::Bool && p.kind != ParamKind::Choice) {
      problems.push_back(at + "a key can drive a bool, a choice or a number, not a vector or colour");
    }
  }
  return problems;
}

bool applyHotkey(ParamRegistry& params, const std::string& key) {
  for (const Param& p : params.params()) {
    if (p.hotkey != key) continue;
    if (p.kind == ParamKind::Bool) {
      params.set(p.name, params.get(p.name) == "true" ? "false" : "true");
    } else if (p.kind == ParamKind::Choice) {
      const int i = choiceIndex(p);
      params.set(p.name, p.choices[std::size_t(i + 1) % p.choices.size()]);
    } else if (!hotkeyAction(p).empty()) {  // a number: 0 <-> its default
      params.set(p.name, std::strtod(params.get(p.name).c_str(), nullptr) == 0.0 ? p.defaultValue : "0");
    }
    return true;
  }
  return false;
}

std::string describeHotkeys(const ParamRegistry& params) {
  std::ostringstream out;
  for (const FrameworkKey& k : kFrameworkKeys) out << k.key << "  (framework)  " << k.action << '\n';
  out << "F1  (framework)  " << functionKeys(";  ").substr(3) << '\n';
  std::vector<const Param*> bound;
  for (const Param& p : params.params())
    if (!p.hotkey.empty()) bound.push_back(&p);
  std::stable_sort(bound.begin(), bound.end(), [](const Param* a, const Param* b) { return a->hotkey < b->hotkey; });
  for (const Param* p : bound) out << p->hotkey << "  " << p->name << "  " << hotkeyAction(*p) << '\n';
  return out.str();
}

}  // namespace shadowlab
