// The teaching moments of the lesson READMEs' "What to try", checked as a lecturer would see them:
// each a before/after pair rendered in the lit view, which must differ where the moment is.
//   moment_check MOMENTS_FILE BIN_DIR OUT_DIR [--lesson NN_name] [--size WxH]
// MOMENTS_FILE (tests/data/moments.txt): one moment a line, fields split at '|':
//   lesson | what | before args | after args | x0 y0 x1 y1 | min %
// The lesson (BIN_DIR/lesson_NN_name) runs twice, `--headless --strict-gl --frames 3 --size WxH`
// (640x360 unless --size) plus each side's args, and writes OUT_DIR/NN_name_<k>_{before,after}.png.
// In the region (fractions of the frame, x0 y0 the top left corner) a pixel differs when a channel
// moves by more than 24 levels of 255 (about a tenth of the range: seen from across a room, not
// noise); the share of such pixels must reach `min %`. Exit 1 naming every moment below its bound
// (with the share measured), the file and line of a malformed moment, or a lesson that failed.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/image.hpp"
#include "core/process.hpp"

namespace fs = std::filesystem;

namespace {

constexpr int kLevels = 24;  // a channel must move by more than this to count as a visible change

struct Moment {
  int line = 0;
  std::string lesson, what;
  std::vector<std::string> before, after;
  double x0 = 0, y0 = 0, x1 = 1, y1 = 1, minShare = 0;
};

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

// Words split at blanks; "a b c" in double quotes is one word (a vec3 value: light0.direction="0 -1 0").
std::vector<std::string> words(const std::string& s) {
  std::vector<std::string> out;
  std::string w;
  bool quoted = false, any = false;
  for (const char c : s) {
    if (c == '"') quoted = !quoted, any = true;
    else if ((c == ' ' || c == '\t') && !quoted) {
      if (any) out.push_back(w);
      w.clear();
      any = false;
    } else w += c, any = true;
  }
  if (any) out.push_back(w);
  return out;
}

// Parses the file; throws std::runtime_error "FILE:LINE: reason".
std::vector<Moment> readMoments(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read moments file '" + path + "'");
  std::vector<Moment> out;
  std::string text;
  for (int n = 1; std::getline(in, text); ++n) {
    if (trim(text).empty() || trim(text)[0] == '#') continue;
    const auto fail = [&](const std::string& why) {
      return std::runtime_error(path + ":" + std::to_string(n) + ": " + why +
                                " (a moment is: lesson | what | before args | after args | x0 y0 x1 y1 | min %)");
    };
    if (std::count(text.begin(), text.end(), '"') % 2) throw fail("an unclosed \"");
    std::vector<std::string> f;
    std::stringstream s(text);
    for (std::string field; std::getline(s, field, '|');) f.push_back(trim(field));
    if (f.size() != 6) throw fail(std::to_string(f.size()) + " fields, not 6");
    Moment m;
    m.line = n;
    m.lesson = f[0];
    m.what = f[1];
    m.before = words(f[2]);
    m.after = words(f[3]);
    const std::vector<std::string> r = words(f[4]);
    char* end = nullptr;
    auto number = [&](const std::string& w) {
      const double v = std::strtod(w.c_str(), &end);
      if (end == w.c_str() || *end != '\0') throw fail("'" + w + "' is not a number");
      return v;
    };
    if (r.size() != 4) throw fail("the region has " + std::to_string(r.size()) + " numbers, not 4");
    m.x0 = number(r[0]), m.y0 = number(r[1]), m.x1 = number(r[2]), m.y1 = number(r[3]);
    if (!(0 <= m.x0 && m.x0 < m.x1 && m.x1 <= 1 && 0 <= m.y0 && m.y0 < m.y1 && m.y1 <= 1))
      throw fail("the region must be 0 <= x0 < x1 <= 1 and 0 <= y0 < y1 <= 1");
    m.minShare = number(f[5]);
    if (!(m.minShare > 0 && m.minShare <= 100)) throw fail("min % must be above 0 and at most 100");
    if (m.before == m.after) throw fail("before and after are the same run");
    out.push_back(std::move(m));
  }
  return out;
}

bool render(const std::string& bin, const std::vector<std::string>& args, const std::string& size,
            const std::string& png) {
  std::vector<std::string> cmd = {bin, "--headless", "--strict-gl", "--frames", "3", "--size", size};
  cmd.insert(cmd.end(), args.begin(), args.end());
  cmd.insert(cmd.end(), {"--screenshot", png});
  shadowlab::ProcessOptions o;
  o.stdoutPath = png + ".log";
  const int rc = shadowlab::runProcess(cmd, o);
  if (rc != 0) std::cerr << "FAIL: " << bin << " exited " << rc << " (log: " << o.stdoutPath << ")\n";
  return rc == 0;
}

// The share (percent) of the region's pixels with a channel more than kLevels apart.
double changedShare(const shadowlab::Image8& a, const shadowlab::Image8& b, const Moment& m) {
  const int x0 = int(m.x0 * a.width), x1 = int(m.x1 * a.width), y0 = int(m.y0 * a.height), y1 = int(m.y1 * a.height);
  std::size_t changed = 0, all = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x, ++all) {
      const std::uint8_t *p = a.at(x, y), *q = b.at(x, y);
      for (int c = 0; c < 3; ++c)
        if (std::abs(int(p[c]) - int(q[c])) > kLevels) {
          ++changed;
          break;
        }
    }
  return all ? 100.0 * double(changed) / double(all) : 0.0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::cerr << "usage: moment_check MOMENTS_FILE BIN_DIR OUT_DIR [--lesson NN_name] [--size WxH]\n";
    return 2;
  }
  std::string only, size = "640x360";
  for (int i = 4; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--lesson") only = argv[i + 1];
    else if (a == "--size") size = argv[i + 1];
    else {
      std::cerr << "moment_check: unknown option '" << a << "' (valid: --lesson, --size)\n";
      return 2;
    }
  }
  std::vector<Moment> moments;
  try {
    moments = readMoments(argv[1]);
  } catch (const std::exception& e) {
    std::cerr << "FAIL: " << e.what() << '\n';
    return 1;
  }
  fs::create_directories(argv[3]);
  int checked = 0, failed = 0;
  for (std::size_t k = 0; k < moments.size(); ++k) {
    const Moment& m = moments[k];
    if (!only.empty() && m.lesson != only) continue;
    ++checked;
    const std::string bin = (fs::path(argv[2]) / ("lesson_" + m.lesson)).string();
    const std::string stem = (fs::path(argv[3]) / (m.lesson + "_" + std::to_string(m.line))).string();
    const std::string where = std::string(argv[1]) + ":" + std::to_string(m.line) + " (" + m.what + ")";
    if (!render(bin, m.before, size, stem + "_before.png") || !render(bin, m.after, size, stem + "_after.png")) {
      std::cerr << "FAIL: " << where << ": the lesson did not render\n";
      ++failed;
      continue;
    }
    try {
      const shadowlab::Image8 a = shadowlab::loadImage(stem + "_before.png", 3);
      const shadowlab::Image8 b = shadowlab::loadImage(stem + "_after.png", 3);
      const double share = changedShare(a, b, m);
      const bool ok = share >= m.minShare;
      char line[160];
      std::snprintf(line, sizeof line, "%.1f %% of the region changes (at least %.1f %% expected)", share, m.minShare);
      (ok ? std::cout : std::cerr) << (ok ? "ok: " : "FAIL: ") << where << ": " << line << '\n';
      failed += ok ? 0 : 1;
    } catch (const std::exception& e) {
      std::cerr << "FAIL: " << where << ": " << e.what() << '\n';
      ++failed;
    }
  }
  if (checked == 0) {
    std::cerr << "FAIL: no moment of lesson '" << only << "' in " << argv[1] << '\n';
    return 1;
  }
  std::cout << checked - failed << " of " << checked << " moments visible\n";
  return failed ? 1 : 0;
}
