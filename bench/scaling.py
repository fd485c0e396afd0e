#!/usr/bin/python3
"""How each technique's cost grows with the work (issue 19, item 3).

For every technique in the registry (`lucent techniques --json`) that renders a mesh under the
default lights (a uniform sky for those that take only environments), this times `lucent render` and fits power laws, time ~ a x^b, by least squares in
log-log:
  - prepare and frame time against the triangle count (one sphere remeshed, 10 k to 1 M triangles);
  - the per-point stage (the statistics' evaluation_seconds, else the whole frame) against the shaded
    pixel count, and against the technique's accuracy knob (the first knob of its own default sweep):
    a frame's fixed stages (an atlas, maps) would hide how the per-point work grows.
Each technique runs at the cheapest setting of its own default sweep (so no knob is named here), and
the registry's own scaling claims are printed beside the fitted exponents.

usage: /usr/bin/python3 bench/scaling.py build/lucent [--out DIR] [--quick] [--timeout S] [--only A,B]
       /usr/bin/python3 bench/scaling.py build/lucent --replot DIR/scaling.csv --out DIR
(--quick: 10 k to 160 k triangles and fewer pixel counts: 4 minutes on 2 cores; the full run takes
 about 25, most of it QuadGraph's TetGen on the finest meshes)
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import tempfile
import time

import numpy as np


def sphere_mesh(path, triangles):
    """A UV sphere with about `triangles` triangles (2 N (N - 1) for N x N divisions), as PLY."""
    import vtk

    n = max(8, int(round(math.sqrt(triangles / 2.0))))
    source = vtk.vtkSphereSource()
    source.SetRadius(15.0)
    source.SetThetaResolution(n)
    source.SetPhiResolution(n)
    clean = vtk.vtkCleanPolyData()  # the poles' duplicate points would leave the mesh open
    clean.SetInputConnection(source.GetOutputPort())
    clean.Update()
    writer = vtk.vtkPLYWriter()
    writer.SetFileName(path)
    writer.SetInputData(clean.GetOutput())
    writer.Write()
    return clean.GetOutput().GetNumberOfPolys()


def techniques(lucent):
    out = subprocess.run([lucent, "techniques", "--json"], check=True, capture_output=True, text=True)
    usable = []
    for t in json.loads(out.stdout)["techniques"]:
        caps = t["capabilities"]
        # The default lights where the technique takes them, else a uniform sky.
        if caps["point_lights"] and caps["directional_lights"]:
            lights = []
        elif caps["environment_lights"]:
            lights = ["--light", "env:uniform"]
        else:
            continue
        sweep = t["default_sweep"][0] if t["default_sweep"] else None
        usable.append({"name": t["name"], "sweep": sweep, "precompute": caps["precompute_scaling"],
                       "frame": caps["frame_scaling"], "lights": lights})
    return usable


def render(lucent, tech, mesh, width, knob, work, timeout):
    """Runs one render; returns its statistics' figures and wall time, or None with the reason."""
    stats = os.path.join(work, "stats.json")
    if os.path.exists(stats):
        os.remove(stats)  # a run that writes none must not read the previous run's
    cmd = [lucent, "render", "--mesh", mesh, "--method", tech["name"], "--width", str(width),
           "--height", str(width), "--quiet", "--stats", stats, "--out",
           os.path.join(work, "out.exr")] + tech["lights"]
    if knob:
        cmd += ["--knob", "%s=%s" % knob]
    start = time.time()
    try:
        run = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, "timeout after %d s" % timeout
    if run.returncode != 0:
        return None, (run.stderr.strip().splitlines() or ["exit %d" % run.returncode])[-1]
    with open(stats) as f:
        figures = json.load(f)["figures"]
    figures["wall"] = time.time() - start
    return figures, ""


def short(reason):
    """The first clause of a refusal, for the table."""
    return reason.replace("lucent render: ", "").split(":")[0][:80]


def per_point(figures):
    """The stage that does the per-point work, where the technique times it apart."""
    return figures.get("evaluation_seconds", figures["frame_seconds"])


def fit(xs, ys):
    """Exponent b of y ~ a x^b over the positive points, or nan with fewer than 2."""
    pts = [(x, y) for x, y in zip(xs, ys) if x > 0 and y > 0]
    if len(pts) < 2 or len({p[0] for p in pts}) < 2:
        return float("nan")
    lx, ly = np.log([p[0] for p in pts]), np.log([p[1] for p in pts])
    return float(np.polyfit(lx, ly, 1)[0])


def measure(lucent, tech, mesh, width, knob, work, timeout, label):
    """One render, logged; returns (prepare, frame, per-point seconds, shaded pixels) or the reason."""
    fig, why = render(lucent, tech, mesh, width, knob, work, timeout)
    print("%-14s %s: %s" % (tech["name"], label, why or "%.2f s" % fig["wall"]), file=sys.stderr,
          flush=True)
    if not fig:
        return None, why
    return (fig.get("prepare_seconds", 0), fig["frame_seconds"], per_point(fig),
            fig.get("shaded_pixels", width * width)), ""


def time_technique(args, tech, meshes, widths, work, rows):
    """The three series of one technique (rows of the CSV appended), and its table entry."""
    base_width = 96
    sweep = tech["sweep"]
    cheapest = (sweep["knob"], sweep["values"][0]) if sweep else None
    moderate = meshes[1][1]  # pixels and knob on a 30-40 k triangle mesh: every technique can
    series = {"triangles": [], "pixels": [], "knob": []}
    refused = ""

    def record(axis, value, m):
        series[axis].append((value, m[0], m[1] if axis == "triangles" else m[2]))
        rows.append([tech["name"], axis if axis != "knob" else sweep["knob"], value] + list(m[:3]))

    for tris, path in meshes:
        if refused.startswith("timeout"):
            break  # a finer mesh would only time out too
        m, why = measure(args.lucent, tech, path, base_width, cheapest, work, args.timeout,
                         "%8d triangles" % tris)
        refused = refused or why
        if m:
            record("triangles", tris, m)
    for w in widths:
        m, _ = measure(args.lucent, tech, moderate, w, cheapest, work, args.timeout, "%5d px wide" % w)
        if m:
            record("pixels", m[3], m)
    for v in sweep["values"] if sweep else []:
        try:
            value = float(v)
        except ValueError:
            continue
        m, _ = measure(args.lucent, tech, moderate, base_width, (sweep["knob"], v), work, args.timeout,
                       "%s=%s" % (sweep["knob"], v))
        if m:
            record("knob", value, m)
    tri = series["triangles"]
    return {
        "name": tech["name"] + (" (uniform sky)" if tech["lights"] else ""),
        "prep_tri": fit([r[0] for r in tri], [r[1] for r in tri]),
        "frame_tri": fit([r[0] for r in tri], [r[2] for r in tri]),
        "frame_px": fit([r[0] for r in series["pixels"]], [r[2] for r in series["pixels"]]),
        "knob": sweep["knob"] if sweep else "",
        "frame_knob": fit([r[0] for r in series["knob"]], [r[2] for r in series["knob"]]),
        "span": ("%d-%d" % (tri[0][0], tri[-1][0]) if tri else "none") +
                (" (%s)" % short(refused) if refused else ""),
        "claim": "prepare %s; frame %s" % (tech["precompute"], tech["frame"]),
        "series": series,
    }


def write_results(table, rows, out):
    with open(os.path.join(out, "scaling.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["technique", "axis", "value", "prepare_seconds", "frame_seconds", "per_point_seconds"])
        w.writerows(rows)
    lines = ["| technique | triangles timed | prepare ~ tris^b | frame ~ tris^b | "
             "per-point stage ~ pixels^b | per-point stage ~ knob^b (knob) | the registry's claim |",
             "|---|---|---|---|---|---|---|"]
    for r in table:
        lines.append("| %s | %s | %.2f | %.2f | %.2f | %.2f (%s) | %s |" % (
            r["name"], r["span"], r["prep_tri"], r["frame_tri"], r["frame_px"], r["frame_knob"],
            r["knob"], r["claim"]))
    text = "\n".join(lines)
    print(text)
    with open(os.path.join(out, "scaling.md"), "w") as f:
        f.write(text + "\n")
    plot({r["name"]: r["series"]["triangles"] for r in table}, os.path.join(out, "scaling.png"))
    print("CSV, table and plot in %s" % out)


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("lucent")
    ap.add_argument("--out", default="scaling_out")
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--timeout", type=int, default=150, help="seconds per render (default 150)")
    ap.add_argument("--only", default="", help="comma-separated technique names (default: all)")
    ap.add_argument("--replot", metavar="CSV", help="only redraw OUT/scaling.png from a run's CSV")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    if args.replot:
        replot(args.replot, os.path.join(args.out, "scaling.png"))
        return
    counts = [10_000, 40_000, 160_000] if args.quick else [10_000, 30_000, 100_000, 300_000,
                                                             1_000_000]
    widths = [96, 192, 384] if args.quick else [96, 192, 384, 768]
    techs = techniques(args.lucent)
    if args.only:
        techs = [t for t in techs if t["name"] in set(args.only.split(","))]
    rows, table = [], []
    with tempfile.TemporaryDirectory() as work:
        meshes = []
        for n in counts:
            path = os.path.join(work, "sphere_%d.ply" % n)
            meshes.append((sphere_mesh(path, n), path))
        for t in techs:
            table.append(time_technique(args, t, meshes, widths, work, rows))
    write_results(table, rows, args.out)


def plot(series, path):
    """Frame and prepare time against triangles, log-log; series: name -> [(tris, prep, frame)]."""
    try:
        import matplotlib
    except ImportError:  # not among lucent's dependencies: the table and CSV stand alone
        print("no plot: matplotlib is missing (apt-get install python3-matplotlib)", file=sys.stderr)
        return

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(13, 5))
    for name, tri in series.items():
        if not tri:
            continue
        frame = [(p[0], p[2]) for p in tri if p[2] > 0]
        line, = axes[0].loglog(*zip(*frame), "o-", label="%s (b=%.2f)" % (name, fit(*zip(*frame))))
        prep = [(p[0], p[1]) for p in tri if p[1] > 0]  # a technique without a prepare has no line
        if len(prep) > 1:
            axes[1].loglog(*zip(*prep), "o-", color=line.get_color(),
                           label="%s (b=%.2f)" % (name, fit(*zip(*prep))))
    for ax, what in zip(axes, ["frame", "prepare"]):
        ax.set_xlabel("triangles (one sphere remeshed)")
        ax.set_ylabel("%s time (s)" % what)
        ax.set_title("%s time against triangle count (b: fitted exponent)" % what)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.0, 0.5))
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def replot(csv_path, png_path):
    """The plot again from a run's CSV (its triangle rows), without rendering."""
    series = {}
    with open(csv_path) as f:
        for row in csv.DictReader(f):
            if row["axis"] == "triangles":
                series.setdefault(row["technique"], []).append(
                    (float(row["value"]), float(row["prepare_seconds"]), float(row["frame_seconds"])))
    plot(series, png_path)


if __name__ == "__main__":
    main()
