#!/usr/bin/env python3
"""The shadowlab autograder's two steps around grade_submission.sh (run_autograder calls both).

  autograder.py place SUBMISSION STAGE TREE LESSONS
      Puts the student's files where the course has them, in STAGE: lessons/NN_name/exercises.cpp
      and shaders/NN_name/exercises.glsl. A whole handout tree (at any depth: a zip unpacked in a
      folder) is placed by its paths; a flat upload by what each file is: a C++ file by its
      `namespace shadowlab::exNN`, a GLSL file by its "// Lesson NN" heading, either by a lesson
      number in its name (exercises_03.glsl), or, in a one-lesson assignment, by being the only one
      of its kind. Prints one line per file it placed, ignored or could not place, with why.
  autograder.py finish GRADE_DIR RESULTS_JSON PLACEMENT LOG EXIT_CODE
      Writes Gradescope's results.json: the grade's (grade_report's), with the placement lines and
      the grader's summary as its top-level output; when grading failed, a zero with the log's end.
LESSONS: "03,05" or "" (every lesson with exercises).
"""
import json
import re
import sys
from pathlib import Path

SKIP_DIRS = {"__MACOSX", ".git", "build", "out", "node_modules"}


def lessons_of(tree: Path, wanted: str):
    """{"03": "03_shadow_quality"} for the lessons of this assignment, and which have GLSL."""
    names = {d.name[:2]: d.name for d in sorted((tree / "lessons").iterdir()) if (d / "exercises.cpp").is_file()}
    glsl = {nn for nn, name in names.items() if (tree / "shaders" / name / "exercises.glsl").is_file()}
    if wanted.strip():
        keep = {n.strip().zfill(2) for n in wanted.split(",") if n.strip()}
        names = {nn: name for nn, name in names.items() if nn in keep}
    return names, {nn for nn in glsl if nn in names}


def number_in_name(path: Path, lessons):
    found = [nn for nn in re.findall(r"(?<!\d)(\d{1,2})(?!\d)", path.stem) if nn.zfill(2) in lessons]
    return found[0].zfill(2) if len(found) == 1 else None


def identify(path: Path, rel: str, lessons, glsl_lessons):
    """(lesson, kind, how) or (None, kind, why not)."""
    kind = "cpp" if path.suffix in (".cpp", ".cc", ".cxx") else "glsl" if path.suffix == ".glsl" else None
    if kind is None:
        return None, None, "not graded (only exercises.cpp and exercises.glsl are)"
    m = re.search(r"(?:^|/)(?:lessons|shaders)/(\d\d)_[^/]+/exercises\.(cpp|glsl)$", rel)
    if m and m.group(2) == kind:
        return m.group(1), kind, "by its path"
    text = path.read_text(errors="replace")
    if kind == "cpp":
        m = re.search(r"namespace\s+shadowlab\s*::\s*ex(\d\d)\b|namespace\s+ex(\d\d)\s*\{", text)
        if m:
            return m.group(1) or m.group(2), kind, "by its namespace"
    else:
        m = re.search(r"^\s*//\s*Lesson\s+(\d\d)\b", "\n".join(text.splitlines()[:20]), re.M)
        if m:
            return m.group(1), kind, "by its heading"
    nn = number_in_name(path, lessons)
    if nn:
        return nn, kind, "by the number in its name"
    candidates = sorted(lessons) if kind == "cpp" else sorted(glsl_lessons)
    if len(candidates) == 1:
        return candidates[0], kind, "the assignment's only " + ("C++" if kind == "cpp" else "GLSL") + " file"
    what = "`namespace shadowlab::exNN` line" if kind == "cpp" else '"// Lesson NN" first line'
    return None, kind, f"cannot tell which lesson it is for: it has no {what} and no lesson number in its name"


def place(submission: Path, stage: Path, tree: Path, wanted: str) -> int:
    lessons, glsl_lessons = lessons_of(tree, wanted)
    placed = {}
    lines = []
    files = sorted(p for p in submission.rglob("*") if p.is_file() and not SKIP_DIRS & set(p.relative_to(submission).parts))
    for path in files:
        rel = path.relative_to(submission).as_posix()
        nn, kind, how = identify(path, rel, lessons, glsl_lessons)
        if nn is None:
            lines.append(f"{rel}: {how}" + (": not graded" if kind else ""))
            continue
        if nn not in lessons:
            lines.append(f"{rel}: lesson {nn} is not part of this assignment (lessons {', '.join(sorted(lessons))}): not graded")
            continue
        if kind == "glsl" and nn not in glsl_lessons:
            lines.append(f"{rel}: lesson {nn} has no GLSL exercises: not graded")
            continue
        target = f"lessons/{lessons[nn]}/exercises.cpp" if kind == "cpp" else f"shaders/{lessons[nn]}/exercises.glsl"
        if target in placed:
            lines.append(f"{rel}: is also lesson {nn}'s {kind} file; {placed[target]} is graded, this one is not")
            continue
        placed[target] = rel
        (stage / target).parent.mkdir(parents=True, exist_ok=True)
        (stage / target).write_bytes(path.read_bytes())
        lines.append(f"{rel}: graded as {target} ({how})")
    for nn, name in sorted(lessons.items()):
        for target in [f"lessons/{name}/exercises.cpp"] + ([f"shaders/{name}/exercises.glsl"] if nn in glsl_lessons else []):
            if target not in placed:
                lines.append(f"no {target} in the submission: graded as the untouched stub (0 points)")
    print("\n".join(lines))
    return 0


def finish(grade: Path, results: Path, placement: Path, log: Path, code: int) -> int:
    notes = placement.read_text() if placement.is_file() else ""
    log_text = log.read_text(errors="replace") if log.is_file() else ""
    source = grade / "results.json"
    if code == 0 and source.is_file():
        data = json.loads(source.read_text())
        data["output"] = "Your files:\n" + notes + "\n" + data.get("output", "")
    else:
        tail = "\n".join(log_text.splitlines()[-40:])
        data = {"score": 0, "output": "Your files:\n" + notes + f"\nGrading failed (exit {code}); the grader's last lines:\n" + tail, "tests": []}
    results.parent.mkdir(parents=True, exist_ok=True)
    results.write_text(json.dumps(data, indent=2))
    return 0


if __name__ == "__main__":
    a = sys.argv[1:]
    if len(a) == 5 and a[0] == "place":
        sys.exit(place(Path(a[1]), Path(a[2]), Path(a[3]), a[4]))
    if len(a) == 6 and a[0] == "finish":
        sys.exit(finish(Path(a[1]), Path(a[2]), Path(a[3]), Path(a[4]), int(a[5])))
    print(__doc__, file=sys.stderr)
    sys.exit(2)
