#pragma once
// The techniques a lesson picks by name: lesson 05's soft ones (lessons/05_soft_shadows/
// soft_techniques) and the showdown's every one (lessons/10_showdown/showdown_techniques). An entry
// says what the technique is called (the `technique` choice, and the prefix of its parameters: pcss
// -> pcss.filter_taps), how to make one, and the showdown's preset that shows it. Adding a
// technique to the showdown is its files and one entry; the test gpu.registry checks that every
// entry renders, has its preset and is in the benchmark (tools/showdown_bench.sh).
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "technique/technique.hpp"

namespace shadowlab::tech {

struct TechniqueEntry {
  std::string name;                                        // "pcss": technique=pcss, parameters pcss.*
  std::function<std::unique_ptr<ShadowTechnique>()> make;  // a new one, with the lesson's defaults
  std::string preset;                                      // the showdown's preset that shows it
};

// One of each entry's technique, made once and kept in the entries' order.
class TechniqueSet {
 public:
  explicit TechniqueSet(std::vector<TechniqueEntry> entries) : entries_(std::move(entries)) {
    for (const TechniqueEntry& e : entries_) techniques_.push_back(e.make());
  }
  int size() const { return int(techniques_.size()); }
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const TechniqueEntry& e : entries_) out.push_back(e.name);
    return out;
  }
  const TechniqueEntry& entry(int i) const { return entries_.at(std::size_t(i)); }
  // The position of the technique named `name` (a lesson's default choice); throws for a name the set lacks.
  int indexOf(const std::string& name) const {
    for (std::size_t i = 0; i < entries_.size(); ++i)
      if (entries_[i].name == name) return int(i);
    throw std::logic_error("TechniqueSet: no technique '" + name + "'");
  }
  ShadowTechnique& operator[](int i) { return *techniques_.at(std::size_t(i)); }
  const ShadowTechnique& operator[](int i) const { return *techniques_.at(std::size_t(i)); }
  // The technique named `name` as its own class, for what only that class has (csm.splitter,
  // psm.drawMaps). A name the set lacks, or another class, is a programming error: it throws.
  template <class T>
  T& get(const std::string& name) {
    for (std::size_t i = 0; i < entries_.size(); ++i)
      if (entries_[i].name == name)
        if (T* t = dynamic_cast<T*>(techniques_[i].get())) return *t;
    throw std::logic_error("TechniqueSet: no technique '" + name + "' of the class asked for");
  }
  // Each technique's parameters under its own name ("pcss." ...), and its GL resources.
  void declare(ParamRegistry& r) {
    for (std::size_t i = 0; i < entries_.size(); ++i) techniques_[i]->declare(r, entries_[i].name + ".");
  }
  void init() {
    for (auto& t : techniques_) t->init();
  }

 private:
  std::vector<TechniqueEntry> entries_;
  std::vector<std::unique_ptr<ShadowTechnique>> techniques_;
};

// An entry whose technique is T made from `args` (copied into every one it makes).
template <class T, class... Args>
TechniqueEntry entryOf(std::string name, std::string preset, Args... args) {
  return {std::move(name), [=] { return std::unique_ptr<ShadowTechnique>(new T(args...)); }, std::move(preset)};
}

}  // namespace shadowlab::tech
