#pragma once
// Hotkeys, GL-free: which keys the framework keeps for itself, what a parameter's hotkey does for
// each kind of parameter, and the problems a lesson's bindings can have (a key bound twice, a key
// the framework owns, a kind a key cannot drive). Every lesson checks its registry at start-up and
// refuses to run with a problem; `--list-hotkeys` prints the table a lecturer reads (tests run it
// on every lesson).
#include <span>
#include <string>
#include <vector>

#include "core/params.hpp"

namespace shadowlab {

struct FrameworkKey {
  const char* key;     // as Param::hotkey spells keys: "R", "H", "W", ...
  const char* action;  // what it does, for the help text
};

// The letter keys the framework handles itself (windowed): shader reload, hide the UI and the fly
// camera's movement. Function keys, Tab, Home, Esc and Ctrl +/- are not letter keys.
std::span<const FrameworkKey> frameworkKeys();

// The function keys and the other non-letter keys, in words, joined by `separator` ("F1 help, F2
// stats, ..."): one list for --help, --list-hotkeys and the help window.
std::string functionKeys(const std::string& separator);

// What pressing `p.hotkey` does, in words ("toggle", "next choice", "0 <-> 0.5"); "" when the kind
// cannot be driven by a key.
std::string hotkeyAction(const Param& p);

// One line per problem, naming the key and the parameters: a key bound to two parameters, a key
// the framework owns, a key that is not 0-9 or A-Z, a vector or colour with a key, a number whose
// default is 0 (its key would toggle 0 <-> 0) or whose range excludes 0.
std::vector<std::string> hotkeyProblems(const ParamRegistry& params);

// Presses `key`: a bool toggles, a choice steps to the next, a number toggles between 0 and its
// default. Returns false when no parameter has that key.
bool applyHotkey(ParamRegistry& params, const std::string& key);

// The table of every key: the framework's, then the parameters' (key, parameter, action).
std::string describeHotkeys(const ParamRegistry& params);

}  // namespace shadowlab
