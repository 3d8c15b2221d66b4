#pragma once
// Recorded camera and light paths: a lesson records keyframes while the user moves, a benchmark
// replays them so every technique sees the same frames.
//
// Text format (one keyframe a line, whitespace-separated, '#' starts a comment):
//   shadowlab-path 1
//   key <time> <camera position xyz> <camera target xyz> <light position xyz> <light direction xyz>
// Times in seconds, strictly increasing. The light direction is the direction light travels
// (Light::direction) and must not be zero; it is normalised on load (in double, so 1e300 and
// 1e-30 work). Positions and targets lie within +-kMaxPathCoordinate, and the camera is not at its
// target. The header is exactly 'shadowlab-path 1'.
#include <iosfwd>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace shadowlab::measure {

// Past this a float position has lost the precision a camera needs (and 1e300 is inf).
inline constexpr double kMaxPathCoordinate = 1e6;

struct PathKey {
  double time = 0.0;
  glm::vec3 cameraPosition{0.0f, 2.0f, 8.0f};
  glm::vec3 cameraTarget{0.0f};
  glm::vec3 lightPosition{0.0f, 8.0f, 0.0f};
  glm::vec3 lightDirection{0.0f, -1.0f, 0.0f};
  bool operator==(const PathKey&) const = default;
};

class CameraLightPath {
 public:
  // Appends a key; throws std::invalid_argument unless its time is finite and after the last
  // key's, its positions are within kMaxPathCoordinate, the camera is not at its target and the
  // light direction is non-zero (naming the values).
  void add(const PathKey& key);
  const std::vector<PathKey>& keys() const { return keys_; }
  bool empty() const { return keys_.empty(); }
  double duration() const { return keys_.empty() ? 0.0 : keys_.back().time - keys_.front().time; }

  // The pose at `time`: positions and target interpolated linearly between neighbouring keys, the
  // light direction along the great arc (slerp); clamped to the first/last key outside the path.
  // Throws std::logic_error on an empty path.
  PathKey sample(double time) const;
  // `frames` poses evenly spaced from the first to the last key (both included; 1 frame: the first).
  std::vector<PathKey> resample(int frames) const;

  void write(std::ostream& out) const;
  void save(const std::string& path) const;  // throws std::runtime_error naming the path
  // Parse errors throw std::runtime_error as "<name>:<line>: <what>".
  static CameraLightPath read(std::istream& in, const std::string& name);
  static CameraLightPath load(const std::string& path);

 private:
  std::vector<PathKey> keys_;
};

// --replay FILE[@T | @T0..T1]: the file, and which part of the path the frames show. A value naming
// an existing file is that file, '@' and all; else after the last '@' "T" holds the path at time T,
// "T0..T1" plays it from T0 to T1 (finite numbers >= 0, T1 > T0; e.g. a slow drift of a few
// frames for shimmer). Throws std::invalid_argument naming the text and the forms it accepts.
struct ReplaySpec {
  std::string file;
  double holdAt = -1.0;  // >= 0: hold there
  double from = -1.0;    // >= 0 (with `to`): play this span instead of the whole path
  double to = -1.0;
  // The path time of `frame` (of `frames`, <= 0 for a window that runs until closed; `clock`: the
  // seconds since it started), relative to the path's first key: the whole path or the span spread
  // over the frames, in real time in a window (a span then stops at its end).
  double timeAt(double duration, int frame, int frames, double clock) const;
};
ReplaySpec parseReplaySpec(const std::string& value);

}  // namespace shadowlab::measure
