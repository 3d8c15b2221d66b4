// Benchmark report writer: Pareto fronts, CSV/JSON/HTML agreement, and the progress bar.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "measure/report.hpp"

using namespace shadowlab::measure;
namespace fs = std::filesystem;

namespace {

ReportRow hardRow(const std::string& scene, const std::string& technique, double shadowMs, double mainMs,
                  double misclassifiedPct) {
  ReportRow r;
  r.scene = scene;
  r.technique = technique;
  r.parameters = "map=1024, bias=0.002";  // a comma: the CSV must quote it
  r.gpuMs = {{"shadow", shadowMs}, {"main", mainMs}};
  r.cpuMs = 0.25;
  r.shadowTriangles = 12000;
  r.shadowTexels = 1024 * 1024;
  r.culledCasters = 37;
  r.skippedFaces = 2;
  r.reusedMaps = 1;
  r.drawCalls = 412;
  r.hasHard = true;
  r.hard.facingPixels = 1000;
  r.hard.misclassifiedPct = misclassifiedPct;
  r.hard.leakPct = misclassifiedPct / 4;
  r.hard.falseShadowPct = misclassifiedPct * 3 / 4;
  r.hard.edgeTolerantPct = misclassifiedPct / 2;
  r.hasAliasing = true;
  r.aliasing.mean = 1.25;
  r.aliasing.rms = 1.5;
  r.aliasing.p95 = 3;
  r.aliasing.max = 7.5;
  r.aliasing.shareAbove1 = 0.375;
  r.imageThumbnail = "thumbs/" + technique + ".png";
  return r;
}

std::string readFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> splitCsvLine(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cell += '"';
        ++i;
      } else if (c == '"') quoted = false;
      else cell += c;
    } else if (c == '"') quoted = true;
    else if (c == ',') {
      cells.push_back(cell);
      cell.clear();
    } else cell += c;
  }
  cells.push_back(cell);
  return cells;
}

}  // namespace

TEST_CASE("measure.report: the Pareto front keeps what nothing beats in both time and error") {
  std::vector<std::pair<double, double>> p = {{1, 5}, {2, 3}, {3, 4}, {4, 1}, {2, 3}, {5, 1}};
  // (3,4) loses to (2,3); (5,1) to (4,1); the two (2,3) tie and both stay.
  CHECK(paretoFront(p) == std::vector<std::size_t>{0, 1, 4, 3});
  CHECK(paretoFront({}).empty());
  CHECK(paretoFront({{7, 7}}) == std::vector<std::size_t>{0});
}

TEST_CASE("measure.report: one number format for CSV and HTML") {
  CHECK(formatNumber(1.5) == "1.5");
  CHECK(formatNumber(5.0) == "5");
  CHECK(formatNumber(1.0 / 3.0) == "0.333333");
  CHECK(formatNumber(1234567.0) == "1.23457e+06");
  CHECK(formatNumber(std::numeric_limits<double>::infinity()) == "inf");
}

TEST_CASE("measure.report: CSV, JSON and HTML are written and agree") {
  std::vector<ReportRow> rows = {hardRow("box", "A", 1.0, 0.5, 5.0), hardRow("box", "B", 1.5, 0.5, 3.0),
                                 hardRow("box", "C", 2.5, 0.5, 4.0), hardRow("box", "D", 3.5, 0.5, 1.0)};
  ReportRow soft;
  soft.scene = "trees & <leaves>";
  soft.technique = "PCSS";
  soft.gpuMs = {{"shadow", 0.75}, {"blocker", 0.125}};
  soft.hasSoft = true;
  soft.soft.rmse = 0.0625;
  soft.soft.maxAbs = 0.5;
  rows.push_back(soft);

  fs::path dir = fs::temp_directory_path() / "shadowlab_measure_report_test";
  fs::remove_all(dir);
  std::string htmlPath = writeReport(dir.string(), "bench", rows, "Unit test run");
  REQUIRE(fs::exists(dir / "bench.csv"));
  REQUIRE(fs::exists(dir / "bench.json"));
  REQUIRE(fs::exists(dir / "bench.html"));
  CHECK(fs::path(htmlPath) == dir / "bench.html");
  std::string csv = readFile(dir / "bench.csv"), html = readFile(dir / "bench.html");
  auto json = nlohmann::json::parse(readFile(dir / "bench.json"));

  // CSV: a header and one line per row; every number in it appears as a table cell of the HTML.
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);
  std::vector<std::string> header = splitCsvLine(line);
  CHECK(header.front() == "scene");
  auto column = [&](const std::string& name) {
    auto it = std::find(header.begin(), header.end(), name);
    REQUIRE(it != header.end());
    return std::size_t(it - header.begin());
  };
  std::vector<std::vector<std::string>> table;
  while (std::getline(lines, line)) table.push_back(splitCsvLine(line));
  REQUIRE(table.size() == rows.size());
  int numbers = 0;
  for (const auto& cells : table) {
    REQUIRE(cells.size() == header.size());
    for (std::size_t i = 3; i < cells.size() - 2; ++i)  // numeric columns, between labels and images
      if (!cells[i].empty()) {
        CAPTURE(header[i]);
        CHECK(html.find(">" + cells[i] + "<") != std::string::npos);
        ++numbers;
      }
  }
  CHECK(numbers > 60);
  // Values computed by hand from the rows: A's GPU total 1.0 + 0.5, D's error 1 %, PCSS RMSE.
  CHECK(table[0][column("gpu_total_ms")] == "1.5");
  CHECK(table[0][column("parameters")] == "map=1024, bias=0.002");
  CHECK(table[3][column("misclassified_pct")] == "1");
  CHECK(table[3][column("leak_pct")] == "0.25");
  CHECK(table[4][column("soft_rmse")] == "0.0625");
  CHECK(table[4][column("gpu_ms:blocker")] == "0.125");
  CHECK(table[0][column("gpu_ms:blocker")].empty());
  CHECK(table[4][column("misclassified_pct")].empty());
  CHECK(table[1][column("m_share_above_1")] == "0.375");
  // Skipped work: the counts where the lesson reported them, empty where not (the soft row).
  CHECK(table[0][column("culled_casters")] == "37");
  CHECK(table[0][column("cube_faces_skipped")] == "2");
  CHECK(table[0][column("maps_reused")] == "1");
  CHECK(table[0][column("draw_calls")] == "412");
  CHECK(table[4][column("culled_casters")].empty());
  CHECK(table[4][column("draw_calls")].empty());

  // JSON carries the same rows.
  REQUIRE(json["rows"].size() == rows.size());
  CHECK(json["rows"][1]["gpuTotalMs"].get<double>() == 2.0);
  CHECK(json["rows"][3]["hard"]["misclassifiedPct"].get<double>() == 1.0);
  CHECK(json["rows"][4]["soft"]["rmse"].get<double>() == 0.0625);
  CHECK(json["title"] == "Unit test run");
  CHECK(json["rows"][0]["culledCasters"].get<int>() == 37);
  CHECK(json["rows"][0]["mapsReused"].get<int>() == 1);
  CHECK(json["rows"][4]["culledCasters"].is_null());

  // HTML: self-contained, a scatter per scene, the front A, B, D (C loses to B) listed and marked.
  CHECK(html.find("<script") == std::string::npos);
  CHECK(html.find("src=\"http") == std::string::npos);
  CHECK(html.find("<svg") != std::string::npos);
  CHECK(html.find("Scene: trees &amp; &lt;leaves&gt;") != std::string::npos);
  std::size_t list = html.find("<ol class=\"pareto-list\">");
  std::size_t listEnd = html.find("</ol>", list);
  REQUIRE(list != std::string::npos);
  std::string front = html.substr(list, listEnd - list);
  CHECK(front.find("<li>A [") != std::string::npos);
  CHECK(front.find("<li>B [") != std::string::npos);
  CHECK(front.find("<li>D [") != std::string::npos);
  CHECK(front.find("<li>C [") == std::string::npos);
  std::size_t marked = 0;
  for (std::size_t at = 0; (at = html.find("class=\"pareto\"", at)) != std::string::npos; ++at) ++marked;
  CHECK(marked == 2 * 3 + 2 * 1);  // box: 3 points + 3 rows; trees: its single run
  CHECK(html.find("<img class=\"thumb\" src=\"thumbs/A.png\"") != std::string::npos);
  fs::remove_all(dir);

  CHECK_THROWS_WITH_AS(writeCsv("/nonexistent/dir/x.csv", rows), doctest::Contains("/nonexistent/dir/x.csv"),
                       std::runtime_error);
}

TEST_CASE("measure.report: figures along the frames, one line per technique, only for several frames") {
  // Two techniques over four frames (a path or a light sweep); A's mean m doubles each frame.
  std::vector<ReportRow> rows;
  for (int f = 0; f < 4; ++f) {
    ReportRow a = hardRow("city", "A", 1.0, 0.5, 2.0 + f), b = hardRow("city", "B", 2.0, 0.5, 1.0);
    a.frame = b.frame = f;
    a.aliasing.mean = std::pow(2.0, f);
    a.hard.referenceShadowed = 400 + std::size_t(f);
    rows.push_back(a);
    rows.push_back(b);
  }
  const std::string html = toHtml(rows, "series");
  std::vector<std::string> plots;
  for (std::size_t at = 0; (at = html.find("<svg class=\"series\"", at)) != std::string::npos; ++at)
    plots.push_back(html.substr(at, html.find("</svg>", at) - at));
  REQUIRE(plots.size() == 3);  // aliasing m, misclassified %, shadow-pass ms
  CHECK(plots[0].find("aliasing m (mean) (log)") != std::string::npos);
  CHECK(plots[1].find("misclassified pixels (%)") != std::string::npos);
  CHECK(plots[2].find("shadow passes (GPU ms)") != std::string::npos);
  // A's aliasing line: four points, frames evenly apart, and (log scale) equal steps up for each doubling.
  const std::size_t title = plots[0].find("<title>A</title>");
  REQUIRE(title != std::string::npos);
  const std::size_t points = plots[0].rfind("points=\"", title) + 8;
  std::istringstream in(plots[0].substr(points, plots[0].find('"', points) - points));
  std::vector<double> x, y;
  double px, py;
  char comma;
  while (in >> px >> comma >> py) {
    x.push_back(px);
    y.push_back(py);
  }
  REQUIRE(x.size() == 4);
  for (std::size_t i = 1; i < 4; ++i) {
    CHECK(x[i] - x[i - 1] == doctest::Approx(x[1] - x[0]));
    CHECK(y[i] < y[i - 1]);  // higher m is higher up
    CHECK(y[i - 1] - y[i] == doctest::Approx(y[0] - y[1]));
  }
  CHECK(plots[0].find("<title>B</title>") != std::string::npos);
  // The reference's shadowed pixels reach the CSV column and the JSON.
  CHECK(nlohmann::json::parse(toJson(rows, "series"))["rows"][6]["hard"]["referenceShadowed"] == 403);
  // One frame per technique: nothing to draw along the frames.
  std::vector<ReportRow> single = {hardRow("box", "A", 1.0, 0.5, 5.0), hardRow("box", "B", 1.5, 0.5, 3.0)};
  CHECK(toHtml(single, "one frame").find("class=\"series\"") == std::string::npos);
}

TEST_CASE("measure.report: shimmer figures get their columns per span, only when measured") {
  std::vector<ReportRow> rows = {hardRow("city", "csm", 1.0, 0.5, 0.4), hardRow("city", "uniform", 1.0, 0.5, 0.5)};
  CHECK(toCsv(rows).find("shimmer") == std::string::npos);
  ShimmerFigures f;
  f.frames = 8;
  f.extraFlipPct = 0.125;
  f.maxExtraFlipPct = 0.25;
  f.referenceFlipPct = 0.5;
  f.redrawn = true;
  rows[0].shimmer["sun"] = f;
  rows[0].shimmer["camera"] = f;
  rows[0].shimmer["camera"].extraFlipPct = 0.0;
  const std::string csv = toCsv(rows);
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);
  const std::vector<std::string> header = splitCsvLine(line);
  const auto at = [&](const std::string& name) {
    const auto it = std::find(header.begin(), header.end(), name);
    REQUIRE(it != header.end());
    return std::size_t(it - header.begin());
  };
  CHECK(at("shimmer_pct:camera") < at("shimmer_pct:sun"));  // spans in the order of their names
  std::getline(lines, line);
  const std::vector<std::string> csm = splitCsvLine(line);
  std::getline(lines, line);
  const std::vector<std::string> uniform = splitCsvLine(line);
  CHECK(csm[at("shimmer_pct:camera")] == "0");
  CHECK(csm[at("shimmer_pct:sun")] == "0.125");
  CHECK(csm[at("shimmer_max_pct:sun")] == "0.25");
  CHECK(csm[at("shimmer_reference_pct:sun")] == "0.5");
  CHECK(uniform[at("shimmer_pct:sun")].empty());  // not measured: no figure, not a zero
  const auto json = nlohmann::json::parse(toJson(rows, "t"));
  CHECK(json["rows"][0]["shimmer"]["sun"]["extraFlipPct"] == 0.125);
  CHECK(json["rows"][0]["shimmer"]["sun"]["frames"] == 8);
  CHECK(json["rows"][0]["shimmer"]["sun"]["redrawn"] == true);
  CHECK_FALSE(json["rows"][1].contains("shimmer"));
}

TEST_CASE("measure.report: the progress bar draws percentage and ETA on one line") {
  CHECK(ProgressBar::render("bench", 5, 10, 4.0, 10) == "bench [=====>    ]  50% 5/10 ETA 0:04");
  CHECK(ProgressBar::render("", 10, 10, 75.0, 10) == "[==========] 100% 10/10 took 1:15");
  CHECK(ProgressBar::render("x", 0, 4, 0.0, 4) == "x [    ]   0% 0/4 ETA --:--");

  std::FILE* file = std::tmpfile();
  REQUIRE(file);
  {
    ProgressBar bar(3, "run", file, /*force=*/true);
    CHECK(bar.active());
    bar.advance();
    bar.advance(2);
  }
  std::rewind(file);
  std::string text;
  for (int c; (c = std::fgetc(file)) != EOF;) text += char(c);
  std::fclose(file);
  CHECK(text.find('\r') != std::string::npos);
  CHECK(text.find("100% 3/3") != std::string::npos);
  CHECK(text.back() == '\n');
  CHECK(std::count(text.begin(), text.end(), '\n') == 1);  // one line, redrawn

  std::FILE* quietFile = std::tmpfile();
  REQUIRE(quietFile);
  {
    ProgressBar quiet(3, "run", quietFile);  // a file is not a terminal
    CHECK_FALSE(quiet.active());
    quiet.advance(3);
  }
  CHECK(std::ftell(quietFile) == 0);
  std::fclose(quietFile);
}
