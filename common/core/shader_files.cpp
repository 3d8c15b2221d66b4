#include "core/shader_files.hpp"

#include <map>
#include <mutex>
#include <set>

#include "core/sealed_files.hpp"

namespace shadowlab {
namespace {
std::mutex g_mutex;
std::map<std::string, std::string>& registered() {
  static std::map<std::string, std::string> texts;
  return texts;
}
std::set<std::string>& replaced() {
  static std::set<std::string> paths;
  return paths;
}
std::set<std::string>& drawn() {
  static std::set<std::string> paths;
  return paths;
}
}  // namespace

void registerShaderText(const std::string& relativePath, std::string text) {
  std::lock_guard<std::mutex> lock(g_mutex);
  registered()[relativePath] = std::move(text);
}

std::optional<std::string> virtualShaderText(const std::string& relativePath) {
  {
    std::lock_guard<std::mutex> lock(g_mutex);
    const auto it = registered().find(relativePath);
    if (it != registered().end()) return it->second;
  }
  std::size_t count = 0;
  const sealed::File* files = sealed::files(count);
  for (std::size_t f = 0; f < count; ++f) {
    if (relativePath != files[f].path) continue;
    std::string text(files[f].size, '\0');
    for (std::size_t i = 0; i < files[f].size; ++i) text[i] = char(files[f].bytes[i] ^ sealed::keystream(i));
    return text;
  }
  return std::nullopt;
}

bool shaderWithheld(const std::string& relativePath) {
  std::size_t count = 0;
  const char* const* paths = sealed::withheld(count);
  for (std::size_t i = 0; i < count; ++i)
    if (relativePath == paths[i]) return true;
  return false;
}

std::string withheldStandIn(const std::string& relativePath) {
  const auto slash = relativePath.rfind('/');
  return (slash == std::string::npos ? std::string() : relativePath.substr(0, slash + 1)) + "exercises.glsl";
}

void noteWithheldReplaced(const std::string& relativePath) {
  std::lock_guard<std::mutex> lock(g_mutex);
  replaced().insert(relativePath);
}

std::vector<std::string> withheldReplaced() {
  std::lock_guard<std::mutex> lock(g_mutex);
  return {replaced().begin(), replaced().end()};
}

void noteWithheldDrawn(const std::vector<std::string>& relativePaths) {
  std::lock_guard<std::mutex> lock(g_mutex);
  drawn().insert(relativePaths.begin(), relativePaths.end());
}

std::vector<std::string> takeWithheldDrawn() {
  std::lock_guard<std::mutex> lock(g_mutex);
  std::vector<std::string> out(drawn().begin(), drawn().end());
  drawn().clear();
  return out;
}

}  // namespace shadowlab
