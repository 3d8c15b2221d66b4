// The GLSL grader of one lesson (grade_exNN_glsl; SHADOWLAB_GLSL_LESSON names it at build time):
// the lesson's GLSL cases on the GPU (app/glsl_cases.hpp), then its renders: the lesson run
// headless with the student's exercises.glsl (impl=student) and with the reference, images and
// ground-truth figures compared within the stated tolerances. The lesson binary it runs is the
// lesson built with the REFERENCE C++ exercises, so only the GLSL is the student's.
//
//   grade_exNN_glsl --lesson-binary=PATH [--student=tree|reference|DIR] [--exercise=NN.k]
//                   [--seed=N] [--hidden-seed=N] [--images=DIR] [--results-json=F] [--score-json=F]
//                   [--junit=F] [--gradescope=F] [--expect-stub-scores-zero] [--cases-only]
//                   [--seeds=FROM-TO] [--record-reference=DIR] [--precomputed=DIR]
//
// The student handout withholds the reference GLSL: there the reference's side of every public
// case and render is what `make handout` recorded in the instructor's tree (--record-reference=DIR:
// DIR/<lesson>.json and DIR/<lesson>/render_K.{png,json}, the public cases and renders only) and
// ships in tests/grading/glsl/reference/ (app/glsl_cases.hpp, glslReferenceWithheld).
// --precomputed=DIR grades against such a recording in this tree (its validity tests), public
// cases only.
//
// --student: whose exercises.glsl: this tree's (default), the reference file (validity), or
// DIR/shaders/<lesson>/exercises.glsl (a submission). The last two run against a copy of the
// shader tree (SHADOWLAB_ROOT) with that file in place. A file that does not compile fails every
// case with the compiler's error. --cases-only leaves the renders out; --seeds runs the cases once
// per seed FROM..TO in one context (with --expect-stub-scores-zero: proof that no random hidden
// case is one the untouched stub passes by chance, whatever seed a grading run draws). Exit: 0 all passed, 1 a case
// failed (or none ran), 2 bad usage.
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/context.hpp"
#include "app/glsl_cases.hpp"
#include "core/image.hpp"
#include "core/paths.hpp"
#include "core/process.hpp"
#include "grading/checks.hpp"
#include "grading/report.hpp"

#ifndef SHADOWLAB_GLSL_LESSON
#error "SHADOWLAB_GLSL_LESSON (the lesson folder, e.g. 02_shadow_maps) must be defined by the build"
#endif

namespace fs = std::filesystem;
using namespace shadowlab;

namespace {

struct Options {
  std::string lessonBinary, student = "tree", exercise, images, recordDir, precomputed;
  std::string tree;            // this tree's root (its shaders hold the untouched stubs)
  bool studentIsStub = false;  // the student's exercises.glsl is this tree's untouched file
  grading::ReportFiles reports;
  bool expectStubsScoreZero = false, casesOnly = false;
  std::uint64_t seedFrom = 0, seedTo = 0;  // --seeds; seedTo == 0: the one seed in use
};

bool parseSeed(const std::string& text, std::uint64_t& out) {
  char* end = nullptr;
  const unsigned long long s = std::strtoull(text.c_str(), &end, 10);
  if (text.empty() || *end || text[0] == '-') return false;
  out = s;
  return true;
}

bool value(const std::string& arg, const char* flag, std::string& out) {
  const std::string f = std::string(flag) + "=";
  if (arg.rfind(f, 0) != 0) return false;
  out = arg.substr(f.size());
  return true;
}

int parse(int argc, char** argv, Options& o) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    std::string seed, seeds;
    if (value(a, "--lesson-binary", o.lessonBinary) || value(a, "--student", o.student) ||
        value(a, "--exercise", o.exercise) || value(a, "--images", o.images) ||
        value(a, "--results-json", o.reports.results) || value(a, "--score-json", o.reports.score) ||
        value(a, "--junit", o.reports.junit) || value(a, "--gradescope", o.reports.gradescope) ||
        value(a, "--record-reference", o.recordDir) || value(a, "--precomputed", o.precomputed))
      continue;
    if (a == "--expect-stub-scores-zero") {
      o.expectStubsScoreZero = true;
    } else if (a == "--cases-only") {
      o.casesOnly = true;
    } else if (const char* flag = value(a, "--seed", seed)          ? "--seed"
                                  : value(a, "--hidden-seed", seed) ? "--hidden-seed"
                                                                    : nullptr) {
      std::uint64_t s = 0;
      if (!parseSeed(seed, s)) {
        std::cerr << flag << "='" << seed << "' is not a non-negative integer\n";
        return 2;
      }
      (flag[2] == 's' ? grading::setSeed : grading::setHiddenSeed)(s);
    } else if (value(a, "--seeds", seeds)) {
      const auto dash = seeds.find('-');
      if (dash == std::string::npos || !parseSeed(seeds.substr(0, dash), o.seedFrom) ||
          !parseSeed(seeds.substr(dash + 1), o.seedTo) || o.seedTo < o.seedFrom) {
        std::cerr << "--seeds='" << seeds << "' is not FROM-TO, two non-negative integers with FROM <= TO\n";
        return 2;
      }
    } else {
      std::cerr << "unknown argument '" << a << "'; valid: --lesson-binary --student --exercise --seed "
                << "--hidden-seed --seeds --images --results-json --score-json --junit --gradescope "
                << "--expect-stub-scores-zero --cases-only --record-reference --precomputed\n";
      return 2;
    }
  }
  if (o.lessonBinary.empty()) {
    std::cerr << "--lesson-binary=PATH is required (the lesson built with the reference C++ exercises)\n";
    return 2;
  }
  return 0;
}

// The exercises.glsl that --student names (other than "tree").
fs::path studentFile(const std::string& student, const std::string& lesson) {
  return student == "reference" ? fs::path(sourceRoot()) / "shaders" / lesson / "exercises_reference.glsl"
                                : fs::path(student) / "shaders" / lesson / "exercises.glsl";
}

bool sameContents(const fs::path& a, const fs::path& b) {
  std::ifstream fa(a, std::ios::binary), fb(b, std::ios::binary);
  if (!fa || !fb) return false;
  return std::string(std::istreambuf_iterator<char>(fa), {}) == std::string(std::istreambuf_iterator<char>(fb), {});
}

// A copy of the shader tree with the student's exercises.glsl in place; lessons/ and textures/
// are links to this tree. Returns the new root ("" for this tree as it is).
std::string stageRoot(const std::string& student, const std::string& lesson, std::string& error) {
  if (student == "tree") return "";
  const fs::path tree = sourceRoot();
  const fs::path file = studentFile(student, lesson);
  if (!fs::is_regular_file(file)) {
    error = "no student file " + file.string();
    return "";
  }
  const fs::path root = fs::temp_directory_path() / ("shadowlab_glsl_" + lesson + "_" + std::to_string(getpid()));
  std::error_code ec;
  fs::remove_all(root, ec);
  fs::create_directories(root);
  fs::copy(tree / "shaders", root / "shaders", fs::copy_options::recursive);
  fs::copy_file(file, root / "shaders" / lesson / "exercises.glsl", fs::copy_options::overwrite_existing);
  for (const char* dir : {"lessons", "textures"}) fs::create_directory_symlink(tree / dir, root / dir);
  return root.string();
}

struct Render {
  int exit = 0;
  std::string png, measure, log;
};

// One run of the lesson at the render's placement. side names its files (student, reference,
// stub); impl=student runs an exercises.glsl: the student's (SHADOWLAB_ROOT as staged), or with
// root set, the one under that root.
Render renderLesson(const Options& o, const GlslRender& r, const std::string& side, bool student, const fs::path& dir,
                    const std::string& root = "") {
  Render out;
  out.png = (dir / (side + ".png")).string();
  out.measure = (dir / (side + ".json")).string();
  std::vector<std::string> args{o.lessonBinary, "--headless", "--frames",     "2",
                                "--size",       "320x180",    "--screenshot", out.png};
  if (r.measure) args.insert(args.end(), {"--measure", out.measure});
  args.insert(args.end(), r.args.begin(), r.args.end());
  args.insert(args.end(), {"--set", student ? "impl=student" : "impl=reference"});
  const std::string log = (dir / (side + ".log")).string();
  ProcessOptions options;
  options.stdoutPath = log;  // stderr too: the compile error, file:line
  options.setEnv = {"SHADOWLAB_STRICT_GL=1"};
  if (!root.empty()) options.setEnv.push_back("SHADOWLAB_ROOT=" + root);
  out.exit = runProcess(args, options);
  std::ifstream in(log);
  out.log.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return out;
}

std::string commandLine(const GlslRender& r) {
  std::string s;
  for (const auto& a : r.args) s += " " + a;
  return s;
}

// The student's render against the reference's: pixels, then the ground-truth figures.
std::string compareRenders(const GlslRender& r, const Render& mine, const Render& ref) {
  const Image8 a = loadImage(mine.png, 3), b = loadImage(ref.png, 3);
  const ImageDiff d = compareImages(a, b, r.channelTolerance);
  const double share = double(d.differingPixels) / double(std::size_t(a.width) * a.height);
  std::string why;
  if (share > r.maxDifferingShare)
    why += "\n  differing pixels  " + grading::show(100 * share) + "% differ by more than " +
           std::to_string(r.channelTolerance) + "/255 in a channel (tolerance " +
           grading::show(100 * r.maxDifferingShare) + "%)";
  if (!r.measure) return why;
  std::ifstream fm(mine.measure), fr(ref.measure);
  const nlohmann::json jm = nlohmann::json::parse(fm, nullptr, false), jr = nlohmann::json::parse(fr, nullptr, false);
  // Hard shadows: percentages of the pixels, within figureTolerance points. Soft shadows (lesson
  // 05): the umbra percentages the same way, and the RMSE of V (0..1) within figureTolerance / 100,
  // the same share of the scale.
  struct Figure {
    const char *group, *name;
    double scale;
  };
  const Figure figures[] = {{"hard", "misclassified_pct", 1}, {"hard", "leak_pct", 1},
                            {"hard", "false_shadow_pct", 1},  {"soft", "rmse", 0.01},
                            {"soft", "umbra_over_pct", 1},    {"soft", "umbra_under_pct", 1}};
  int compared = 0;
  for (const Figure& f : figures) {
    if (!jr.is_object() || !jr.contains(f.group)) continue;
    ++compared;
    const double vr = jr[f.group].value(f.name, 0.0);
    const double vm = jm.is_object() && jm.contains(f.group) ? jm[f.group].value(f.name, -1e9) : -1e9;
    const double tolerance = r.figureTolerance * f.scale;
    if (std::abs(vm - vr) > tolerance)
      why += std::string("\n  ") + f.group + "." + f.name + "  expected " + grading::show(vr) + ", actual " +
             grading::show(vm) + " (tolerance " + grading::show(tolerance) + ", against Embree ground truth)";
  }
  if (compared == 0) why += "\n  the reference run measured no ground-truth figures (a grader bug)";
  return why;
}

// Whether the reference's render can grade the answer (grading::renderInformative).
bool informative(const Render& ref, std::string& why) {
  std::ifstream in(ref.measure);
  return grading::renderInformative(nlohmann::json::parse(in, nullptr, false), why);
}

// The precomputed reference render of a public render (the handout, app/glsl_cases.hpp): the image
// and figures --record-reference wrote for the same name and command line, or why there is none.
std::optional<Render> precomputedRender(const std::string& lesson, const GlslRender& r, std::string& why) {
  const fs::path dir = precomputedGlslDir();
  std::ifstream in(dir / (lesson + ".json"));
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (!j.is_object() || !j.contains("renders") || !j["renders"].is_array()) {
    why = "no precomputed reference renders in " + (dir / (lesson + ".json")).string() +
          " (`make handout` writes them in the instructor's tree)";
    return std::nullopt;
  }
  for (const nlohmann::json& e : j["renders"]) {
    if (e.value("name", "") != r.name) continue;
    if (e.value("args", std::vector<std::string>{}) != r.args) {
      why = "the precomputed reference render was made with other arguments than" + commandLine(r);
      return std::nullopt;
    }
    Render ref;
    ref.png = (dir / e.value("image", "")).string();
    ref.measure = e.value("measure", "").empty() ? "" : (dir / e.value("measure", "")).string();
    if (!fs::is_regular_file(ref.png)) {
      why = "the precomputed reference image " + ref.png + " is missing";
      return std::nullopt;
    }
    return ref;
  }
  why = "no precomputed reference render named '" + r.name + "' in " + (dir / (lesson + ".json")).string();
  return std::nullopt;
}

grading::CaseResult renderCase(const Options& o, const std::string& lesson, GlslRender r, int index) {
  grading::CaseResult c;
  c.name = r.name;
  c.exercise = grading::exerciseOf(r.name);
  c.file = "tests/grading/glsl_grader.cpp";
  c.hidden = r.hidden;
  c.stub = glslStubPresent(lesson, c.exercise);
  const fs::path dir = o.images.empty() ? fs::temp_directory_path() / ("shadowlab_render_" + std::to_string(getpid()))
                                        : fs::path(o.images);
  const fs::path caseDir = dir / (lesson + "_render_" + std::to_string(index));
  fs::create_directories(caseDir);
  // A random placement grades only if the reference's render shows enough (informative) and the
  // untouched stub's render of it differs from the reference's beyond the tolerances: where they
  // match (the lesson drew no face map, the exercise's code never ran in view), the stub would
  // pass. The placement follows from the seed alone, never from the student's answer.
  const bool random = r.redraw && r.measure;
  const std::string stubSide = o.studentIsStub ? "student" : "stub";
  // Where the reference GLSL is withheld (the handout) its render is the precomputed one.
  const bool withheld = glslReferenceWithheld(lesson);
  std::string missing = random && withheld ? "a random placement has no precomputed reference render" : "";
  std::optional<Render> precomputed = withheld && !random ? precomputedRender(lesson, r, missing) : std::nullopt;
  if (withheld) {
    if (!precomputed) {
      c.output = "lesson " + lesson + commandLine(r) + "\n  " + missing;
      return c;
    }
    fs::copy_file(precomputed->png, caseDir / "reference.png", fs::copy_options::overwrite_existing);
  }
  Render ref = withheld ? *precomputed : renderLesson(o, r, "reference", false, caseDir), stub;
  bool haveStub = false;
  std::string why, redrawn;
  auto gradable = [&] {
    haveStub = false;
    if (!random || ref.exit != 0) return true;
    if (!informative(ref, why)) return false;
    stub = renderLesson(o, r, stubSide, true, caseDir, o.tree);
    haveStub = true;
    if (stub.exit != 0) return why = "the untouched stub's run failed, exit " + std::to_string(stub.exit), false;
    if (!compareRenders(r, stub, ref).empty()) return true;
    return why = "the untouched stub's render matches the reference's", false;
  };
  constexpr int kDraws = 8;
  bool ok = gradable();
  for (int attempt = 1; !ok && attempt <= kDraws; ++attempt) {
    redrawn += "\n  drawn again:" + commandLine(r) + " (" + why + ")";
    std::cout << "[shadowlab] " << r.name << ": placement drawn again, the reference's render of" << commandLine(r)
              << " cannot grade (" << why << ")\n";
    r.args = r.redraw(attempt);
    ref = renderLesson(o, r, "reference", false, caseDir);
    ok = gradable();
  }
  const bool uninformative = !ok;
  const Render mine = haveStub && o.studentIsStub ? stub : renderLesson(o, r, "student", true, caseDir);
  const std::string what = "lesson " + lesson + commandLine(r) + ", impl=student against impl=reference (320x180" +
                           (withheld ? ", the reference's render precomputed)" : ")");
  if (uninformative)
    c.output = what + "\n  no placement in " + std::to_string(kDraws + 1) + " draws can grade (a grader bug): " + why +
               redrawn;
  else if (ref.exit != 0)
    c.output = what + "\n  the reference run failed (a grader bug), exit " + std::to_string(ref.exit) + ": " + ref.log;
  else if (mine.exit != 0)
    c.output = what + "\n  your run failed, exit " + std::to_string(mine.exit) + ":\n" + mine.log;
  else c.output = compareRenders(r, mine, ref);
  c.passed = c.output.empty();
  if (!c.passed && c.output.rfind("lesson ", 0) != 0) {
    savePng((caseDir / "difference.png").string(), diffImage(loadImage(mine.png, 3), loadImage(ref.png, 3), 4.0f));
    c.output = what + c.output +
               (o.images.empty() ? "\n  images: grade with --images=DIR to keep them (make grade LESSON=NN keeps them "
                                   "in out/grades/exNN/images)"
                                 : "\n  images: " + caseDir.string() + "/{student,reference,difference}.png") +
               redrawn;
  }
  if (o.images.empty()) fs::remove_all(dir);
  return c;
}

grading::RunResult grade(const Options& o, const std::string& lesson) {
  // Against precomputed reference values (the handout, --precomputed) the public cases only: the
  // hidden ones are the instructor's, who grades them with the reference GLSL.
  std::optional<GlslExerciseSet> set = glslExercises(lesson, /*withHidden=*/!glslReferenceWithheld(lesson));
  grading::RunResult run;
  run.suite = "grade_ex" + lesson.substr(0, 2) + "_glsl";
  run.seed = grading::seed();
  run.hiddenSeed = grading::hiddenSeed();
  if (!set) return run;
  auto selected = [&](const std::string& name) {
    return o.exercise.empty() || grading::exerciseOf(name) == o.exercise;
  };
  std::erase_if(set->cases, [&](const GlslCase& c) { return !selected(c.name); });
  std::erase_if(set->renders, [&](const GlslRender& r) { return !selected(r.name); });
  if (!set->cases.empty()) {
    auto context = createHeadlessContext({64, 64, "GLSL cases", false, false});
    run.cases = runGlslCases(*set).cases;
  }
  for (std::size_t i = 0; i < set->renders.size() && !o.casesOnly; ++i)
    run.cases.push_back(renderCase(o, lesson, set->renders[i], int(i)));
  run.testCasesRun = int(run.cases.size());
  return run;
}

// --record-reference=DIR: the reference's side of every public case and render, for the student
// handout, which withholds the reference GLSL (app/glsl_cases.hpp). Needs this tree's reference.
int record(const Options& o, const std::string& lesson) {
  if (glslReferenceWithheld(lesson)) {
    std::cerr << "--record-reference needs the reference GLSL (the instructor's tree); this tree withholds " << lesson
              << "/exercises_reference.glsl\n";
    return 2;
  }
  const std::optional<GlslExerciseSet> set = glslExercises(lesson, /*withHidden=*/false);
  if (!set) {
    std::cerr << "lesson " << lesson << " has no GLSL exercises to record\n";
    return 1;
  }
  nlohmann::json j = {{"lesson", lesson},
                      {"seed", grading::seed()},
                      {"cases", nlohmann::json::array()},
                      {"renders", nlohmann::json::array()}};
  {
    auto context = createHeadlessContext({64, 64, "GLSL reference values", false, false});
    std::string error;
    for (const auto& [c, v] : glslReferenceValues(*set, error))
      j["cases"].push_back({{"name", c->name}, {"expression", c->expression}, {"value", {v.x, v.y, v.z, v.w}}});
    if (!error.empty()) {
      std::cerr << "the reference GLSL does not compile: " << error << "\n";
      return 1;
    }
  }
  const fs::path dir = fs::path(o.recordDir) / lesson;
  fs::create_directories(dir);
  for (std::size_t i = 0; i < set->renders.size(); ++i) {
    const GlslRender& r = set->renders[i];
    const std::string side = "render_" + std::to_string(i);
    const Render ref = renderLesson(o, r, side, false, dir);
    for (const fs::directory_entry& e : fs::directory_iterator(dir))  // the log, --measure's other images
      if (e.path().stem().string().rfind(side + "_", 0) == 0 || e.path().extension() == ".log") fs::remove(e.path());
    if (ref.exit != 0) {
      std::cerr << "the reference render of '" << r.name << "' failed, exit " << ref.exit << ": " << ref.log << "\n";
      return 1;
    }
    j["renders"].push_back({{"name", r.name},
                            {"args", r.args},
                            {"image", lesson + "/" + side + ".png"},
                            {"measure", r.measure ? lesson + "/" + side + ".json" : ""}});
  }
  std::ofstream(fs::path(o.recordDir) / (lesson + ".json")) << j.dump(1) << "\n";
  std::cout << "[shadowlab] recorded " << j["cases"].size() << " reference values and " << j["renders"].size()
            << " reference renders of " << lesson << " in " << o.recordDir << "\n";
  return 0;
}

// Messages name the files a student can open: the staged copy of their exercises.glsl is their
// own file, the rest of the staged tree is this tree (the staged folder is gone by then).
void unstage(grading::RunResult& run, const std::string& root, const std::string& studentGlsl,
             const std::string& lesson, const std::string& tree) {
  auto replaceAll = [](std::string& text, const std::string& from, const std::string& to) {
    std::string out;
    std::size_t start = 0;
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, start)) {
      out.append(text, start, at - start).append(to);
      start = at + from.size();
    }
    text = out.append(text, start, std::string::npos);
  };
  for (grading::CaseResult& c : run.cases) {
    replaceAll(c.output, root + "/shaders/" + lesson + "/exercises.glsl", studentGlsl);
    replaceAll(c.output, root, tree);
  }
}

void print(const grading::RunResult& run) {
  int failed = 0;
  for (const grading::CaseResult& c : run.cases) {
    if (c.passed) continue;
    ++failed;
    std::cout << "===============================================================================\n"
              << "FAILED: " << c.name << (c.hidden ? " [hidden]" : "") << "\n"
              << c.output << "\n";
  }
  std::cout << "===============================================================================\n"
            << "[shadowlab] GLSL cases: " << run.cases.size() << " | " << run.cases.size() - failed << " passed | "
            << failed << " failed (seed " << run.seed << ")\n";
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (int e = parse(argc, argv, o)) return e;
  if (const char* env = std::getenv("SHADOWLAB_SEED")) grading::setSeed(std::strtoull(env, nullptr, 10));
  const std::string lesson = SHADOWLAB_GLSL_LESSON;
  // The handout's recording, found in this tree before a submission is staged in a copy of its shaders.
  if (o.precomputed.empty() && glslReferenceWithheld(lesson)) o.precomputed = precomputedGlslDir();
  if (!o.precomputed.empty()) setPrecomputedGlslDir(fs::absolute(o.precomputed).string());
  if (!o.recordDir.empty()) return record(o, lesson);
  std::string error;
  o.tree = sourceRoot();
  o.studentIsStub = o.student == "tree" || sameContents(studentFile(o.student, lesson),
                                                        fs::path(o.tree) / "shaders" / lesson / "exercises.glsl");
  const std::string root = stageRoot(o.student, lesson, error);
  if (!error.empty()) {
    std::cerr << "grade_glsl: " << error << "\n";
    return 2;
  }
  if (!root.empty()) setenv("SHADOWLAB_ROOT", root.c_str(), 1);
  if (o.seedTo != 0 || o.seedFrom != 0) {  // --seeds: the cases once per seed, every failure named
    int bad = 0;
    for (std::uint64_t s = o.seedFrom;; ++s) {
      grading::setSeed(s);
      const grading::RunResult run = grade(o, lesson);
      std::ostringstream quiet;
      if (run.cases.empty()) {
        std::cerr << "[shadowlab] no GLSL case ran with seed " << s << "\n";
        ++bad;
      } else if (o.expectStubsScoreZero ? !grading::stubsScoreZero({run}, quiet, std::cerr)
                                        : std::any_of(run.cases.begin(), run.cases.end(),
                                                      [](const grading::CaseResult& c) { return !c.passed; })) {
        std::cerr << "[shadowlab] seed " << s << ": " << (o.expectStubsScoreZero ? "a stub passes" : "a case fails")
                  << " (replay: --seed=" << s << ")\n";
        ++bad;
      }
      if (s == o.seedTo) break;  // FROM-TO may end at the largest seed
    }
    if (!root.empty()) fs::remove_all(root);
    std::cout << "[shadowlab] " << o.seedTo - o.seedFrom + 1 << " seeds (" << o.seedFrom << "-" << o.seedTo
              << "): " << bad << (o.expectStubsScoreZero ? " where a stub passed a case" : " with a failing case")
              << "\n";
    return bad == 0 ? 0 : 1;
  }
  grading::RunResult run = grade(o, lesson);
  if (!root.empty()) {
    fs::remove_all(root);
    unstage(run, root, studentFile(o.student, lesson).string(), lesson, o.tree);
  }
  print(run);
  if (!grading::writeReports(o.reports, {run}, std::cerr)) return 1;
  if (run.cases.empty()) {
    std::cerr << "[shadowlab] no GLSL case ran" << (o.exercise.empty() ? "" : " for exercise " + o.exercise) << "\n";
    return 1;
  }
  if (o.expectStubsScoreZero) return grading::stubsScoreZero({run}, std::cout, std::cerr) ? 0 : 1;
  for (const grading::CaseResult& c : run.cases)
    if (!c.passed) return 1;
  return 0;
}
