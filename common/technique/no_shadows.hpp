#pragma once
// No shadows at all: V = 1 for every light, what lesson 01 draws. The baseline a showdown measures
// every technique against (every truly shadowed pixel is a light leak), and the smallest complete
// technique: docs/adding_a_technique.md starts from it.
#include "technique/technique.hpp"

namespace shadowlab::tech {

class NoShadows : public ShadowTechnique {
 public:
  std::string name() const override { return "none"; }
  void declare(ParamRegistry&, const std::string&) override {}  // nothing to set
  void init() override {}
  const ShadowStats& stats() const override { return stats_; }
  std::string visibilityShader() const override { return "common/shadow_none.frag"; }

 private:
  void render(const ShadowContext& c) override;
  ShadowStats stats_;
};

}  // namespace shadowlab::tech
