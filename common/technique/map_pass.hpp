#pragma once
// One light's depth pass, or its reuse. A map last drawn from the same PassKey (a still camera, a
// still light, a static scene) stays as it is: its cost counts as kept ("maps reused" in the
// header) and draw() is false. Otherwise the key is remembered and, until this object goes out of
// scope, what the pass draws is recorded beside the map (the frames that keep it report that) and
// timed as "shadow light<i>". Every map technique's pass starts with one:
//   const MapPass pass(c, stats_, i, p_.reuseMaps, passKey(c, l), l.rendered, l.drawn);
//   if (!pass.draw()) return;
#include <optional>
#include <string>

#include "gl/timer.hpp"
#include "technique/pass_key.hpp"
#include "technique/technique.hpp"

namespace shadowlab::tech {

class MapPass {
 public:
  // light < 0: not timed (the caller times a pass of several lights). maps: how many maps a kept
  // pass holds.
  MapPass(const ShadowContext& c, ShadowStats& stats, int light, bool reuse, PassKey key, PassKey& rendered,
          DrawnFigures& drawn, int maps = 1) {
    if (reuse && key == rendered) {
      stats.keep(drawn, maps);
      return;
    }
    rendered = std::move(key);
    recorder_.emplace(stats, drawn);
    if (light >= 0) timer_.emplace(c.timers, "shadow light" + std::to_string(light));
  }
  bool draw() const { return recorder_.has_value(); }

 private:
  std::optional<ShadowStats::Recorder> recorder_;
  std::optional<gl::TimerScope> timer_;
};

}  // namespace shadowlab::tech
