#!/usr/bin/env python3
"""Measures what the planner reads (include/lucent/plan/calibration.hpp) and writes it to data/planner/.

settings.csv: for each scene of the suite below, `lucent report --truth model` runs every technique that
fits the scene over its own sweep and measures each setting (time, error against its model's truth);
each row is labelled with the scene's features (`lucent plan --features`). The technique list, the
sweeps and the truths come from the registry: this script names no technique.

model-floors.csv: the dipole model's own error against the path tracer and the share of single
scattering, from bench/dipole_vs_pathtrace.py's CSV (six materials, three sizes, two shapes, uniform
environment), each row labelled with its scene's features the same way.

usage: bench/calibrate_planner.py [BUILD_DIR] [OUT_DIR]   (defaults: build data/planner)
A report's results are cached in BUILD_DIR/calibration/<scene>/cache (a rerun with the same lucent
executable resumes). Standard library only. About 14 minutes on 2 cores.
"""
import csv
import io
import json
import os
import subprocess
import sys
import time

BUILD = sys.argv[1] if len(sys.argv) > 1 else "build"
OUT = sys.argv[2] if len(sys.argv) > 2 else "data/planner"
# LUCENT=path measures with another executable (a report's cache holds while its bytes are the same).
LUCENT = os.environ.get("LUCENT", os.path.join(BUILD, "lucent"))
WORK = os.path.join(BUILD, "calibration")
FLOORS = "docs/accuracy/pathtrace/dipole-vs-pathtrace.csv"
RES = ["--width", "48", "--height", "48"]
FRONT, BACK = "dir:0,0.6,1", "dir:0,0.3,-1"
# The physical truth (the ground truth that simulates single scattering, i.e. every order) at 256 of
# its swept samples, a cost the calibration affords; the dipole truth (the ground truth that does not)
# names the model whose floor bench/dipole_vs_pathtrace.py measured. Both read from the registry.
TRUTH_SAMPLES = 256

# Shapes x materials x sizes x light sides x environment: the scenes the planner's data cover.
SUITE = {
    "genus7-skin1-30-backlit": [],
    "genus7-skin1-30-backlit-96px": ["--width", "96", "--height", "96"],
    "sphere-marble-30-front": ["--shape", "sphere", "--material", "marble", "--light", FRONT],
    "twirl-skin1-30-backlit": ["--shape", "twirl"],
    "sphere-ketchup-10-side": ["--shape", "sphere", "--size-mm", "10", "--material", "ketchup",
                               "--light", "dir:1,0.5,0.5"],
    "sphere-skimmilk-50-backlit": ["--shape", "sphere", "--size-mm", "50", "--material", "skimmilk"],
    "torus-marble-10-backlit": ["--shape", "torus", "--size-mm", "10", "--material", "marble",
                                "--light", BACK, "--light", "dir:0,0.6,1:0.1,0.1,0.1"],
    "sphere-skin1-2000-front": ["--shape", "sphere", "--size-mm", "2000", "--light", FRONT],
    "genus7-cream-100-backlit": ["--size-mm", "100", "--material", "cream"],
    "sphere-spectralon-20-front": ["--shape", "sphere", "--size-mm", "20", "--material", "spectralon",
                                   "--light", FRONT],
    "sphere-skin1-10-env": ["--shape", "sphere", "--size-mm", "10", "--light", "env:uniform"],
    "twirl-marble-5-env": ["--shape", "twirl", "--size-mm", "5", "--material", "marble",
                           "--light", "env:uniform"],
    "cube-cavity-apple-20-backlit": ["--shape", "cube-cavity", "--size-mm", "20", "--material", "apple"],
    "sphere-marble-30-env": ["--shape", "sphere", "--material", "marble", "--light", "env:uniform"],
    "genus7-skin1-30-env": ["--light", "env:uniform"],
    "torus-skimmilk-20-env-front": ["--shape", "torus", "--size-mm", "20", "--material", "skimmilk",
                                    "--light", "env:uniform:0.5", "--light", FRONT],
    "sphere-marble-1000-backlit": ["--shape", "sphere", "--size-mm", "1000", "--material", "marble",
                                   "--light", BACK, "--light", "dir:0,0.6,1:0.1,0.1,0.1"],
    "twirl-cream-10-front": ["--shape", "twirl", "--size-mm", "10", "--material", "cream",
                             "--light", FRONT],
    # The same objects at other resolutions: how time grows with the points shaded.
    "sphere-marble-30-front-96px": ["--width", "96", "--height", "96", "--shape", "sphere",
                                    "--material", "marble", "--light", FRONT],
    "twirl-skin1-30-backlit-96px": ["--width", "96", "--height", "96", "--shape", "twirl"],
    "genus7-skin1-30-backlit-192px": ["--width", "192", "--height", "192"],
    "genus7-skin1-30-backlit-400px": ["--width", "400", "--height", "400"],  # render's default
    "cube-cavity-apple-20-backlit-96px": ["--width", "96", "--height", "96", "--shape", "cube-cavity",
                                          "--size-mm", "20", "--material", "apple"],
    "torus-marble-10-backlit-24px": ["--width", "24", "--height", "24", "--shape", "torus",
                                     "--size-mm", "10", "--material", "marble", "--light", BACK,
                                     "--light", "dir:0,0.6,1:0.1,0.1,0.1"],
    "sphere-skimmilk-50-backlit-24px": ["--width", "24", "--height", "24", "--shape", "sphere",
                                        "--size-mm", "50", "--material", "skimmilk"],
}


def run(args, **kw):
    return subprocess.run([LUCENT] + args, check=True, text=True, **kw)


def truths():
    """(--truth-knob arguments for the physical truth, the model of the dipole truth)."""
    techniques = json.loads(run(["techniques", "--json"], capture_output=True).stdout)["techniques"]
    ground = [t for t in techniques if t["capabilities"]["ground_truth"]]
    physical = next(t for t in ground if t["capabilities"]["single_scattering"])
    dipole = next(t for t in ground if not t["capabilities"]["single_scattering"])
    knob = physical["default_sweep"][0]["knob"]
    return ["--truth-knob", f"{physical['name']}.{knob}={TRUTH_SAMPLES}"], dipole["model"]


def features(scene_args):
    """The planner's features of a scene: a dict of name -> text."""
    out = run(["plan", "--features"] + scene_args, capture_output=True).stdout
    rows = list(csv.reader(io.StringIO(out)))
    return dict(zip(rows[0], rows[1])), rows[0]


def measure_settings(truth_knobs):
    rows, names = [], None
    for scene, extra in SUITE.items():
        scene_args = RES + extra if "--width" not in extra else extra
        start = time.time()
        folder = os.path.join(WORK, scene)
        run(["report", "--quiet", "--truth", "model", "--out", folder] + truth_knobs + scene_args)
        feats, names = features(scene_args)
        with open(os.path.join(folder, "results.csv")) as f:
            for r in csv.DictReader(f):
                rows.append({"scene": scene, **feats, **{k: r[k] for k in (
                    "technique", "model", "knobs", "seconds", "prepare_seconds", "frame_seconds",
                    "relative_rms_model")}})
        print(f"{scene}: {time.time() - start:.0f} s", file=sys.stderr)
    # Settings measured against no truth (a model without one) cannot calibrate an error.
    rows = [r for r in rows if r["relative_rms_model"] not in ("nan", "")]
    cols = ["scene"] + names + ["technique", "model", "knobs", "seconds", "prepare_seconds",
                                "frame_seconds", "relative_rms_model"]
    write(os.path.join(OUT, "settings.csv"), cols, rows)


def measure_floors(model):
    rows, names = [], None
    with open(FLOORS) as f:
        for r in csv.DictReader(f):
            scene_args = RES + ["--shape", r["shape"], "--size-mm", r["size_mm"], "--material",
                                r["material"], "--light", "env:uniform"]
            feats, names = features(scene_args)
            # dipole / PT(all) over dipole / PT(multiple) = PT(multiple) / PT(all): what is left
            # without single scattering.
            single = max(1 - float(r[f"dipole_over_pt_all_{c}"]) / float(r[f"dipole_over_pt_multiple_{c}"])
                         for c in "rgb")
            rows.append({"scene": f"{r['shape']}-{r['material']}-{r['size_mm']}-env", **feats,
                         "model": model, "relative_rms_physical": r["relative_rms_vs_all"],
                         "single_share": f"{min(max(single, 0.0), 1.0):.6g}"})
    write(os.path.join(OUT, "model-floors.csv"),
          ["scene"] + names + ["model", "relative_rms_physical", "single_share"], rows)


def write(path, cols, rows):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    tmp = path + ".tmp"
    with open(tmp, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=cols, lineterminator="\n")
        w.writeheader()
        w.writerows(rows)
    os.replace(tmp, path)
    print(f"wrote {path} ({len(rows)} rows)", file=sys.stderr)


if __name__ == "__main__":
    truth_knobs, dipole_model = truths()
    measure_floors(dipole_model)
    measure_settings(truth_knobs)
