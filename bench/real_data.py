#!/usr/bin/env python3
"""Every technique on the real-data corpus (scripts/corpus.sh) against the path tracer: wall time and peak
memory of the whole run (reading, surface, checks, technique), the technique's own time, and the error
against a long path-traced image of the same scene. Writes the table (Markdown and CSV) and, per case, one
side-by-side picture (the truth, then each technique in the table's order) into OUTDIR; docs/real-data.md
shows them.

    python3 bench/real_data.py build/lucent [--out docs/real-data] [--size 160] [--quick]
--quick: 64x64 images and short truths (a minute), to try the script; the docs use the default.
Progress: one line per run on stdout, flushed, so a log shows where it is.
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile
import time

CORPUS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".corpus")
# Skin1 as a transfer function of one point: a scan whose medium is homogeneous (every technique takes it).
SKIN1 = "points:0/0.032,0.17,0.48/0.74,0.88,1.01"


def corpus(name):
    return os.path.normpath(os.path.join(CORPUS, name))


def cases():
    """(case, scene arguments, truth knobs, [(label, technique arguments)])."""
    brain = ["--volume", corpus("scans/ch2bet.nii.gz"), "--iso", "40"]
    head = ["--volume", corpus("scans/ch2.nii.gz"), "--iso", "60", "--view", "1,0.2,0.3"]
    probe = ["--mesh", corpus("meshes/nefertiti.off"), "--repair", "--size-mm", "30"]
    return [
        ("MRI brain (ch2bet, 181x217x181), iso 40, scan as density", brain, "spp=256",
         [("taulut", ["--method", "taulut"]), ("voxel-single", ["--method", "voxel-single"]),
          ("pathtrace 16 spp", ["--method", "pathtrace", "--knob", "spp=16"]),
          ("no --method (planner)", [])]),
        ("MRI brain, iso 40, uniform skin1 transfer", brain + ["--transfer", SKIN1], "spp=256",
         [("reference", ["--method", "reference"]), ("tsis", ["--method", "tsis"]),
          ("hybrid", ["--method", "hybrid"]), ("taulut", ["--method", "taulut"]),
          ("pathtrace 16 spp", ["--method", "pathtrace", "--knob", "spp=16"])]),
        ("MRI head (ch2, 181x217x181), iso 60, scan as density", head, "spp=128",
         [("taulut", ["--method", "taulut"]), ("voxel-single", ["--method", "voxel-single"]),
          ("pathtrace 16 spp", ["--method", "pathtrace", "--knob", "spp=16"])]),
        ("nefertiti (34 boundary edges, --repair) under Blender's city probe",
         probe + ["--light", "env:" + corpus("probes/city.exr")], "spp=1024",
         [("prt", ["--method", "prt"]), ("reference", ["--method", "reference"]),
          ("tsis", ["--method", "tsis", "--knob", "env-strata=8"]),
          ("pathtrace 64 spp", ["--method", "pathtrace", "--knob", "spp=64"])]),
        ("nefertiti under Blender's sunrise probe (a sun of 33664)",
         probe + ["--light", "env:" + corpus("probes/sunrise.exr")], "spp=1024",
         [("prt", ["--method", "prt"]), ("reference", ["--method", "reference"]),
          ("tsis", ["--method", "tsis", "--knob", "env-strata=8"]),
          ("pathtrace 64 spp", ["--method", "pathtrace", "--knob", "spp=64"])]),
        ("Wuson (412 boundary edges: --repair remeshes by winding number)",
         ["--mesh", corpus("meshes/Wuson.stl"), "--repair", "--size-mm", "40"], "spp=256",
         [("reference", ["--method", "reference"]), ("tsis", ["--method", "tsis"]),
          ("hybrid", ["--method", "hybrid"])]),
        ("elephant-with-holes (1353 boundary edges: --repair remeshes)",
         ["--mesh", corpus("meshes/elephant-with-holes.off"), "--repair", "--size-mm", "40",
          "--view", "1,0.3,0.2"], "spp=256",
         [("reference", ["--method", "reference"]), ("tsis", ["--method", "tsis"]),
          ("hybrid", ["--method", "hybrid"])]),
    ]


def run(lucent, scene, method, exr, png, size, log):
    """Renders; returns (wall s, peak MiB, technique s, stderr)."""
    stats = exr + ".json"
    timing = exr + ".time"
    cmd = ["/usr/bin/time", "-f", "%e %M", "-o", timing, lucent, "render", *scene, *method,
           "--width", str(size), "--height", str(size), "--quiet", "--out", exr, "--stats", stats]
    if png:
        cmd += ["--out", png]
    done = subprocess.run(cmd, capture_output=True, text=True)
    log.write(" ".join(cmd) + "\n" + done.stderr + "\n")
    if done.returncode != 0:
        return None, None, None, done.stderr.strip().splitlines()[-1] if done.stderr else "failed"
    wall, kib = open(timing).read().split()[-2:]
    return float(wall), float(kib) / 1024, json.load(open(stats))["wall_seconds"], done.stderr


def compare(lucent, test, truth):
    out = subprocess.run([lucent, "compare", test, truth, "--json"], capture_output=True, text=True)
    if out.returncode != 0:
        return None
    return json.loads(out.stdout)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("lucent")
    parser.add_argument("--out", default="docs/real-data")
    parser.add_argument("--size", type=int, default=160)
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args()
    if not os.path.isdir(CORPUS):
        sys.exit("real_data.py: no corpus at %s: run scripts/corpus.sh" % CORPUS)
    size = 64 if args.quick else args.size
    os.makedirs(args.out, exist_ok=True)
    rows = []
    with tempfile.TemporaryDirectory() as tmp, open(os.path.join(args.out, "runs.log"), "w") as log:
        for index, (case, scene, truth_knobs, methods) in enumerate(cases()):
            truth = os.path.join(tmp, "truth%d.exr" % index)
            knobs = "spp=16" if args.quick else truth_knobs
            truth_png = os.path.join(args.out, "case%d-truth.png" % index)
            wall, mib, tech, err = run(args.lucent, scene, ["--method", "pathtrace", "--knob", knobs], truth,
                                       truth_png, size, log)
            print("%s: path tracer %s: %s" % (case, knobs, "%.1f s" % wall if wall else err), flush=True)
            rows.append([case, "pathtrace %s (truth)" % knobs, wall, mib, tech, 0.0, "", truth_png])
            for label, method in methods:
                exr = os.path.join(tmp, "case%d-%d.exr" % (index, len(rows)))
                png = os.path.join(args.out, "case%d-%s.png" % (index, label.split()[0].replace("(", "")))
                wall, mib, tech, err = run(args.lucent, scene, method, exr, png, size, log)
                if wall is None:
                    print("  %s: FAILED: %s" % (label, err), flush=True)
                    rows.append([case, label, None, None, None, None, err, ""])
                    continue
                c = compare(args.lucent, exr, truth)
                rel = c["relative_rms"] if c else None
                ratio = "%.2f/%.2f/%.2f" % (c["mean_ratio_r"], c["mean_ratio_g"], c["mean_ratio_b"]) if c else ""
                chosen = [l for l in err.splitlines() if "auto:" in l]
                if chosen:
                    label += " -> " + chosen[0].split("auto: ")[1].split(":")[0]
                print("  %s: %.2f s wall (%.2f s technique), %.0f MiB, relative RMS %s, mean ratio %s"
                      % (label, wall, tech, mib, "%.3f" % rel if rel is not None else "-", ratio), flush=True)
                rows.append([case, label, wall, mib, tech, rel, ratio, png])
    with open(os.path.join(args.out, "table.csv"), "w", newline="") as f:
        csv.writer(f).writerows([["case", "technique", "wall_s", "peak_mib", "technique_s", "relative_rms",
                                  "mean_ratio_rgb", "picture"]] + rows)
    with open(os.path.join(args.out, "table.md"), "w") as f:
        f.write("| case | technique | wall s | peak MiB | technique s | relative RMS vs truth | mean ratio R/G/B |\n")
        f.write("|---|---|---|---|---|---|---|\n")
        fmt = lambda v, p: ("%." + str(p) + "f") % v if isinstance(v, float) else "-"
        for case, label, wall, mib, tech, rel, ratio, _ in rows:
            f.write("| %s | %s | %s | %s | %s | %s | %s |\n" % (case, label, fmt(wall, 2), fmt(mib, 0),
                                                                  fmt(tech, 2), fmt(rel, 3), ratio or "-"))
    # One side-by-side picture per case: the truth first, then each technique in the table's order.
    montage = os.path.join(os.path.dirname(os.path.abspath(__file__)), "montage.py")
    for index in range(len(cases())):
        pictures = [r[7] for r in rows if r[7] and os.path.basename(r[7]).startswith("case%d-" % index)]
        subprocess.run(["/usr/bin/python3", montage, os.path.join(args.out, "case%d.png" % index), *pictures],
                       check=True)
        for picture in pictures:
            os.remove(picture)
    print("real_data.py: %d runs; %s/table.md, table.csv, case*.png, runs.log" % (len(rows), args.out), flush=True)


if __name__ == "__main__":
    main()
