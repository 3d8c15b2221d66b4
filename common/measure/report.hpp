#pragma once
// Benchmark reports: one row per (scene, technique and parameters, frame, repeat) measured by the
// runner, written as CSV (spreadsheets), JSON (scripts) and one self-contained HTML page (people):
// per scene an inline SVG scatter of GPU time against error with the Pareto front marked and
// listed, the table, and thumbnails by relative path. No scripts, no external resources.
// Every number appears in the HTML exactly as formatNumber() writes it into the CSV.
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "measure/metrics.hpp"

namespace shadowlab::measure {

// Shimmer along a short span of a path (consecutive frames, measured one against the next): the
// share of pixels a frame whose shadow flips where the ground truth's does not, and for soft
// shadows the mean change of visibility beyond the reference's (metrics.hpp's TemporalErrors).
struct ShimmerFigures {
  int frames = 0;               // frame pairs compared
  double extraFlipPct = 0;      // mean over the pairs, % of the pixels facing the light in both
  double maxExtraFlipPct = 0;   // the worst pair
  double referenceFlipPct = 0;  // the ground truth's own flips (the shadow truly moving), mean
  double extraChange = 0;       // soft: mean |dV| beyond the reference's, mean over the pairs
  bool redrawn = false;         // the camera moved: the shadows drawn again at the last frame's very points
  bool reprojected = false;     // the camera moved, the lesson cannot redraw: points followed by reprojection
  double unmatchedPct = 0;      // of those, the share of facing pixels whose point was not seen before
};

struct ReportRow {
  std::string scene;
  std::string technique;   // e.g. "PCF 3x3"
  std::string parameters;  // the parameter set or preset label, e.g. "map=2048 bias=0.002"
  int frame = 0;           // index along the camera/light path (0 for a still view)
  int repeat = 0;
  std::map<std::string, double> gpuMs;  // per pass (timer queries), e.g. {"shadow", 0.8}, {"main", 1.2}
  double cpuMs = 0;
  std::uint64_t shadowTriangles = 0;  // triangles drawn into shadow maps
  std::uint64_t shadowTexels = 0;     // texels of every shadow map rendered
  // Skipped work, as the lesson's header counts it; -1: the lesson did not report it (a technique
  // that culls nothing, or no counters at all). Maps reused is 0 when the lesson reports counters
  // without it (the header shows it only once a map was reused).
  std::int64_t culledCasters = -1, skippedFaces = -1, reusedMaps = -1, drawCalls = -1;
  bool hasHard = false;
  HardShadowErrors hard;
  bool hasSoft = false;
  SoftShadowErrors soft;
  bool hasAliasing = false;
  AliasingStats aliasing;
  bool hasBand = false;  // near shadow edges (the lesson's MeasureSource::edgeBand): errors, and m there
  HardShadowErrors band;
  AliasingStats bandAliasing;
  std::map<std::string, ShimmerFigures> shimmer;  // by the span's name (e.g. "camera", "sun"), when measured
  std::string imageThumbnail;                     // paths relative to the report's folder (may be empty)
  std::string errorThumbnail;

  double gpuTotalMs() const;
  // The scatter's error axis: misclassified % for hard shadows, else soft RMSE in % of full
  // visibility; -1 when the row has neither.
  double errorFigure() const;
};

// "%.6g", the one number format the CSV and the HTML share ("nan"/"inf" spelled out).
std::string formatNumber(double value);

// Indices of the points no other point beats in both coordinates (smaller is better; a point
// equal to another is kept), ordered by x.
std::vector<std::size_t> paretoFront(const std::vector<std::pair<double, double>>& points);

std::string toCsv(const std::vector<ReportRow>& rows);
std::string toJson(const std::vector<ReportRow>& rows, const std::string& title);
std::string toHtml(const std::vector<ReportRow>& rows, const std::string& title);
// Each throws std::runtime_error naming the path when it cannot be written.
void writeCsv(const std::string& path, const std::vector<ReportRow>& rows);
void writeJson(const std::string& path, const std::vector<ReportRow>& rows, const std::string& title);
void writeHtml(const std::string& path, const std::vector<ReportRow>& rows, const std::string& title);
// <folder>/<stem>.csv, .json and .html (the folder is created); returns the HTML path.
std::string writeReport(const std::string& folder, const std::string& stem, const std::vector<ReportRow>& rows,
                        const std::string& title);

// A one-line terminal progress bar redrawn with '\r': label, bar, percentage, done/total, ETA.
// Quiet (writes nothing) when `out` is not a terminal, unless `force`. Redraws at most every
// 100 ms, and always at the end; finish() (or the destructor) ends the line.
class ProgressBar {
 public:
  ProgressBar(std::size_t total, std::string label, std::FILE* out = stderr, bool force = false);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  void advance(std::size_t steps = 1);
  void set(std::size_t done);
  void finish();
  bool active() const { return active_; }
  std::size_t done() const { return done_; }

  // The text of one redraw (without '\r'), e.g. "bench [=======>      ]  50% 5/10 ETA 0:04".
  static std::string render(const std::string& label, std::size_t done, std::size_t total, double elapsedSeconds,
                            int barWidth = 30);

 private:
  void draw(bool final);
  std::size_t total_, done_ = 0;
  std::string label_;
  std::FILE* out_;
  bool active_;
  bool finished_ = false;
  std::chrono::steady_clock::time_point start_, lastDraw_;
};

}  // namespace shadowlab::measure
