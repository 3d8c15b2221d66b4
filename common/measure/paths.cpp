#include "measure/paths.hpp"

#include "core/decimal.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace shadowlab::measure {

namespace {

glm::vec3 slerp(glm::vec3 a, glm::vec3 b, float t) {
  a = glm::normalize(a);
  b = glm::normalize(b);
  float c = std::clamp(glm::dot(a, b), -1.0f, 1.0f);
  if (c > 0.9995f) return glm::normalize(a + t * (b - a));
  float angle = std::acos(c);
  if (angle > 3.14159f) {  // opposite directions: any great arc will do; pick one through a normal
    glm::vec3 axis = std::abs(a.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    glm::vec3 mid = glm::normalize(glm::cross(a, axis));
    return t < 0.5f ? slerp(a, mid, 2 * t) : slerp(mid, b, 2 * t - 1);
  }
  float s = std::sin(angle);
  return glm::normalize((std::sin((1 - t) * angle) / s) * a + (std::sin(t * angle) / s) * b);
}

std::string vecText(const glm::dvec3& v) {
  std::ostringstream o;
  o << "(" << v.x << ", " << v.y << ", " << v.z << ")";
  return o.str();
}

// Unit length for any finite non-zero vector: scaled by its largest component first, so neither
// 1e20 (whose square overflows a float) nor 1e-30 (whose square underflows) loses it.
glm::vec3 robustNormalize(const glm::dvec3& v) {
  const double scale = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  const glm::dvec3 s = v / scale;
  return glm::vec3(s / glm::length(s));
}

bool withinRange(const glm::dvec3& v) {
  return glm::all(glm::lessThanEqual(glm::abs(v), glm::dvec3(kMaxPathCoordinate)));
}

// One key's checks (CameraLightPath::add for floats, read() for the file's doubles).
void validateKey(double time, const glm::dvec3& camera, const glm::dvec3& target, const glm::dvec3& light,
                 const glm::dvec3& direction) {
  if (!std::isfinite(time))
    throw std::invalid_argument("CameraLightPath: key time " + std::to_string(time) + " is not finite");
  const std::pair<const char*, const glm::dvec3*> positions[] = {
      {"camera position", &camera}, {"camera target", &target}, {"light position", &light}};
  for (const auto& [what, v] : positions)
    if (!withinRange(*v))
      throw std::invalid_argument(std::string(what) + " " + vecText(*v) + " is outside +-" +
                                  std::to_string(int(kMaxPathCoordinate)));
  if (!(glm::length(target - camera) > 1e-6))
    throw std::invalid_argument("the camera at " + vecText(camera) + " is at its target " + vecText(target) +
                                ": a view needs a direction");
  const double scale = std::max({std::abs(direction.x), std::abs(direction.y), std::abs(direction.z)});
  if (!(scale > 0.0) || !std::isfinite(scale))
    throw std::invalid_argument("light direction " + vecText(direction) + " is not a direction");
}

}  // namespace

void CameraLightPath::add(const PathKey& key) {
  validateKey(key.time, key.cameraPosition, key.cameraTarget, key.lightPosition, key.lightDirection);
  if (!keys_.empty() && !(key.time > keys_.back().time))
    throw std::invalid_argument("CameraLightPath: key time " + std::to_string(key.time) +
                                " is not after the previous key's " + std::to_string(keys_.back().time));
  if (!keys_.empty()) {
    // Linear between the keys: the eye-to-target vector must not pass through zero on the way
    // (a replay would ask lookFrom for a view with no direction at that frame).
    const glm::dvec3 from = glm::dvec3(keys_.back().cameraTarget) - glm::dvec3(keys_.back().cameraPosition);
    const glm::dvec3 change = glm::dvec3(key.cameraTarget) - glm::dvec3(key.cameraPosition) - from;
    const double t =
        glm::dot(change, change) > 0.0 ? std::clamp(-glm::dot(from, change) / glm::dot(change, change), 0.0, 1.0) : 0.0;
    if (!(glm::length(from + t * change) > 1e-6))
      throw std::invalid_argument("between the previous key and this one the camera passes through its target (at " +
                                  std::to_string(int(t * 100.0 + 0.5)) + " % of the way)");
  }
  PathKey k = key;
  k.lightDirection = robustNormalize(key.lightDirection);
  keys_.push_back(k);
}

PathKey CameraLightPath::sample(double time) const {
  if (keys_.empty()) throw std::logic_error("CameraLightPath::sample: the path has no keys");
  if (!(time > keys_.front().time)) {
    PathKey k = keys_.front();
    k.time = time;
    return k;
  }
  if (!(time < keys_.back().time)) {
    PathKey k = keys_.back();
    k.time = time;
    return k;
  }
  auto next = std::upper_bound(keys_.begin(), keys_.end(), time, [](double t, const PathKey& k) { return t < k.time; });
  const PathKey& b = *next;
  const PathKey& a = *(next - 1);
  float t = float((time - a.time) / (b.time - a.time));
  PathKey out;
  out.time = time;
  out.cameraPosition = glm::mix(a.cameraPosition, b.cameraPosition, t);
  out.cameraTarget = glm::mix(a.cameraTarget, b.cameraTarget, t);
  out.lightPosition = glm::mix(a.lightPosition, b.lightPosition, t);
  out.lightDirection = slerp(a.lightDirection, b.lightDirection, t);
  return out;
}

std::vector<PathKey> CameraLightPath::resample(int frames) const {
  if (frames < 1) throw std::invalid_argument("CameraLightPath::resample: frames " + std::to_string(frames) + " < 1");
  if (keys_.empty()) throw std::logic_error("CameraLightPath::resample: the path has no keys");
  std::vector<PathKey> out;
  for (int i = 0; i < frames; ++i)
    out.push_back(
        sample(frames == 1 ? keys_.front().time : keys_.front().time + duration() * double(i) / double(frames - 1)));
  return out;
}

void CameraLightPath::write(std::ostream& out) const {
  out << "shadowlab-path 1\n"
      << "# key time  camera.xyz  target.xyz  light.xyz  lightDirection.xyz\n";
  auto v = [&](const glm::vec3& p) { out << ' ' << p.x << ' ' << p.y << ' ' << p.z; };
  out << std::setprecision(9);
  for (const PathKey& k : keys_) {
    out << "key " << std::setprecision(17) << k.time << std::setprecision(9);
    v(k.cameraPosition);
    v(k.cameraTarget);
    v(k.lightPosition);
    v(k.lightDirection);
    out << '\n';
  }
}

void CameraLightPath::save(const std::string& path) const {
  std::ofstream file(path);
  if (!file) throw std::runtime_error(path + ": cannot open for writing");
  write(file);
  file.flush();
  if (!file) throw std::runtime_error(path + ": write failed");
}

namespace {
// A finite decimal number and nothing else ("1x", "nan", "inf", "0x10" and "" are not).
bool parseFinite(const std::string& token, double& out) { return parseDecimal(token, out); }

// The key's 13 numbers, each finite: time, camera, target, light position, light direction.
std::array<double, 13> keyNumbers(std::istringstream& words, const std::function<void(const std::string&)>& fail) {
  std::array<double, 13> values{};
  for (int i = 0; i < 13; ++i) {
    std::string token;
    if (!(words >> token)) fail("key has " + std::to_string(i) + " numbers, expected 13 (time and four xyz triples)");
    if (!parseFinite(token, values[std::size_t(i)]))
      fail("'" + token + "' is not a finite number (field " + std::to_string(i + 1) + ")");
  }
  std::string extra;
  if (words >> extra) fail("unexpected '" + extra + "' after 13 numbers");
  return values;
}
}  // namespace

CameraLightPath CameraLightPath::read(std::istream& in, const std::string& name) {
  CameraLightPath path;
  std::string line;
  int number = 0;
  bool header = false;
  auto fail = [&](const std::string& what) {
    throw std::runtime_error(name + ":" + std::to_string(number) + ": " + what);
  };
  while (std::getline(in, line)) {
    ++number;
    if (auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    std::string word;
    if (!(words >> word)) continue;
    if (!header) {
      std::string version, extra;
      words >> version;
      if (word != "shadowlab-path" || version.empty() || (words >> extra))
        fail("expected 'shadowlab-path 1', got '" + line + "'");
      if (version != "1") fail("unsupported path version '" + version + "' (this reads version 1)");
      header = true;
      continue;
    }
    if (word != "key") fail("unknown record '" + word + "' (expected 'key')");
    const std::array<double, 13> v = keyNumbers(words, fail);
    auto vec = [&](std::size_t at) { return glm::dvec3(v[at], v[at + 1], v[at + 2]); };
    PathKey k;
    k.time = v[0];
    try {
      validateKey(v[0], vec(1), vec(4), vec(7), vec(10));  // in double: 1e300 never becomes inf
      k.cameraPosition = vec(1);
      k.cameraTarget = vec(4);
      k.lightPosition = vec(7);
      k.lightDirection = robustNormalize(vec(10));
      path.add(k);
    } catch (const std::invalid_argument& e) { fail(e.what()); }
  }
  if (!header) {
    number = std::max(number, 1);
    fail("empty file: expected 'shadowlab-path 1'");
  }
  return path;
}

CameraLightPath CameraLightPath::load(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw std::runtime_error(path + ": cannot open for reading");
  return read(file, path);
}

ReplaySpec parseReplaySpec(const std::string& value) {
  std::error_code ec;
  const auto at = value.rfind('@');
  if (at == std::string::npos || std::filesystem::exists(value, ec)) return {value};
  const std::string time = value.substr(at + 1);
  const auto dots = time.find("..");
  ReplaySpec spec{value.substr(0, at)};
  if (dots == std::string::npos) {
    if (!parseFinite(time, spec.holdAt) || spec.holdAt < 0.0)
      throw std::invalid_argument("'" + time +
                                  "' after '@' is not a time >= 0 in seconds (FILE@T holds the path at T, "
                                  "FILE@T0..T1 plays it from T0 to T1)");
    return spec;
  }
  const std::string a = time.substr(0, dots), b = time.substr(dots + 2);
  if (!parseFinite(a, spec.from) || !parseFinite(b, spec.to) || spec.from < 0.0 || !(spec.to > spec.from))
    throw std::invalid_argument("'" + time +
                                "' after '@' is not a span T0..T1 of times in seconds with 0 <= T0 < T1 "
                                "(FILE@T0..T1 plays the path from T0 to T1 over the frames)");
  return spec;
}

double ReplaySpec::timeAt(double duration, int frame, int frames, double clock) const {
  if (holdAt >= 0.0) return holdAt;
  const double start = from >= 0.0 ? from : 0.0, end = from >= 0.0 ? to : duration;
  if (frames > 1) return start + (end - start) * double(frame) / double(frames - 1);
  return from >= 0.0 ? std::min(start + clock, end) : clock;
}

}  // namespace shadowlab::measure
