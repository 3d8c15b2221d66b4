// Light-camera set-up cost of PSM fix 2 ([Kozlov2004] §4.1): clipping N receiver boxes against the
// view frustum, moving the key points to post-projective space and fitting the smallest cone.
// Usage: bench_psm_setup [out.csv]   (CSV to stdout without an argument). Median of repeats, in the
// thread's CPU time (CLOCK_THREAD_CPUTIME_ID): on a machine shared with other builds, wall time
// counts the time the thread waited for a core.
#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

#include "algorithms/psm/psm_camera.hpp"

using namespace shadowlab;
using namespace shadowlab::psm;

namespace {
double cpuMicroseconds() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e6 + double(t.tv_nsec) * 1e-3;
}
}  // namespace

int main(int argc, char** argv) {
  // A street-level camera (Zf/Zn = 1e4) and a low sun from behind-left: the hard case of §4.
  const glm::dmat4 view = lookAlong(glm::dvec3(0, 2, 0), glm::dvec3(0.2, -0.1, -1.0));
  const CameraFrustum cam = makeCamera(view, 60.0 * std::numbers::pi / 180.0, 16.0 / 9.0, 0.5, 5000.0);
  const glm::dvec4 light(-0.4, 0.5, 0.6, 0.0);
  std::uint64_t s = 12345;
  auto rnd = [&] {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    return (s >> 11) * (1.0 / 9007199254740992.0);
  };
  std::vector<Aabb> all;
  for (int i = 0; i < 100000; ++i) {  // buildings on a 4 km square in front of the camera
    Aabb b;
    const double x = (rnd() - 0.5) * 4000, z = -rnd() * 4000, w = 2 + 20 * rnd(), h = 3 + 40 * rnd();
    b.min = glm::vec3(x - w, 0, z - w);
    b.max = glm::vec3(x + w, h, z + w);
    all.push_back(b);
  }
  // One optional argument, the CSV's path: anything like a flag, or more than one, is a mistake
  // (a "--help" once became a file of that name).
  const std::string usage = "usage: bench_psm_setup [out.csv] (the CSV to stdout without one)";
  if (argc == 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h")) {
    std::cout << usage << '\n';
    return 0;
  }
  if (argc > 2 || (argc == 2 && (argv[1][0] == '-' || argv[1][0] == '\0'))) {
    std::cerr << "bench_psm_setup: unexpected argument '" << argv[argc > 2 ? 2 : 1] << "'; " << usage << '\n';
    return 2;
  }
  std::ofstream file;
  if (argc > 1) {
    file.open(argv[1]);
    if (!file) {
      std::cerr << "bench_psm_setup: cannot write " << argv[1] << '\n';
      return 2;
    }
  }
  std::ostream& csv = argc > 1 ? static_cast<std::ostream&>(file) : std::cout;
  csv << "boxes,median_us,min_us,per_box_ns,key_points,status\n";
  std::cout << "boxes      median (us)   min (us)   per box (ns)   key points   status\n";
  PsmFitter fitter;
  for (int n : {10, 100, 1000, 10000, 100000}) {
    const std::span<const Aabb> boxes(all.data(), n);
    fitter.fit(cam, light, boxes);  // warm the buffers: per-frame calls do not allocate
    const int repeats = n <= 1000 ? 201 : (n <= 10000 ? 41 : 11);
    std::vector<double> us;
    for (int r = 0; r < repeats; ++r) {
      const double t0 = cpuMicroseconds();
      fitter.fit(cam, light, boxes);
      us.push_back(cpuMicroseconds() - t0);
    }
    std::nth_element(us.begin(), us.begin() + us.size() / 2, us.end());
    const double med = us[us.size() / 2];
    // The least: the cost with the core to itself (the median also carries the neighbours' load).
    const double least = *std::min_element(us.begin(), us.end());
    const char* status = fitter.result().status == FitStatus::Ok            ? "ok"
                         : fitter.result().status == FitStatus::ConeTooWide ? "cone-too-wide"
                                                                            : "no-receivers";
    std::printf("%-10d %12.2f %10.2f %14.1f %12zu   %s\n", n, med, least, med * 1000.0 / n,
                fitter.worldKeyPoints().size(), status);
    csv << n << ',' << med << ',' << least << ',' << med * 1000.0 / n << ',' << fitter.worldKeyPoints().size() << ','
        << status << '\n';
  }
  return 0;
}
