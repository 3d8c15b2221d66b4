// The showdown's registry of techniques (lessons/10_showdown/showdown_techniques, with lesson 05's
// soft ones): every entry is a technique of that name with its parameters under its prefix, has its
// preset in the showdown's presets (which gpu.10_showdown.golden renders and compares, strict GL)
// and its row in the benchmark (tools/showdown_bench.sh). Adding a technique without its preset or
// its benchmark row fails here.
#include <doctest/doctest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "05_soft_shadows/soft_techniques.hpp"
#include "10_showdown/showdown_techniques.hpp"
#include "core/params.hpp"
#include "test_support.hpp"

using namespace shadowlab;

namespace {
std::string readFile(const std::string& path) {
  std::ifstream in(path);
  REQUIRE_MESSAGE(in, "cannot read " << path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

TEST_CASE("registry: every showdown technique is named as its entry, under its own prefix") {
  tech::TechniqueSet set(tech::showdownTechniques());
  std::set<std::string> names;
  for (int i = 0; i < set.size(); ++i) {
    CAPTURE(set.entry(i).name);
    CHECK(set[i].name() == set.entry(i).name);
    CHECK(names.insert(set.entry(i).name).second);  // no name twice
  }
  ParamRegistry r;
  set.declare(r);  // a clash of two prefixes would throw "registered twice"
  for (const Param& p : r.params()) {
    const std::string prefix = p.name.substr(0, p.name.find('.'));
    CAPTURE(p.name);
    CHECK(names.count(prefix) == 1);
  }
}

TEST_CASE("registry: lesson 05's soft techniques are the showdown's, in the same order") {
  const auto soft = tech::softTechniques();
  const tech::TechniqueSet all(tech::showdownTechniques());
  int at = all.indexOf(soft.front().name);
  for (const tech::TechniqueEntry& e : soft) {
    CAPTURE(e.name);
    REQUIRE(at < all.size());
    CHECK(all.entry(at).name == e.name);
    CHECK(all.entry(at).preset == e.preset);
    ++at;
  }
}

TEST_CASE("registry: every technique has its preset, a golden image of it, and its benchmark row") {
  const std::string root = test::sourceTree();
  const PresetFile presets = PresetFile::load(root + "/lessons/10_showdown/presets.txt");
  const std::string bench = readFile(root + "/tools/showdown_bench.sh");
  // The map techniques the script runs at every budget: map_techniques="uniform psm ...".
  std::set<std::string> mapTechniques;
  const auto at = bench.find("\nmap_techniques=\"");
  REQUIRE_MESSAGE(at != std::string::npos, "tools/showdown_bench.sh has no map_techniques=\"...\" line");
  const auto from = at + 17, to = bench.find('"', from);
  std::istringstream list(bench.substr(from, to - from));
  for (std::string t; list >> t;) mapTechniques.insert(t);
  CHECK(mapTechniques.size() >= 5);
  const tech::TechniqueSet set(tech::showdownTechniques());
  for (int i = 0; i < set.size(); ++i) {
    const tech::TechniqueEntry& e = set.entry(i);
    CAPTURE(e.name);
    CAPTURE(e.preset);
    const Preset* p = presets.find(e.preset);
    REQUIRE_MESSAGE(p, "no preset [" << e.preset << "] in lessons/10_showdown/presets.txt");
    bool picks = false;
    for (const PresetValue& v : p->values) picks = picks || (v.name == "technique" && v.value == e.name);
    CHECK_MESSAGE(picks, "[" << e.preset << "] does not set technique = " << e.name);
    CHECK_MESSAGE(std::ifstream(root + "/tests/data/golden/10_showdown/" + e.preset + ".png").good(),
                  "no golden image of [" << e.preset << "] (SHADOWLAB_RECORD_GOLDEN=missing ctest -R golden)");
    const bool benchmarked =
        bench.find("technique=" + e.name + " ") != std::string::npos || mapTechniques.count(e.name);
    CHECK_MESSAGE(benchmarked, "tools/showdown_bench.sh has no configuration with technique=" << e.name);
  }
}
