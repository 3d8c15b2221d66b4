#!/usr/bin/env python3
"""Lesson 10's "which technique when", generated from the measured figures (tools/showdown_bench.sh).

Reads OUT/<path>/report.json (shadowlab_bench's rows: one per configuration and path sample) and
writes OUT/summary.md and OUT/index.html: per path and texel budget the mean figures of every
technique, the Pareto front of shadow-pass time against misclassified pixels, the technique with
the least error and its margin over the next, the fastest; the error against the light direction
per technique (the sweep); the soft methods against the sphere-light reference (OUT/soft: RMSE
against the reference's noise floor, the Pareto front of frame time against RMSE); the comparison
of Lloyd et al. (EGSR 2006); and one page over every path: per budget and path the least
misclassified technique, its margin and the front, and how often each technique is either. No verdict is written by
hand: every sentence is a comparison of two figures from the reports. Usage:
    showdown_summary.py OUT_DIR SIZE REPEATS
"""
import html
import json
import os
import statistics
import sys


def load(path, kind="hard"):
    rows = json.load(open(path))["rows"]
    by = {}
    for r in rows:
        if kind not in r:  # a run the ground truth could not judge that way (no hard / soft figures)
            continue
        by.setdefault(r["technique"], []).append(r)
    for v in by.values():
        v.sort(key=lambda r: r["frame"])
    return by


def shadow_ms(r):
    """Every pass but the lit scene: the maps' depth passes (and the hybrid maps' merge and index), or
    the stencil volumes' whole frame (their shadows are drawn with the lit passes)."""
    return sum(v for k, v in r["gpuMs"].items() if k != "scene" and v is not None)


def mean(xs):
    xs = [x for x in xs if x is not None]
    return sum(xs) / len(xs) if xs else float("nan")


def figures(rows):
    a = [r.get("aliasing") or {} for r in rows]
    return {
        "mis": mean([r["hard"]["misclassifiedPct"] for r in rows]),
        "leak": mean([r["hard"]["leakPct"] for r in rows]),
        "false": mean([r["hard"]["falseShadowPct"] for r in rows]),
        "m": mean([x.get("mean") for x in a]),
        "p95": mean([x.get("p95") for x in a]),
        "max": max([x.get("max") or 0.0 for x in a]),
        "shadow": statistics.median([shadow_ms(r) for r in rows]),
        "frame": statistics.median([r["gpuTotalMs"] or 0.0 for r in rows]),
        "texels": rows[0]["shadowTexels"],
        "tris": rows[0]["shadowTriangles"],
        # skipped work (None where the technique does not report it: the volumes, the hybrid maps)
        "culled": mean([r.get("culledCasters") for r in rows]),
        "reused": mean([r.get("mapsReused") for r in rows]),
        # shimmer along the short spans (shadowlab_bench --shimmer; the same on every row of a configuration)
        "shimmer": shimmer(rows),
        "shimmer_max": shimmer(rows, "maxExtraFlipPct"),
        "shimmer_ref": shimmer(rows, "referenceFlipPct"),
    }


SPANS = ("camera", "sun")  # showdown_bench.sh's --shimmer names: a drifting camera, a turning sun


def shimmer(rows, key="extraFlipPct"):
    """Per span the mean share of pixels a frame whose shadow flips where the ground truth's does not
    (soft: key="extraChange", the visibility's change beyond the reference's); NaN where not measured."""
    spans = rows[0].get("shimmer") or {}
    return {n: (spans[n][key] if n in spans else float("nan")) for n in SPANS}


def pct(x, fmt="{:.3f}"):
    return "-" if x != x else fmt.format(x)


def soft_figures(rows):
    """A soft method's figures over the path: RMSE and max |error| of visibility against the sphere-light
    reference, the umbra over- and under-estimated (% of pixels), its times."""
    floors = [r["soft"]["referenceNoiseRmse"] for r in rows if r["soft"].get("referenceNoiseRmse") is not None]
    return {
        "rmse": mean([r["soft"]["rmse"] for r in rows]),
        "max": max([r["soft"]["maxAbs"] or 0.0 for r in rows]),
        "over": mean([r["soft"]["umbraOverPct"] for r in rows]),
        "under": mean([r["soft"]["umbraUnderPct"] for r in rows]),
        "floor": mean(floors) if floors else None,
        "shadow": statistics.median([shadow_ms(r) for r in rows]),
        "frame": statistics.median([r["gpuTotalMs"] or 0.0 for r in rows]),
        "texels": rows[0]["shadowTexels"],
        "change": shimmer(rows, "extraChange")["camera"],
    }


def soft_section(table):
    """The soft methods' table and generated lines: the least RMSE and its margin, each method against
    the reference's noise floor, the Pareto front of frame time against RMSE."""
    floors = [f["floor"] for f in table.values() if f["floor"]]
    floor = floors[0] if floors else None
    md = ["\n## Soft shadows: RMSE against the sphere-light reference\n",
          "(lesson 05's sphere light over the showcase; RMSE of visibility in [0, 1]; umbra over / under: % of "
          "pixels the method puts in full shadow that the reference lights partly, and the reverse; shimmer: the "
          "mean change of visibility a frame beyond the reference's while the camera drifts" +
          (f"; the reference's noise floor, the RMSE between two references with different seeds: {floor:.4f}"
           if floor else "") + ")\n",
          "| technique | RMSE | x noise floor | max abs | umbra over % | umbra under % | shimmer | shadow ms | frame ms "
          "| texels |",
          "|---|---|---|---|---|---|---|---|---|---|"]
    for t, f in sorted(table.items(), key=lambda x: x[1]["rmse"]):
        ratio = f"{f['rmse'] / floor:.2f}" if floor else "-"
        md.append(f"| {t} | {f['rmse']:.4f} | {ratio} | {f['max']:.3f} | {f['over']:.2f} | {f['under']:.2f} | "
                  f"{pct(f['change'], '{:.5f}')} | {f['shadow']:.1f} | {f['frame']:.1f} | {f['texels']} |")
    ranked = sorted(table.items(), key=lambda x: x[1]["rmse"])
    best = ranked[0]
    margin = (f"{ranked[1][1]['rmse'] - best[1]['rmse']:.4f} less than {ranked[1][0]} ({ranked[1][1]['rmse']:.4f})"
              if len(ranked) > 1 else "alone")
    front = pareto([(t, {"frame": f["frame"], "mis": f["rmse"]}) for t, f in table.items()])
    fastest = min(table.items(), key=lambda x: x[1]["frame"])
    md.append(f"\n- **soft, showcase**: least RMSE **{best[0]}** ({best[1]['rmse']:.4f}), {margin}; fastest frame "
              f"{fastest[0]} ({fastest[1]['frame']:.1f} ms); Pareto front (frame time against RMSE): {', '.join(front)}.")
    return md


def skipped(x):
    """A mean count of skipped work, or '-' where the technique does not report it."""
    return "-" if x != x else f"{x:.0f}"


def budget(label):
    parts = label.split()
    return parts[1] if len(parts) > 1 else "-"


def contender(label):
    """Every row but "none" (no shadows at all): the floor the others are read against, listed in the
    tables but never the least misclassified, the fastest or on the front."""
    return label.split()[0] != "none"


def pareto(items):
    """Labels not dominated in (frame ms, misclassified %): nothing else is as fast and as right."""
    front = []
    for a, fa in items:
        if not any(fb["frame"] <= fa["frame"] and fb["mis"] <= fa["mis"] and
                   (fb["frame"] < fa["frame"] or fb["mis"] < fa["mis"]) for b, fb in items if b != a):
            front.append(a)
    return sorted(front, key=lambda a: dict(items)[a]["frame"])


def best_of(items):
    """The least misclassified of (label, figures) items, with the next one: (best, second or None)."""
    by_err = sorted(items, key=lambda x: x[1]["mis"])
    return by_err[0], (by_err[1] if len(by_err) > 1 else None)


def verdicts(name, table):
    """The generated lines of one path: per budget the least error, its margin, the fastest, the front."""
    lines = []
    budgets = sorted({budget(t) for t in table if budget(t) != "-"}, key=int)
    for b in budgets:
        items = [(t, f) for t, f in table.items() if budget(t) in (b, "-") and contender(t)]
        best, second = best_of(items)
        margin = (f"{second[1]['mis'] - best[1]['mis']:.3f} points less than {second[0]} "
                  f"({second[1]['mis']:.3f} %)") if second else "alone"
        fastest = min(items, key=lambda x: x[1]["frame"])
        by_m = min((x for x in items if x[1]["m"] == x[1]["m"]), key=lambda x: x[1]["m"], default=None)
        steady = []
        for span, words in (("camera", "the drifting camera"), ("sun", "the turning sun")):
            measured = [x for x in items if x[1]["shimmer"][span] == x[1]["shimmer"][span]]
            if measured:
                b_ = min(measured, key=lambda x: x[1]["shimmer"][span])
                steady.append(f"under {words} {b_[0]} ({b_[1]['shimmer'][span]:.3f} %)")
        steadiest = f"; steadiest {', '.join(steady)}" if steady else ""
        lines.append(f"- **{name}, {b}^2 texels per light**: least misclassified **{best[0]}** "
                     f"({best[1]['mis']:.3f} %), {margin}; lowest mean aliasing m "
                     f"{by_m[0] + ' (' + format(by_m[1]['m'], '.3g') + ')' if by_m else 'n/a'}; fastest frame "
                     f"{fastest[0]} ({fastest[1]['frame']:.1f} ms); Pareto front (frame time against error): "
                     f"{', '.join(pareto(items))}{steadiest}.")
    return lines


def one_page(tables):
    """Every path at once: per texel budget and path the least misclassified technique with its margin
    over the next and the Pareto front (frame time against error); then, per technique, in how many
    (path, budget) cells it is the least misclassified and on the front. Counted, not judged."""
    budgets = sorted({budget(t) for table in tables.values() for t in table if budget(t) != "-"}, key=int)
    paths = list(tables)
    md = ["\n## One page: the best technique per scene and budget\n",
          "(each cell: the least misclassified technique at that budget per light, its misclassified %, the margin "
          "over the next in points, and the Pareto front of frame time against error; techniques without a map, "
          "the stencil volumes, are in every budget)\n",
          "| budget | " + " | ".join(paths) + " |", "|---" * (len(paths) + 1) + "|"]
    best_count, front_count, cells = {}, {}, 0
    for b in budgets:
        row = []
        for p in paths:
            items = [(t, f) for t, f in tables[p].items() if budget(t) in (b, "-") and contender(t)]
            if not any(budget(t) == b for t, _ in items):
                row.append("-")
                continue
            cells += 1
            best, second = best_of(items)
            margin = f", {second[1]['mis'] - best[1]['mis']:.3f} pts over {second[0]}" if second else ""
            front = pareto(items)
            for t in front:
                front_count[t.split()[0]] = front_count.get(t.split()[0], 0) + 1
            best_count[best[0].split()[0]] = best_count.get(best[0].split()[0], 0) + 1
            row.append(f"**{best[0]}** {best[1]['mis']:.3f} %{margin}; front: {', '.join(front)}")
        md.append(f"| {b}^2 | " + " | ".join(row) + " |")
    names = sorted(set(best_count) | set(front_count), key=lambda t: (-best_count.get(t, 0), -front_count.get(t, 0), t))
    md.append(f"\nOver the {cells} (path, budget) cells: " +
              "; ".join(f"**{t}** least misclassified in {best_count.get(t, 0)}, on the front in {front_count.get(t, 0)}"
                        for t in names) + ".")
    return md


def svg_sweep(sweep):
    """Misclassified % against the sweep's direction index, one polyline per technique."""
    w, h, pad = 640, 260, 40
    series = {t: [r["hard"]["misclassifiedPct"] for r in rs] for t, rs in sweep.items()}
    n = max(len(v) for v in series.values())
    top = max(max(v) for v in series.values()) or 1.0
    colours = ["#e41a1c", "#377eb8", "#4daf4a", "#984ea3", "#ff7f00", "#a65628", "#f781bf", "#999999"]
    out = [f'<svg width="{w}" height="{h}" xmlns="http://www.w3.org/2000/svg" style="background:#fff">',
           f'<text x="{pad}" y="14" font-size="12">misclassified % against sun direction (0..{n - 1}, '
           f'bench/paths/psm_light_sweep.path)</text>']
    for i, (t, v) in enumerate(sorted(series.items())):
        pts = " ".join(f"{pad + (w - 2 * pad) * k / max(n - 1, 1):.1f},{h - pad - (h - 2 * pad) * y / top:.1f}"
                       for k, y in enumerate(v))
        c = colours[i % len(colours)]
        out.append(f'<polyline fill="none" stroke="{c}" stroke-width="2" points="{pts}"/>')
        out.append(f'<text x="{w - pad - 120}" y="{30 + 14 * i}" font-size="11" fill="{c}">{html.escape(t)}</text>')
    out.append(f'<text x="4" y="{pad}" font-size="10">{top:.2f} %</text>'
               f'<text x="4" y="{h - pad}" font-size="10">0 %</text></svg>')
    return "\n".join(out)


def main():
    if len(sys.argv) == 2 and sys.argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return
    usage = "usage: showdown_summary.py OUT_DIR SIZE REPEATS (tools/showdown_bench.sh runs it)"
    if len(sys.argv) != 4 or any(a.startswith("-") for a in sys.argv[1:]):
        print(f"showdown_summary.py: expected OUT_DIR SIZE REPEATS, got {sys.argv[1:]}; {usage}", file=sys.stderr)
        sys.exit(2)
    out, size, repeats = sys.argv[1:4]
    if not os.path.isdir(out):
        print(f"showdown_summary.py: no directory {out}; {usage}", file=sys.stderr)
        sys.exit(2)
    paths = [p for p in ("city", "terrain", "forest", "city_1m", "sweep") if os.path.exists(f"{out}/{p}/report.json")]
    data = {p: load(f"{out}/{p}/report.json") for p in paths}
    tables = {p: {t: figures(rs) for t, rs in by.items()} for p, by in data.items()}
    md = [f"# Lesson 10: which technique when (measured, {size}, llvmpipe on a shared 2-core machine; "
          f"shadow ms: every pass but the lit scene (the volumes: their whole frame), frame ms: the GPU total, "
          f"both the median over the path's samples, {repeats} repeat(s): noisy, for ratios only; "
          "the error figures are deterministic)\n",
          "Generated by tools/showdown_summary.py from the reports beside it; nothing here is written by hand.\n",
          "(shimmer: the share of pixels a frame whose shadow flips where the ground truth's does not, the mean "
          "over 8 consecutive frames of bench/paths/city_drift.path (the camera sliding 3 cm a frame) and of "
          "bench/paths/sun_turn.path (the sun turning 0.1 degree a frame); the flips are counted per world point "
          "followed under the moving camera.)\n",
          "| path | technique | texels | misclassified % | leaks % | false % | m mean | m p95 | m max | "
          "shimmer camera % | shimmer sun % | shadow ms | frame ms | shadow tris | culled casters | maps reused |",
          "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for p, table in tables.items():
        for t, f in table.items():
            md.append(f"| {p} | {t} | {f['texels']} | {f['mis']:.3f} | {f['leak']:.3f} | {f['false']:.3f} | "
                      f"{f['m']:.3g} | {f['p95']:.3g} | {f['max']:.3g} | {pct(f['shimmer']['camera'])} | "
                      f"{pct(f['shimmer']['sun'])} | {f['shadow']:.1f} | {f['frame']:.1f} | "
                      f"{f['tris']} | {skipped(f['culled'])} | {skipped(f['reused'])} |")
    md.extend(one_page(tables))
    md.append("\n## Which technique when\n")
    for p, table in tables.items():
        md.extend(verdicts(p, table))
    if os.path.exists(f"{out}/soft/report.json"):
        md.extend(soft_section({t: soft_figures(rs) for t, rs in load(f"{out}/soft/report.json", "soft").items()}))
    md.append("\n## Lloyd et al. (EGSR 2006): warping plus 4 z-partitions at 2048^2 total against one LiSPSM "
              "map at 4096^2\n")
    md.append("(csm+warp: a LiSPSM warp inside each cascade, csm.warp; csm: plain z-partitioning, for contrast. "
              "m is measured through each pixel's own cascade; m max is the largest over the path's frames, "
              "capped at 1024 where a grazing receiver's Jacobian is near singular.)\n")
    for p, table in tables.items():
        l4 = table.get("lispsm 4096")
        for name in ("csm+warp 2048", "csm 2048"):
            c = table.get(name)
            if c and l4:
                md.append(f"- {p}: {name}: max m {c['max']:.3g} against LiSPSM 4096 {l4['max']:.3g} "
                          f"({'lower' if c['max'] < l4['max'] else 'not lower'}), p95 {c['p95']:.3g} against "
                          f"{l4['p95']:.3g} ({'lower' if c['p95'] < l4['p95'] else 'not lower'}), misclassified "
                          f"{c['mis']:.3f} % against {l4['mis']:.3f} %; shadow time ratio "
                          f"{c['shadow'] / l4['shadow'] if l4['shadow'] else float('nan'):.2f}.")
    md.extend(sdsm_section(tables))
    md.extend(stability_section(tables))
    open(f"{out}/summary.md", "w").write("\n".join(md) + "\n")
    page = ["<!doctype html><meta charset='utf-8'><title>Lesson 10: the showdown</title>",
            "<body style='font-family:sans-serif;max-width:1100px;margin:auto'>",
            "<h1>Lesson 10: the showdown, time against error</h1>",
            "<p>Per path, shadowlab_bench's report: the time-against-error scatter with its Pareto front, "
            "tables and thumbnails.</p><ul>"]
    page += [f"<li><a href='{p}/report.html'>{p}</a></li>" for p in paths + ["soft"]
             if os.path.exists(f"{out}/{p}/report.html")]
    page.append("</ul>")
    if "sweep" in data:
        page.append("<h2>Error against the light direction</h2>" + svg_sweep(data["sweep"]))
    page.append("<h2>Summary</h2><pre style='white-space:pre-wrap'>" + html.escape("\n".join(md)) + "</pre>")
    open(f"{out}/index.html", "w").write("\n".join(page) + "\n")
    print("\n".join(md))


def sdsm_section(tables):
    """Sample distribution shadow maps (Lauritzen et al., I3D 2011) against the practical cascades,
    with and without the warp inside each, at the same total texels: one row per path and figure."""
    names = ("csm 2048", "csm+warp 2048", "sdsm 2048", "sdsm+warp 2048")
    rows = [(p, t) for p, t in tables.items() if all(n in t for n in names)]
    if not rows:
        return []
    md = ["\n## Sample distribution shadow maps (Lauritzen et al., I3D 2011) against the practical cascades\n",
          "(sdsm: the cascades split over the depths on screen and fitted to them; +warp: a LiSPSM warp "
          "inside each cascade, for both; 2048^2 total texels, four cascades.)\n",
          "| path | figure | " + " | ".join(n.replace(" 2048", "") for n in names) + " |",
          "|---|---|" + "---|" * len(names)]
    for p, t in rows:
        for label, key, fmt in (("misclassified %", "mis", "{:.3f}"), ("mean m", "m", "{:.3g}"),
                                ("p95 of m", "p95", "{:.3g}"), ("shadow ms", "shadow", "{:.1f}")):
            values = [t[n][key] for n in names]
            best = min(values)
            cells = [("**" + fmt.format(v) + "**") if v == best and key != "shadow" else fmt.format(v) for v in values]
            md.append(f"| {p} | {label} | " + " | ".join(cells) + " |")
    return md


def stability_section(tables):
    """Shimmer at 2048^2: every map technique with its texel snapping on and off, the cascades with
    and without SDSM, the warps (PSM, LiSPSM), per path, ordered by the drifting camera's figure."""
    rows = [(p, t, f) for p, table in tables.items() for t, f in table.items()
            if budget(t) in ("2048", "-") and contender(t) and f["shimmer"]["camera"] == f["shimmer"]["camera"]]
    if not rows:
        return []
    md = ["\n## Stability: shimmer a frame at 2048^2 texels per light\n",
          "(extra flips: % of the pixels facing the light whose shadow flips between consecutive frames where the "
          "ground truth's does not; the reference's own flips are the shadow truly moving. \"/nosnap\": the same "
          "technique with its texel snapping off.)\n",
          "| path | technique | camera drift % | worst frame % | sun turn % | worst frame % | reference camera % "
          "| reference sun % |", "|---|---|---|---|---|---|---|---|"]
    for p, t, f in sorted(rows, key=lambda x: (list(tables).index(x[0]), x[2]["shimmer"]["camera"])):
        worst = f["shimmer_max"]
        ref = f["shimmer_ref"]
        md.append(f"| {p} | {t} | {pct(f['shimmer']['camera'])} | {pct(worst['camera'])} | "
                  f"{pct(f['shimmer']['sun'])} | {pct(worst['sun'])} | {pct(ref['camera'])} | {pct(ref['sun'])} |")
    for p in tables:
        for a, b in (("csm 2048", "csm/nosnap 2048"), ("uniform 2048", "uniform/nosnap 2048"),
                     ("sdsm 2048", "sdsm/nosnap 2048"),
                     ("sdsm 2048", "csm 2048"), ("lispsm 2048", "uniform 2048"), ("psm 2048", "uniform 2048")):
            fa, fb = tables[p].get(a), tables[p].get(b)
            if not fa or not fb:
                continue
            parts = []
            for span, words in (("camera", "drifting camera"), ("sun", "turning sun")):
                x, y = fa["shimmer"][span], fb["shimmer"][span]
                if x == x and y == y:
                    parts.append(f"{words} {x:.3f} % against {y:.3f} %" + (f" ({x / y:.2f}x)" if y > 0 else ""))
            if parts:
                md.append(f"- {p}: {a} against {b}: " + "; ".join(parts) + ".")
    return md


if __name__ == "__main__":
    main()
