# shadowlab: two commands do everything (each installs what is missing first).
#   make run    the course: a launcher window, or without a display every lesson rendered into out/tour/
#   make test   every test through ctest, headless
#   make web    the lessons as WebGL2 pages in build/web/site (Debian's emscripten); make serve shows them
# Also: make build, make slides, make docs, make grade LESSON=01, make bench, make soak, make fuzz, make stub-hashes, make format, make clean;
# instructors: make handout (the student tree), make grade-submission SUBMISSION=DIR (public + hidden cases),
# make gradescope [LESSONS=03,05] (the Gradescope autograder zip), make grade-class SUBMISSIONS=DIR.
PRESET ?= default
BUILD  := build/$(PRESET)
JOBS   ?= $(shell nproc 2>/dev/null || echo 2)
CTEST_ARGS ?=

.PHONY: run test build deps configure node-tools web serve slides docs grade bench soak fuzz fuzz-build stub-hashes clean tour format handout grade-submission gradescope grade-class

deps:
	@bash tools/install-deps.sh

node-tools: deps
	@if [ ! -f tools/web/node_modules/.package-lock.json ] || [ tools/web/package-lock.json -nt tools/web/node_modules/.package-lock.json ]; then \
	  echo "npm: installing tools/web (reveal.js, KaTeX, playwright-core)"; npm ci --prefix tools/web --no-audit --no-fund; fi

configure: deps
	@cmake --preset $(PRESET) $(CMAKE_ARGS) >/dev/null

build: configure
	@cmake --build --preset $(PRESET) -j $(JOBS)

# The browser build: static pages (index.html and one page per lesson) for any web host.
web: node-tools build
	@SHADOWLAB_BIN=$(BUILD)/bin bash tools/wasm/build.sh build/web

serve: web
	@node tools/wasm/serve.mjs build/web/site $(PORT)

run: build
	@$(BUILD)/bin/shadowlab

tour: build
	@$(BUILD)/bin/shadowlab --tour out/tour

# Everything: unit, stress, shaders, GPU (headless EGL), graders' validity, slides and web pages;
# then the GL-free layers again under AddressSanitizer + UndefinedBehaviorSanitizer. Student
# grading (-L exNN) is left out: it grades exercises.cpp, which holds stubs until a student fills it.
test: node-tools build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -LE '^ex[0-9]+$$' $(CTEST_ARGS)
	@cmake --preset sanitize >/dev/null && cmake --build --preset sanitize -j $(JOBS)
	@cd build/sanitize && ASAN_OPTIONS=detect_leaks=1 LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure -j $(JOBS) -L unit
	@$(MAKE) --no-print-directory fuzz-build && cd build/fuzz && ctest --output-on-failure -j $(JOBS) -L fuzz

# libFuzzer targets of the GL-free parsers (tests/fuzz), built with clang under ASan + UBSan.
# make fuzz runs each for FUZZ_RUNS executions and prints the figures (tools/fuzz.sh).
FUZZ_RUNS ?= 1000000
fuzz-build: deps
	@cmake --preset fuzz >/dev/null && cmake --build --preset fuzz -j $(JOBS)

fuzz: fuzz-build
	@bash tools/fuzz.sh build/fuzz $(FUZZ_RUNS)

slides: node-tools build
	@node tools/slides/build.mjs --bin $(BUILD)/bin --out out/slides

# The generated parts of the READMEs (each lesson's hotkeys and presets, the top README's lessons
# table) from the lessons themselves; `make test` checks them (docs.lesson_readmes).
docs: build
	@node tools/docs/lesson_docs.mjs --bin $(BUILD)/bin --write

LESSON ?= 01
# Grades lesson LESSON's exercises.cpp (and exercises.glsl, where the lesson has GLSL exercises):
# out/grades/exLESSON/{score.json, junit.xml, results.json (Gradescope)}. Each C++ exercise runs in
# a process of its own with a time and a memory limit (grade_isolated): a crash or an endless loop
# costs that exercise only, with the reason in the report.
grade: build
	@if [ ! -x $(BUILD)/bin/grade_ex$(LESSON) ]; then \
	  echo "make grade: LESSON=$(LESSON) has no grader; valid: $$(ls $(BUILD)/bin | sed -n 's/^grade_ex\([0-9][0-9]*\)$$/\1/p' | paste -sd ' ' -)" >&2; \
	  exit 2; fi
	@rm -rf out/grades/ex$(LESSON) && mkdir -p out/grades/ex$(LESSON); bin=$(BUILD)/bin; \
	  $$bin/grade_isolated --reference=$$bin/grade_ex$(LESSON)_reference --results-json=out/grades/ex$(LESSON)/cpp.json \
	    -- $$bin/grade_ex$(LESSON) >/dev/null; \
	  glsl=$$(ls $$bin/glsl_lesson_$(LESSON)_* 2>/dev/null | head -1); \
	  if [ -x $$bin/grade_ex$(LESSON)_glsl ] && [ -n "$$glsl" ]; then \
	    $$bin/grade_ex$(LESSON)_glsl --lesson-binary=$$glsl --images=out/grades/ex$(LESSON)/images \
	      --results-json=out/grades/ex$(LESSON)/glsl.json >/dev/null; fi; \
	  $$bin/grade_report --out out/grades/ex$(LESSON) out/grades/ex$(LESSON)/*.json

# The student handout: out/handout/shadowlab and out/handout/shadowlab-student.tar.gz (tools/handout).
HANDOUT ?= out/handout
handout: configure
	@if [ ! -f tools/handout/make_handout.sh ]; then echo "make handout: the instructor's tree only; this is the student handout, which has no reference sources to make one from" >&2; exit 2; fi
	@SHADOWLAB_BUILD=$(CURDIR)/$(BUILD) bash tools/handout/make_handout.sh $(HANDOUT)

# Grades a student's files against this tree with the hidden cases and a seed it chooses (SEED=N
# to fix it): out/grades/submission/{score.json, junit.xml, results.json}.
SUBMISSION ?=
GRADES ?= out/grades/submission
# A class: every submission in SUBMISSIONS (folders or archives), two at a time, with a CSV and an
# HTML summary (tools/grading/grade_class.sh): out/grades/class/.
grade-class: configure
	@if [ -z "$(SUBMISSIONS)" ]; then echo "usage: make grade-class SUBMISSIONS=DIR [LESSONS=03,05] [GRADES=OUT]" >&2; exit 2; fi
	@if [ ! -f tools/grading/grade_class.sh ]; then echo "make grade-class: the instructor's tree only" >&2; exit 2; fi
	@LESSONS=$(LESSONS) SEED=$(SEED) bash tools/grading/grade_class.sh $(SUBMISSIONS) $(if $(filter out/grades/submission,$(GRADES)),out/grades/class,$(GRADES))

# The Gradescope autograder zip of this tree (tools/grading/make_gradescope.sh): out/gradescope/.
GRADESCOPE ?= out/gradescope
gradescope:
	@if [ ! -f tools/grading/make_gradescope.sh ]; then echo "make gradescope: the instructor's tree only; this is the student handout, which has no hidden cases to grade with" >&2; exit 2; fi
	@LESSONS=$(LESSONS) bash tools/grading/make_gradescope.sh $(GRADESCOPE)

grade-submission: configure
	@if [ -z "$(SUBMISSION)" ]; then echo "usage: make grade-submission SUBMISSION=DIR [SEED=N] [GRADES=OUT] [LESSONS=03,05] [REFERENCE_CALLS=report]"; exit 2; fi
	@if [ ! -f tools/grading/grade_submission.sh ]; then echo "grade-submission: the instructor's tree only (the handout has no hidden cases)"; exit 2; fi
	@SEED=$(SEED) LESSONS=$(LESSONS) REFERENCE_CALLS=$(REFERENCE_CALLS) bash tools/grading/grade_submission.sh $(SUBMISSION) $(GRADES)

# Benchmarks, apart from the tests: every lesson's frame time against its floor (out/bench/frames.{csv,html},
# and docs/benchmarks.md: the README's one table, with the machine and date it ran on), the browser
# pages against them (tools/wasm/bench.mjs: download, first frame, frame ms, fps; a section of the same file),
# the PSM light-camera set-up against receiver count, lesson 01 over its presets against ground
# truth (report in out/bench/), and lesson 10's showdown (tools/showdown_bench.sh, out/bench/showdown).
# Lessons add their own sweeps: tools/shadow_bench.sh, tools/volume_bench.sh, filter_sweep (see the README).
bench: build web
	@mkdir -p out/bench
	@if [ -n "$$DISPLAY$$WAYLAND_DISPLAY" ]; then $(BUILD)/bin/frame_bench --bin $(BUILD)/bin --out out/bench --window --markdown docs/benchmarks.md; \
	  else xvfb-run -a -s "-screen 0 1920x1080x24" $(BUILD)/bin/frame_bench --bin $(BUILD)/bin --out out/bench --window --markdown docs/benchmarks.md; fi
	@node tools/wasm/bench.mjs --site build/web/site --native out/bench/frames.csv --markdown docs/benchmarks.md
	@$(BUILD)/bin/bench_psm_setup out/bench/psm_setup.csv
	@$(BUILD)/bin/shadowlab_bench $(BUILD)/bin/lesson_01_lighting --out out/bench/01_lighting \
	  --preset default --preset three_lights --preset spot_only --repeat 3 --frames 6
	@bash tools/showdown_bench.sh $(BUILD) out/bench/showdown

soak: build
	@cmake --build --preset $(PRESET) --target stress_soak

stub-hashes:
	@sha256sum lessons/*/exercises.cpp shaders/*/exercises.glsl > tests/grading/pristine.sha256 && cat tests/grading/pristine.sha256

# Applies .clang-format to every C++ file (the ctest format.check fails on any that does not conform).
format:
	@find common lessons tests tools bench -name '*.cpp' -o -name '*.hpp' | grep -v node_modules | xargs clang-format -i

clean:
	rm -rf build out
