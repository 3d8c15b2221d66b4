#!/usr/bin/env python3
"""class_report.py OUT: the class summary of a grade-class run (tools/grading/grade_class.sh).

Reads OUT/STUDENT/grade/{score.json, results.json, logs/reference_calls.txt} and writes
OUT/class.csv (one row per student: total, maximum, points per exercise, what went wrong) and
OUT/class.html (the same table, the cases most students fail with a message of each, the
submissions that did not compile or could not be graded, and the answers borrowed from the
reference). Prints one line with where they are.
"""
import csv
import html
import json
import sys
from collections import defaultdict
from pathlib import Path


def number(x: float) -> str:
    return f"{x:.2f}".rstrip("0").rstrip(".")


def student_rows(out: Path):
    rows, failing = [], defaultdict(lambda: {"students": set(), "hidden": False, "message": ""})
    for dir in sorted(p for p in out.iterdir() if p.is_dir() and not p.name.startswith(".")):
        grade = dir / "grade"
        row = {"student": dir.name, "score": "", "max": "", "exercises": {}, "problems": []}
        score = grade / "score.json"
        if not score.is_file():
            log = (dir / "grade.log").read_text(errors="replace").splitlines() if (dir / "grade.log").is_file() else []
            row["problems"].append("not graded: " + (log[-1] if log else "no log"))
            rows.append(row)
            continue
        s = json.loads(score.read_text())
        row["score"], row["max"] = number(s["score"]), number(s["max_score"])
        row["exercises"] = {k: number(v["points"]) for k, v in s["exercises"].items()}
        for suite in s.get("seeds", {}):
            if suite.endswith("(did not compile)"):
                nn = suite.replace("grade_ex", "").split("_")[0]
                row["problems"].append(f"lesson {nn}'s exercises.cpp did not compile")
        results = grade / "results.json"  # the grade as reported: compile failures and borrowing applied
        for t in json.loads(results.read_text()).get("tests", []) if results.is_file() else []:
            output = t.get("output", "")
            if t["status"] == "passed" or "SHADOWLAB_STUB marker is still in place" in output:
                continue
            f = failing[t["name"]]
            f["students"].add(dir.name)
            f["hidden"] = t.get("visibility") != "visible"
            f["message"] = f["message"] or "\n".join(output.splitlines()[:4])
        calls = grade / "logs" / "reference_calls.txt"
        if calls.is_file():
            for line in calls.read_text().splitlines():
                if "\t" in line:
                    row["problems"].append(f"{line.split(chr(9))[0]} borrowed the reference answer")
            row["problems"].sort()
        rows.append(row)
    return rows, failing


def main(out: Path) -> int:
    rows, failing = student_rows(out)
    exercises = sorted({e for r in rows for e in r["exercises"]})
    with open(out / "class.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["student", "score", "max_score"] + exercises + ["problems"])
        for r in rows:
            w.writerow([r["student"], r["score"], r["max"]] + [r["exercises"].get(e, "") for e in exercises] +
                       ["; ".join(r["problems"])])
    e = html.escape
    head = "".join(f"<th>{e(x)}</th>" for x in ["student", "score"] + exercises + ["problems"])
    body = ""
    for r in rows:
        cells = [e(r["student"]), f"{r['score']}&nbsp;/&nbsp;{r['max']}" if r["score"] != "" else "&mdash;"]
        cells += [e(str(r["exercises"].get(x, ""))) for x in exercises] + [e("; ".join(r["problems"]))]
        body += "<tr>" + "".join(f"<td>{c}</td>" for c in cells) + "</tr>\n"
    worst = sorted(failing.items(), key=lambda kv: (-len(kv[1]["students"]), kv[0]))[:15]
    fails = "".join(
        f"<tr><td>{len(v['students'])} of {len(rows)}</td><td>{e(name)}{' (hidden)' if v['hidden'] else ''}</td>"
        f"<td><pre>{e(v['message'])}</pre></td></tr>\n" for name, v in worst)
    broken = "".join(f"<li>{e(r['student'])}: {e('; '.join(r['problems']))}</li>\n" for r in rows if r["problems"])
    page = f"""<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>shadowlab: class grades</title>
<style>body{{font:15px system-ui,sans-serif;margin:2em}} table{{border-collapse:collapse}}
td,th{{border:1px solid #bbb;padding:4px 8px;text-align:left;vertical-align:top}} pre{{margin:0;white-space:pre-wrap}}</style>
</head><body>
<h1>Class grades: {len(rows)} submissions</h1>
<table><tr>{head}</tr>
{body}</table>
<h2>The cases most students fail</h2>
<table><tr><th>students</th><th>case</th><th>one student's message</th></tr>
{fails or '<tr><td colspan="3">none</td></tr>'}</table>
<h2>Did not compile, not graded, or borrowed the reference answer</h2>
<ul>
{broken or '<li>none</li>'}</ul>
<p>Each student's report: STUDENT/grade/ (score.json, results.json, logs/); where each file went: STUDENT/placement.txt.</p>
</body></html>
"""
    (out / "class.html").write_text(page)
    print(f"grade-class: {len(rows)} submissions; {out / 'class.csv'}, {out / 'class.html'}")
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    sys.exit(main(Path(sys.argv[1])))
