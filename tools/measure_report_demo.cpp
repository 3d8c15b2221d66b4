// measure_report_demo OUT_DIR: a small benchmark report made end to end on the CPU, for the page
// check (tests/measure.cmake) and as an example of the measure API. Ground truth from Embree over
// a hand-made scene (a floor, a box-like slab and an alpha-tested card), "techniques" that are the
// reference shifted or eroded by a pixel or two (what a biased or low-resolution shadow map does),
// their errors, heatmaps and thumbnails, then CSV + JSON + HTML.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "core/image.hpp"
#include "measure/ground_truth.hpp"
#include "measure/metrics.hpp"
#include "measure/report.hpp"

using namespace shadowlab;
using namespace shadowlab::measure;

namespace {

Mesh quad(float x0, float x1, float z0, float z1, float y) {
  Mesh m;
  m.positions = {{x0, y, z0}, {x0, y, z1}, {x1, y, z1}, {x1, y, z0}};
  m.normals.assign(4, glm::vec3(0, 1, 0));
  m.uvs = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

void add(Scene& scene, Mesh mesh, std::uint32_t material) {
  SceneObject o;
  o.name = "object" + std::to_string(scene.objects.size());
  o.mesh = std::uint32_t(scene.meshes.size());
  o.material = material;
  scene.meshes.push_back(std::move(mesh));
  scene.objects.push_back(o);
}

// Visibility shifted by (dx, dy) pixels: a shadow map that misplaces the shadow.
ImageF shifted(const ImageF& ref, int dx, int dy) {
  ImageF out = ref;
  for (int y = 0; y < ref.height; ++y)
    for (int x = 0; x < ref.width; ++x) {
      int sx = std::clamp(x - dx, 0, ref.width - 1), sy = std::clamp(y - dy, 0, ref.height - 1);
      if (ref.at(x, y) >= 0 && ref.at(sx, sy) >= 0) out.at(x, y) = ref.at(sx, sy);
    }
  return out;
}

Image8 greyscale(const ImageF& vis) {
  Image8 out;
  out.width = vis.width;
  out.height = vis.height;
  out.channels = 4;
  out.data.resize(std::size_t(vis.width) * vis.height * 4);
  for (std::size_t i = 0; i < vis.data.size(); ++i) {
    auto g = std::uint8_t(vis.data[i] < 0 ? 30 : 60 + 180 * vis.data[i]);
    out.data[4 * i] = out.data[4 * i + 1] = out.data[4 * i + 2] = g;
    out.data[4 * i + 3] = 255;
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  const char* usage = "usage: measure_report_demo OUT_DIR (writes a sample measurement report there)\n";
  if (argc == 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h")) {
    std::fputs(usage, stdout);
    return 0;
  }
  // One argument, the directory: a flag there is a mistake, not a name to create ("--help" was).
  if (argc != 2 || argv[1][0] == '-' || argv[1][0] == '\0') {
    if (argc > 1) std::fprintf(stderr, "measure_report_demo: unexpected argument '%s'; ", argv[argc > 2 ? 2 : 1]);
    std::fputs(usage, stderr);
    return 2;
  }
  try {
    const std::string outDir = argv[1];
    std::filesystem::create_directories(std::filesystem::path(outDir) / "thumbs");

    Image8 leaves;
    leaves.width = leaves.height = 8;
    leaves.data.assign(8 * 8 * 4, 255);
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x) leaves.at(x, y)[3] = (x / 2 + y / 2) % 2 ? 255 : 0;
    Scene scene;
    scene.materials.push_back(Material{});
    Material card;
    card.name = "leaves";
    card.texture = "leaves.png";
    card.alphaCutoff = 0.5f;
    scene.materials.push_back(card);
    add(scene, quad(-4, 4, -4, 4, 0), 0);
    add(scene, quad(-2.5f, -0.5f, -1, 1, 1.5f), 0);
    add(scene, quad(0.5f, 2.5f, -1, 1, 1.0f), 1);
    GroundTruth truth(scene, std::map<std::string, Image8>{{"leaves.png", leaves}});

    const int size = 96;
    SurfaceBuffer view(size, size);
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x)
        view.set(x, y, {-4 + 8.0f * (x + 0.5f) / size, 0, -4 + 8.0f * (y + 0.5f) / size}, {0, 1, 0});
    Light light;
    light.kind = LightKind::Point;
    light.position = {0.5f, 6, 0.3f};
    ImageF reference = truth.hardVisibility(view, light);
    savePng(outDir + "/thumbs/reference.png", greyscale(reference));

    struct Variant {
      const char* technique;
      const char* parameters;
      int dx, dy;
      double shadowMs;
    };
    const Variant variants[] = {{"shadow map", "map=512", 2, 1, 0.4},
                                {"shadow map", "map=1024", 1, 0, 0.7},
                                {"shadow map", "map=2048", 1, 1, 1.6},
                                {"PSM", "map=1024 cube", 0, 0, 1.1}};
    std::vector<ReportRow> rows;
    ProgressBar progress(std::size(variants), "demo");
    int index = 0;
    for (const Variant& v : variants) {
      ImageF technique = shifted(reference, v.dx, v.dy);
      ReportRow row;
      row.scene = "card and slab";
      row.technique = v.technique;
      row.parameters = v.parameters;
      row.gpuMs = {{"shadow", v.shadowMs}, {"main", 0.35}};
      row.cpuMs = truth.lastQueryMs();
      row.shadowTriangles = truth.triangleCount();
      row.shadowTexels = 1024ull * 1024ull;
      row.hasHard = true;
      row.hard = compareHard(technique, reference);
      std::string stem = "thumbs/v" + std::to_string(index++);
      savePng(outDir + "/" + stem + ".png", greyscale(technique));
      savePng(outDir + "/" + stem + "_error.png", hardErrorHeatmap(technique, reference));
      row.imageThumbnail = stem + ".png";
      row.errorThumbnail = stem + "_error.png";
      rows.push_back(row);
      progress.advance();
    }
    progress.finish();

    Light area = light;
    area.area = AreaShape::Sphere;
    area.radius = 0.4f;
    ImageF soft = truth.softVisibility(view, area, 16, 1);
    ImageF hardAsSoft = reference;  // a hard shadow map used where the light is soft
    ReportRow softRow;
    softRow.scene = "card and slab, soft";
    softRow.technique = "hard shadow map";
    softRow.gpuMs = {{"shadow", 0.7}, {"main", 0.35}};
    softRow.hasSoft = true;
    softRow.soft = compareSoft(hardAsSoft, soft);
    savePng(outDir + "/thumbs/soft_error.png", softErrorHeatmap(hardAsSoft, soft));
    softRow.errorThumbnail = "thumbs/soft_error.png";
    rows.push_back(softRow);

    std::string html = writeReport(outDir, "report", rows, "measure_report_demo");
    std::printf("%s\n", html.c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "measure_report_demo: %s\n", e.what());
    return 1;
  }
}
