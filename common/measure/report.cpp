#include "measure/report.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include <stdexcept>

#ifdef _WIN32
#include <io.h>
#else
#include <unistd.h>
#endif

#include <nlohmann/json.hpp>

namespace shadowlab::measure {

double ReportRow::gpuTotalMs() const {
  double sum = 0;
  for (const auto& [pass, ms] : gpuMs) sum += ms;
  return sum;
}

double ReportRow::errorFigure() const {
  if (hasHard) return hard.misclassifiedPct;
  if (hasSoft) return 100.0 * soft.rmse;
  return -1.0;
}

std::string formatNumber(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

std::vector<std::size_t> paretoFront(const std::vector<std::pair<double, double>>& points) {
  std::vector<std::size_t> front;
  for (std::size_t i = 0; i < points.size(); ++i) {
    bool dominated = false;
    for (std::size_t j = 0; j < points.size() && !dominated; ++j)
      dominated = points[j].first <= points[i].first && points[j].second <= points[i].second &&
                  (points[j].first < points[i].first || points[j].second < points[i].second);
    if (!dominated) front.push_back(i);
  }
  std::stable_sort(front.begin(), front.end(), [&](std::size_t a, std::size_t b) {
    return points[a].first < points[b].first ||
           (points[a].first == points[b].first && points[a].second < points[b].second);
  });
  return front;
}

namespace {
bool isTerminal(std::FILE* f) {
#ifdef _WIN32
  return _isatty(_fileno(f)) != 0;
#else
  return ::isatty(::fileno(f)) != 0;
#endif
}

// One definition of the table, shared by CSV and HTML so their numbers cannot drift apart.
struct Column {
  std::string header;
  bool numeric;
  std::function<std::string(const ReportRow&)> cell;
};

std::vector<std::string> passNames(const std::vector<ReportRow>& rows) {
  std::set<std::string> names;
  for (const auto& r : rows)
    for (const auto& [pass, ms] : r.gpuMs) names.insert(pass);
  return {names.begin(), names.end()};
}

// Shimmer: one group of columns per measured span, in the order of the spans' names.
void shimmerColumns(const std::vector<ReportRow>& rows, std::vector<Column>& c) {
  std::set<std::string> spans;
  for (const ReportRow& r : rows)
    for (const auto& [name, figures] : r.shimmer) spans.insert(name);
  for (const std::string& span : spans) {
    auto shimmer = [&](const std::string& name, std::function<double(const ShimmerFigures&)> f) {
      c.push_back({name + ":" + span, true, [=](const ReportRow& r) {
                     const auto it = r.shimmer.find(span);
                     return it == r.shimmer.end() ? std::string() : formatNumber(f(it->second));
                   }});
    };
    shimmer("shimmer_pct", [](const ShimmerFigures& s) { return s.extraFlipPct; });
    shimmer("shimmer_max_pct", [](const ShimmerFigures& s) { return s.maxExtraFlipPct; });
    shimmer("shimmer_reference_pct", [](const ShimmerFigures& s) { return s.referenceFlipPct; });
    shimmer("shimmer_change", [](const ShimmerFigures& s) { return s.extraChange; });
  }
}

std::vector<Column> columns(const std::vector<ReportRow>& rows) {
  auto num = [](double v) { return formatNumber(v); };
  auto count = [](std::uint64_t v) { return std::to_string(v); };
  std::vector<Column> c;
  c.push_back({"scene", false, [](const ReportRow& r) { return r.scene; }});
  c.push_back({"technique", false, [](const ReportRow& r) { return r.technique; }});
  c.push_back({"parameters", false, [](const ReportRow& r) { return r.parameters; }});
  c.push_back({"frame", true, [](const ReportRow& r) { return std::to_string(r.frame); }});
  c.push_back({"repeat", true, [](const ReportRow& r) { return std::to_string(r.repeat); }});
  c.push_back({"gpu_total_ms", true, [=](const ReportRow& r) { return num(r.gpuTotalMs()); }});
  for (const std::string& pass : passNames(rows))
    c.push_back({"gpu_ms:" + pass, true, [=](const ReportRow& r) {
                   auto it = r.gpuMs.find(pass);
                   return it == r.gpuMs.end() ? std::string() : num(it->second);
                 }});
  c.push_back({"cpu_ms", true, [=](const ReportRow& r) { return num(r.cpuMs); }});
  c.push_back({"shadow_triangles", true, [=](const ReportRow& r) { return count(r.shadowTriangles); }});
  c.push_back({"shadow_texels", true, [=](const ReportRow& r) { return count(r.shadowTexels); }});
  auto skipped = [](std::int64_t v) { return v < 0 ? std::string() : std::to_string(v); };
  c.push_back({"culled_casters", true, [=](const ReportRow& r) { return skipped(r.culledCasters); }});
  c.push_back({"cube_faces_skipped", true, [=](const ReportRow& r) { return skipped(r.skippedFaces); }});
  c.push_back({"maps_reused", true, [=](const ReportRow& r) { return skipped(r.reusedMaps); }});
  c.push_back({"draw_calls", true, [=](const ReportRow& r) { return skipped(r.drawCalls); }});
  auto hard = [&](const char* name, std::function<std::string(const HardShadowErrors&)> f) {
    c.push_back({name, true, [=](const ReportRow& r) { return r.hasHard ? f(r.hard) : std::string(); }});
  };
  hard("facing_pixels", [=](const HardShadowErrors& e) { return count(e.facingPixels); });
  hard("reference_shadowed", [=](const HardShadowErrors& e) { return count(e.referenceShadowed); });
  hard("misclassified_pct", [=](const HardShadowErrors& e) { return num(e.misclassifiedPct); });
  hard("leak_pct", [=](const HardShadowErrors& e) { return num(e.leakPct); });
  hard("false_shadow_pct", [=](const HardShadowErrors& e) { return num(e.falseShadowPct); });
  hard("edge_tolerant_pct", [=](const HardShadowErrors& e) { return num(e.edgeTolerantPct); });
  c.push_back({"soft_rmse", true, [=](const ReportRow& r) { return r.hasSoft ? num(r.soft.rmse) : std::string(); }});
  c.push_back(
      {"soft_max_abs", true, [=](const ReportRow& r) { return r.hasSoft ? num(r.soft.maxAbs) : std::string(); }});
  auto soft = [&](const char* name, std::function<std::string(const SoftShadowErrors&)> f) {
    c.push_back({name, true, [=](const ReportRow& r) { return r.hasSoft ? f(r.soft) : std::string(); }});
  };
  soft("umbra_over_pct", [=](const SoftShadowErrors& e) { return num(e.umbraOverPct); });
  soft("umbra_under_pct", [=](const SoftShadowErrors& e) { return num(e.umbraUnderPct); });
  soft("bleed_pct", [=](const SoftShadowErrors& e) { return num(e.bleedPct); });
  soft("reference_noise_rmse", [=](const SoftShadowErrors& e) { return e.noiseFloor < 0 ? "" : num(e.noiseFloor); });
  auto alias = [&](const char* name, std::function<double(const AliasingStats&)> f) {
    c.push_back({name, true, [=](const ReportRow& r) { return r.hasAliasing ? num(f(r.aliasing)) : std::string(); }});
  };
  alias("m_mean", [](const AliasingStats& s) { return s.mean; });
  alias("m_rms", [](const AliasingStats& s) { return s.rms; });
  alias("m_p95", [](const AliasingStats& s) { return s.p95; });
  alias("m_max", [](const AliasingStats& s) { return s.max; });
  alias("m_share_above_1", [](const AliasingStats& s) { return s.shareAbove1; });
  // Near shadow edges: only when a lesson measured them, so other reports keep their columns.
  if (std::any_of(rows.begin(), rows.end(), [](const ReportRow& r) { return r.hasBand; })) {
    auto band = [&](const char* name, std::function<std::string(const ReportRow&)> f) {
      c.push_back({name, true, [=](const ReportRow& r) { return r.hasBand ? f(r) : std::string(); }});
    };
    band("edge_pixels_band", [=](const ReportRow& r) { return count(r.band.facingPixels); });
    band("edge_misclassified_pct", [=](const ReportRow& r) { return num(r.band.misclassifiedPct); });
    band("edge_m_mean", [=](const ReportRow& r) { return r.hasAliasing ? num(r.bandAliasing.mean) : std::string(); });
    band("edge_m_p95", [=](const ReportRow& r) { return r.hasAliasing ? num(r.bandAliasing.p95) : std::string(); });
  }
  shimmerColumns(rows, c);
  c.push_back({"image", false, [](const ReportRow& r) { return r.imageThumbnail; }});
  c.push_back({"error_image", false, [](const ReportRow& r) { return r.errorThumbnail; }});
  return c;
}

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char ch : s) {
    if (ch == '"') out += '"';
    out += ch;
  }
  return out + "\"";
}

std::string html(const std::string& s) {
  std::string out;
  for (char ch : s) {
    switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += ch;
    }
  }
  return out;
}

// Relative thumbnail paths become URLs: escape what a URL path cannot hold raw.
std::string urlPath(const std::string& s) {
  static const char* hex = "0123456789ABCDEF";
  std::string out;
  for (unsigned char ch : s) {
    if (std::isalnum(ch) || std::string("/._-~").find(char(ch)) != std::string::npos) out += char(ch);
    else {
      out += '%';
      out += hex[ch >> 4];
      out += hex[ch & 15];
    }
  }
  return out;
}

std::string fmt(double v, const char* format = "%.3g") {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, v);
  return buffer;
}

std::string label(const ReportRow& r) {
  std::string s = r.technique;
  if (!r.parameters.empty()) s += " [" + r.parameters + "]";
  if (r.frame) s += " frame " + std::to_string(r.frame);
  if (r.repeat) s += " #" + std::to_string(r.repeat);
  return s;
}

std::string scatterSvg(const std::vector<const ReportRow*>& rows, const std::vector<std::size_t>& front,
                       const std::string& errorName) {
  const double W = 560, H = 340, left = 70, right = 20, top = 20, bottom = 50;
  double maxX = 0, maxY = 0;
  for (const ReportRow* r : rows) {
    maxX = std::max(maxX, r->gpuTotalMs());
    maxY = std::max(maxY, r->errorFigure());
  }
  maxX = maxX > 0 ? maxX * 1.1 : 1.0;
  maxY = maxY > 0 ? maxY * 1.1 : 1.0;
  auto px = [&](double x) { return left + (W - left - right) * x / maxX; };
  auto py = [&](double y) { return H - bottom - (H - top - bottom) * std::max(y, 0.0) / maxY; };
  std::ostringstream s;
  s << "<svg class=\"scatter\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
    << "\" viewBox=\"0 0 " << W << ' ' << H << "\" role=\"img\" aria-label=\"GPU time against " << html(errorName)
    << "\">\n";
  s << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << W - left - right << "\" height=\""
    << H - top - bottom << "\" fill=\"#fafafa\" stroke=\"#999\"/>\n";
  for (int i = 0; i <= 4; ++i) {
    double x = maxX * i / 4, y = maxY * i / 4;
    s << "<line x1=\"" << px(x) << "\" y1=\"" << H - bottom << "\" x2=\"" << px(x) << "\" y2=\"" << H - bottom + 5
      << "\" stroke=\"#666\"/><text x=\"" << px(x) << "\" y=\"" << H - bottom + 18
      << "\" text-anchor=\"middle\" class=\"tick\">" << fmt(x) << "</text>\n";
    s << "<line x1=\"" << left - 5 << "\" y1=\"" << py(y) << "\" x2=\"" << left << "\" y2=\"" << py(y)
      << "\" stroke=\"#666\"/><text x=\"" << left - 8 << "\" y=\"" << py(y) + 4
      << "\" text-anchor=\"end\" class=\"tick\">" << fmt(y) << "</text>\n";
  }
  s << "<text x=\"" << (left + W - right) / 2 << "\" y=\"" << H - 10
    << "\" text-anchor=\"middle\">GPU time per frame (ms)</text>\n";
  s << "<text transform=\"translate(16 " << (top + H - bottom) / 2 << ") rotate(-90)\" text-anchor=\"middle\">"
    << html(errorName) << "</text>\n";
  if (front.size() > 1) {  // the staircase: nothing below-left of it is achievable by these runs
    s << "<polyline class=\"front\" fill=\"none\" stroke=\"#d9480f\" stroke-width=\"1.5\" points=\"";
    for (std::size_t k = 0; k < front.size(); ++k) {
      const ReportRow* r = rows[front[k]];
      if (k) s << px(r->gpuTotalMs()) << ',' << py(rows[front[k - 1]]->errorFigure()) << ' ';
      s << px(r->gpuTotalMs()) << ',' << py(r->errorFigure()) << ' ';
    }
    s << "\"/>\n";
  }
  std::set<std::size_t> onFront(front.begin(), front.end());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const ReportRow* r = rows[i];
    bool f = onFront.count(i) > 0;
    s << "<circle cx=\"" << px(r->gpuTotalMs()) << "\" cy=\"" << py(r->errorFigure()) << "\" r=\"" << (f ? 6 : 4)
      << "\" fill=\"" << (f ? "#d9480f" : "#4263eb") << "\" fill-opacity=\"0.8\"" << (f ? " class=\"pareto\"" : "")
      << "><title>" << html(label(*r)) << ": " << formatNumber(r->gpuTotalMs()) << " ms, "
      << formatNumber(r->errorFigure()) << "</title></circle>\n";
  }
  s << "</svg>\n";
  return s.str();
}

// One figure of a row for the series plots; NaN where the row has none.
struct Series {
  const char* name;
  bool logScale;
  std::function<double(const ReportRow&)> value;
};
std::vector<Series> seriesFigures() {
  const double nan = std::nan("");
  return {{"aliasing m (mean)", true, [=](const ReportRow& r) { return r.hasAliasing ? r.aliasing.mean : nan; }},
          {"misclassified pixels (%)", false,
           [=](const ReportRow& r) { return r.hasHard ? r.hard.misclassifiedPct : nan; }},
          {"shadow passes (GPU ms)", false, [=](const ReportRow& r) {
             double ms = 0;
             bool any = false;
             for (const auto& [pass, v] : r.gpuMs)
               if (pass.rfind("shadow", 0) == 0) {
                 ms += v;
                 any = true;
               }
             return any ? ms : nan;
           }}};
}

// A figure along the frames (path samples, or the directions of a sweep), one line per technique.
std::string seriesSvg(const std::vector<const ReportRow*>& rows, const Series& fig) {
  static const char* colours[] = {"#4263eb", "#d9480f", "#2b8a3e", "#ae3ec9", "#e67700", "#1098ad", "#c2255c"};
  std::vector<std::string> techniques;
  int frames = 0;
  double lo = 1e300, hi = -1e300;
  for (const ReportRow* r : rows) {
    if (std::find(techniques.begin(), techniques.end(), r->technique) == techniques.end())
      techniques.push_back(r->technique);
    frames = std::max(frames, r->frame + 1);
    const double v = fig.value(*r);
    if (!std::isfinite(v) || (fig.logScale && !(v > 0))) continue;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  if (!(hi >= lo) || frames < 2) return "";
  auto map = [&](double v) { return fig.logScale ? std::log10(v) : v; };
  double a = fig.logScale ? std::floor(map(lo)) : 0.0, b = fig.logScale ? std::ceil(map(hi)) : hi * 1.1;
  if (!(b > a)) b = a + 1;
  const double W = 560, H = 300, left = 70, right = 160, top = 20, bottom = 45;
  auto px = [&](double f) { return left + (W - left - right) * f / (frames - 1); };
  auto py = [&](double v) { return H - bottom - (H - top - bottom) * (map(v) - a) / (b - a); };
  std::ostringstream s;
  s << "<svg class=\"series\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
    << "\" viewBox=\"0 0 " << W << ' ' << H << "\" role=\"img\" aria-label=\"" << html(fig.name) << " per frame\">\n";
  s << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << W - left - right << "\" height=\""
    << H - top - bottom << "\" fill=\"#fafafa\" stroke=\"#999\"/>\n";
  for (int i = 0; i <= 4; ++i) {
    const double t = a + (b - a) * i / 4, v = fig.logScale ? std::pow(10.0, t) : t;
    s << "<text x=\"" << left - 8 << "\" y=\"" << py(v) + 4 << "\" text-anchor=\"end\" class=\"tick\">" << fmt(v)
      << "</text>\n";
  }
  for (int f = 0; f < frames; f += std::max(1, frames / 8))
    s << "<text x=\"" << px(f) << "\" y=\"" << H - bottom + 16 << "\" text-anchor=\"middle\" class=\"tick\">" << f
      << "</text>\n";
  s << "<text x=\"" << (left + W - right) / 2 << "\" y=\"" << H - 8 << "\" text-anchor=\"middle\">frame</text>\n";
  s << "<text transform=\"translate(16 " << (top + H - bottom) / 2 << ") rotate(-90)\" text-anchor=\"middle\">"
    << html(fig.name) << (fig.logScale ? " (log)" : "") << "</text>\n";
  for (std::size_t t = 0; t < techniques.size(); ++t) {
    const char* c = colours[t % 7];
    s << "<polyline fill=\"none\" stroke=\"" << c << "\" stroke-width=\"1.5\" points=\"";
    for (const ReportRow* r : rows) {
      const double v = fig.value(*r);
      if (r->technique == techniques[t] && std::isfinite(v) && (!fig.logScale || v > 0))
        s << px(r->frame) << ',' << py(v) << ' ';
    }
    s << "\"><title>" << html(techniques[t]) << "</title></polyline>\n";
    s << "<text x=\"" << W - right + 10 << "\" y=\"" << top + 14 + 16 * t << "\" fill=\"" << c << "\">"
      << html(techniques[t]) << "</text>\n";
  }
  s << "</svg>\n";
  return s.str();
}

void writeText(const std::string& path, const std::string& text) {
  std::ofstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error(path + ": cannot open for writing");
  file << text;
  file.flush();
  if (!file) throw std::runtime_error(path + ": write failed");
}

}  // namespace

std::string toCsv(const std::vector<ReportRow>& rows) {
  std::vector<Column> cols = columns(rows);
  std::ostringstream out;
  for (std::size_t i = 0; i < cols.size(); ++i) out << (i ? "," : "") << csvField(cols[i].header);
  out << "\n";
  for (const ReportRow& r : rows) {
    for (std::size_t i = 0; i < cols.size(); ++i) out << (i ? "," : "") << csvField(cols[i].cell(r));
    out << "\n";
  }
  return out.str();
}

std::string toJson(const std::vector<ReportRow>& rows, const std::string& title) {
  using nlohmann::json;
  json doc;
  doc["title"] = title;
  doc["format"] = "shadowlab-benchmark 1";
  json list = json::array();
  auto finite = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };  // JSON has no inf/nan
  for (const ReportRow& r : rows) {
    json j;
    j["scene"] = r.scene;
    j["technique"] = r.technique;
    j["parameters"] = r.parameters;
    j["frame"] = r.frame;
    j["repeat"] = r.repeat;
    json passes = json::object();
    for (const auto& [pass, ms] : r.gpuMs) passes[pass] = finite(ms);
    j["gpuMs"] = passes;
    j["gpuTotalMs"] = finite(r.gpuTotalMs());
    j["cpuMs"] = finite(r.cpuMs);
    j["shadowTriangles"] = r.shadowTriangles;
    j["shadowTexels"] = r.shadowTexels;
    auto skipped = [](std::int64_t v) { return v < 0 ? json(nullptr) : json(v); };  // null: not reported
    j["culledCasters"] = skipped(r.culledCasters);
    j["cubeFacesSkipped"] = skipped(r.skippedFaces);
    j["mapsReused"] = skipped(r.reusedMaps);
    j["drawCalls"] = skipped(r.drawCalls);
    if (r.hasHard)
      j["hard"] = {{"facingPixels", r.hard.facingPixels},
                   {"referenceShadowed", r.hard.referenceShadowed},
                   {"misclassified", r.hard.misclassified},
                   {"leaks", r.hard.leaks},
                   {"falseShadows", r.hard.falseShadows},
                   {"edgePixels", r.hard.edgePixels},
                   {"edgeTolerantMisclassified", r.hard.edgeTolerantMisclassified},
                   {"misclassifiedPct", finite(r.hard.misclassifiedPct)},
                   {"leakPct", finite(r.hard.leakPct)},
                   {"falseShadowPct", finite(r.hard.falseShadowPct)},
                   {"edgeTolerantPct", finite(r.hard.edgeTolerantPct)}};
    if (r.hasSoft)
      j["soft"] = {{"pixels", r.soft.pixels},
                   {"rmse", finite(r.soft.rmse)},
                   {"maxAbs", finite(r.soft.maxAbs)},
                   {"umbraOverPct", finite(r.soft.umbraOverPct)},
                   {"umbraUnderPct", finite(r.soft.umbraUnderPct)},
                   {"bleedPct", finite(r.soft.bleedPct)},
                   {"referenceNoiseRmse", finite(r.soft.noiseFloor)}};
    if (r.hasAliasing)
      j["aliasing"] = {{"pixels", r.aliasing.pixels},   {"mean", finite(r.aliasing.mean)},
                       {"rms", finite(r.aliasing.rms)}, {"p95", finite(r.aliasing.p95)},
                       {"max", finite(r.aliasing.max)}, {"shareAbove1", finite(r.aliasing.shareAbove1)}};
    if (r.hasBand)
      j["edgeBand"] = {{"pixels", r.band.facingPixels},
                       {"misclassified", r.band.misclassified},
                       {"misclassifiedPct", finite(r.band.misclassifiedPct)},
                       {"mMean", finite(r.bandAliasing.mean)},
                       {"mP95", finite(r.bandAliasing.p95)}};
    for (const auto& [span, f] : r.shimmer)
      j["shimmer"][span] = {{"frames", f.frames},
                            {"extraFlipPct", finite(f.extraFlipPct)},
                            {"maxExtraFlipPct", finite(f.maxExtraFlipPct)},
                            {"referenceFlipPct", finite(f.referenceFlipPct)},
                            {"extraChange", finite(f.extraChange)},
                            {"redrawn", f.redrawn},
                            {"reprojected", f.reprojected},
                            {"unmatchedPct", finite(f.unmatchedPct)}};
    j["imageThumbnail"] = r.imageThumbnail;
    j["errorThumbnail"] = r.errorThumbnail;
    list.push_back(std::move(j));
  }
  doc["rows"] = std::move(list);
  return doc.dump(2) + "\n";
}

std::string toHtml(const std::vector<ReportRow>& rows, const std::string& title) {
  std::vector<Column> cols = columns(rows);
  std::vector<std::string> scenes;
  for (const ReportRow& r : rows)
    if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) scenes.push_back(r.scene);
  std::ostringstream s;
  s << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
    << "<link rel=\"icon\" href=\"data:,\">\n<title>" << html(title) << "</title>\n<style>\n"
    << "body{font-family:system-ui,sans-serif;margin:1.5em;color:#222}\n"
    << "table{border-collapse:collapse;font-size:13px;margin:1em 0}\n"
    << "th,td{border:1px solid #ccc;padding:3px 6px;text-align:right;vertical-align:middle}\n"
    << "td.text,th{text-align:left}\nth{background:#f1f3f5}\ntr.pareto td{background:#fff4e6}\n"
    << "img.thumb{width:160px;image-rendering:pixelated;display:block}\n"
    << "svg text{font-size:12px;fill:#333}\nsvg text.tick{font-size:11px}\n</style>\n</head>\n<body>\n"
    << "<h1>" << html(title) << "</h1>\n<p>" << rows.size() << " measurements over " << scenes.size()
    << " scene(s). Error axis: misclassified pixels (% of pixels facing the light) for hard shadows, "
    << "RMSE of visibility (% of full visibility) for soft shadows, both against ray-cast ground truth. "
    << "Orange points and rows form the Pareto front: no other run is both faster and more accurate.</p>\n";
  if (rows.empty()) s << "<p>No measurements.</p>\n";
  for (const std::string& scene : scenes) {
    std::vector<const ReportRow*> sceneRows;
    for (const ReportRow& r : rows)
      if (r.scene == scene) sceneRows.push_back(&r);
    std::vector<std::pair<double, double>> points;
    std::vector<std::size_t> plotted;  // rows with an error figure
    for (std::size_t i = 0; i < sceneRows.size(); ++i)
      if (sceneRows[i]->errorFigure() >= 0) {
        points.push_back({sceneRows[i]->gpuTotalMs(), sceneRows[i]->errorFigure()});
        plotted.push_back(i);
      }
    std::vector<std::size_t> front;
    for (std::size_t k : paretoFront(points)) front.push_back(plotted[k]);
    std::vector<const ReportRow*> plotRows;
    for (std::size_t i : plotted) plotRows.push_back(sceneRows[i]);
    std::vector<std::size_t> frontInPlot;
    for (std::size_t i : front)
      frontInPlot.push_back(std::size_t(std::find(plotted.begin(), plotted.end(), i) - plotted.begin()));
    bool allHard = std::all_of(plotRows.begin(), plotRows.end(), [](const ReportRow* r) { return r->hasHard; });
    std::string errorName = allHard ? "misclassified pixels (%)" : "error (% misclassified or % RMSE)";

    s << "<section>\n<h2>Scene: " << html(scene) << "</h2>\n";
    if (!plotRows.empty()) s << scatterSvg(plotRows, frontInPlot, errorName);
    // Along the frames (a path or a sweep), when there are several: each figure per technique.
    for (const Series& fig : seriesFigures()) s << seriesSvg(sceneRows, fig);
    s << "<h3>Pareto front</h3>\n<ol class=\"pareto-list\">\n";
    for (std::size_t i : front)
      s << "<li>" << html(label(*sceneRows[i])) << ": " << formatNumber(sceneRows[i]->gpuTotalMs()) << " ms, "
        << formatNumber(sceneRows[i]->errorFigure()) << "</li>\n";
    s << "</ol>\n<table>\n<thead><tr>";
    for (const Column& c : cols) s << "<th>" << html(c.header) << "</th>";
    s << "</tr></thead>\n<tbody>\n";
    std::set<std::size_t> onFront(front.begin(), front.end());
    for (std::size_t i = 0; i < sceneRows.size(); ++i) {
      const ReportRow& r = *sceneRows[i];
      s << "<tr" << (onFront.count(i) ? " class=\"pareto\"" : "") << ">";
      for (const Column& c : cols) {
        std::string v = c.cell(r);
        bool image = (c.header == "image" || c.header == "error_image") && !v.empty();
        s << "<td" << (c.numeric ? "" : " class=\"text\"") << ">";
        if (image)
          s << "<a href=\"" << html(urlPath(v)) << "\"><img class=\"thumb\" src=\"" << html(urlPath(v)) << "\" alt=\""
            << html(c.header + " of " + label(r)) << "\"></a>";
        else s << html(v);
        s << "</td>";
      }
      s << "</tr>\n";
    }
    s << "</tbody>\n</table>\n</section>\n";
  }
  s << "</body>\n</html>\n";
  return s.str();
}

void writeCsv(const std::string& path, const std::vector<ReportRow>& rows) { writeText(path, toCsv(rows)); }
void writeJson(const std::string& path, const std::vector<ReportRow>& rows, const std::string& title) {
  writeText(path, toJson(rows, title));
}
void writeHtml(const std::string& path, const std::vector<ReportRow>& rows, const std::string& title) {
  writeText(path, toHtml(rows, title));
}

std::string writeReport(const std::string& folder, const std::string& stem, const std::vector<ReportRow>& rows,
                        const std::string& title) {
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec) throw std::runtime_error(folder + ": cannot create folder (" + ec.message() + ")");
  std::filesystem::path base = std::filesystem::path(folder) / stem;
  writeCsv(base.string() + ".csv", rows);
  writeJson(base.string() + ".json", rows, title);
  writeHtml(base.string() + ".html", rows, title);
  return base.string() + ".html";
}

// ---- ProgressBar --------------------------------------------------------------------------------

ProgressBar::ProgressBar(std::size_t total, std::string label, std::FILE* out, bool force)
    : total_(total),
      label_(std::move(label)),
      out_(out),
      active_(out != nullptr && (force || isTerminal(out))),
      start_(std::chrono::steady_clock::now()),
      lastDraw_(start_ - std::chrono::seconds(1)) {
  if (active_) draw(false);
}

ProgressBar::~ProgressBar() { finish(); }

void ProgressBar::advance(std::size_t steps) { set(done_ + steps); }

void ProgressBar::set(std::size_t done) {
  done_ = std::min(done, total_);
  if (!active_ || finished_) return;
  auto now = std::chrono::steady_clock::now();
  if (done_ == total_ || now - lastDraw_ >= std::chrono::milliseconds(100)) draw(false);
}

void ProgressBar::finish() {
  if (finished_) return;
  finished_ = true;
  if (active_) draw(true);
}

void ProgressBar::draw(bool final) {
  lastDraw_ = std::chrono::steady_clock::now();
  double elapsed = std::chrono::duration<double>(lastDraw_ - start_).count();
  std::string line = render(label_, done_, total_, elapsed);
  std::fprintf(out_, "\r%s%s", line.c_str(), final ? "\n" : "");
  std::fflush(out_);
}

std::string ProgressBar::render(const std::string& label, std::size_t done, std::size_t total, double elapsedSeconds,
                                int barWidth) {
  double fraction = total ? double(std::min(done, total)) / double(total) : 1.0;
  int filled = int(fraction * barWidth);
  std::string bar(std::size_t(barWidth), ' ');
  for (int i = 0; i < filled; ++i) bar[std::size_t(i)] = '=';
  if (filled < barWidth && done > 0) bar[std::size_t(filled)] = '>';
  auto clock = [](double seconds) {
    long s = long(std::lround(std::max(0.0, seconds)));
    char buffer[32];
    if (s >= 3600) std::snprintf(buffer, sizeof buffer, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
    else std::snprintf(buffer, sizeof buffer, "%ld:%02ld", s / 60, s % 60);
    return std::string(buffer);
  };
  std::string eta = done == 0       ? "--:--"
                    : done >= total ? clock(elapsedSeconds)
                                    : clock(elapsedSeconds * double(total - done) / double(done));
  char pct[16];
  std::snprintf(pct, sizeof pct, "%3d%%", int(std::floor(fraction * 100)));
  return (label.empty() ? "" : label + " ") + "[" + bar + "] " + pct + " " + std::to_string(done) + "/" +
         std::to_string(total) + (done >= total ? " took " : " ETA ") + eta;
}

}  // namespace shadowlab::measure
