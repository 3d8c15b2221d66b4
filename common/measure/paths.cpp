#include "measure/paths.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
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

std::string vecText(const glm::vec3& v) {
  std::ostringstream o;
  o << "(" << v.x << ", " << v.y << ", " << v.z << ")";
  return o.str();
}

}  // namespace

void CameraLightPath::add(const PathKey& key) {
  if (!std::isfinite(key.time))
    throw std::invalid_argument("CameraLightPath: key time " + std::to_string(key.time) + " is not finite");
  if (!keys_.empty() && !(key.time > keys_.back().time))
    throw std::invalid_argument("CameraLightPath: key time " + std::to_string(key.time) +
                                " is not after the previous key's " + std::to_string(keys_.back().time));
  if (!(glm::length(key.lightDirection) > 0.0f))
    throw std::invalid_argument("CameraLightPath: light direction " + vecText(key.lightDirection) +
                                " is not a direction");
  PathKey k = key;
  k.lightDirection = glm::normalize(key.lightDirection);
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
      int version = 0;
      if (word != "shadowlab-path" || !(words >> version)) fail("expected 'shadowlab-path 1', got '" + line + "'");
      if (version != 1) fail("unsupported path version " + std::to_string(version));
      header = true;
      continue;
    }
    if (word != "key") fail("unknown record '" + word + "' (expected 'key')");
    // Parse numbers ourselves so "nan", "1x" and friends are rejected with the line.
    double values[13];
    for (int i = 0; i < 13; ++i) {
      std::string token;
      if (!(words >> token)) fail("key has " + std::to_string(i) + " numbers, expected 13 (time and four xyz triples)");
      char* end = nullptr;
      values[i] = std::strtod(token.c_str(), &end);
      if (end == token.c_str() || *end != '\0' || !std::isfinite(values[i]))
        fail("'" + token + "' is not a finite number (field " + std::to_string(i + 1) + ")");
    }
    std::string extra;
    if (words >> extra) fail("unexpected '" + extra + "' after 13 numbers");
    PathKey k;
    k.time = values[0];
    auto vec = [&](int at) { return glm::vec3(float(values[at]), float(values[at + 1]), float(values[at + 2])); };
    k.cameraPosition = vec(1);
    k.cameraTarget = vec(4);
    k.lightPosition = vec(7);
    k.lightDirection = vec(10);
    try {
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

}  // namespace shadowlab::measure
