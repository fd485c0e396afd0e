#!/usr/bin/env python3
"""The random walk (`--method randomwalk`) against the volumetric path tracer (the physical truth,
`--method pathtrace --knob subsurface=1`): its bias, its noise and its time, beside the classic dipole.

Cases: the default scene (a 30 mm genus-7 skin1 ring, back-lit by a point light, a weak directional fill),
a thin back-lit skin1 ribbon (twirl), and 30 mm marble and skin1 spheres under a uniform sky. The truth is
rendered once per case at REF_SPP samples a pixel (cached in OUT/tmp); every other setting is compared with
it by `lucent compare` (relative RMS over covered pixels, mean ratio per channel). The mean ratio's own
uncertainty is the two images' mean relative standard errors combined (from --stats). "s to 1 %" is the
time the setting would need for a per-pixel relative standard error of 1 % (seconds x (stderr / 0.01)^2).

usage: bench/randomwalk_vs_pathtrace.py [BUILD_DIR] [OUT_DIR]   (defaults: build docs/accuracy/randomwalk)
writes OUT_DIR/randomwalk-vs-pathtrace.csv and prints a Markdown table. Standard library only.
"""
import csv
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lucent_cli  # noqa: E402

BUILD = sys.argv[1] if len(sys.argv) > 1 else "build"
OUT = sys.argv[2] if len(sys.argv) > 2 else "docs/accuracy/randomwalk"
LUCENT = os.path.join(BUILD, "lucent")
TMP = os.path.join(OUT, "tmp")

# name, scene options, truth spp (point lights behind a refracting boundary converge slowly)
CASES = [
    ("default", ["--width", "64", "--height", "64"], 16384),
    ("twirl-back-lit", ["--shape", "twirl", "--width", "64", "--height", "64"], 16384),
    ("marble-sphere-sky", ["--shape", "sphere", "--material", "marble", "--light", "env:uniform",
                           "--width", "64", "--height", "64"], 2048),
    ("skin1-sphere-sky", ["--shape", "sphere", "--material", "skin1", "--light", "env:uniform",
                          "--width", "64", "--height", "64"], 2048),
]
SETTINGS = [
    ("reference", []),
    ("reference", ["single=refracted", "profile=pbd"]),
    ("pathtrace", ["subsurface=1", "spp=16"]),
    ("pathtrace", ["subsurface=1", "spp=256"]),
    ("randomwalk", ["spp=16"]),
    ("randomwalk", ["spp=64"]),
    ("randomwalk", ["spp=256"]),
    ("randomwalk", ["spp=1024"]),
    ("randomwalk", ["spp=256", "env-exit=lobe"]),
    ("randomwalk", ["spp=256", "exit=first"]),
]


def render(case_options, method, knobs, tag):
    return lucent_cli.render(LUCENT, TMP, tag, case_options, method, knobs)


def compare(test, ref):
    return lucent_cli.compare(LUCENT, test, ref)


def truth(name, options, spp):
    tag = f"{name}-truth-{spp}"
    exr, stats = os.path.join(TMP, tag + ".exr"), os.path.join(TMP, tag + ".json")
    if not (os.path.exists(exr) and os.path.exists(stats)):
        print(f"{name}: the path tracer at {spp} spp (cached in {TMP})", file=sys.stderr)
        return render(options, "pathtrace", ["subsurface=1", f"spp={spp}"], tag)
    with open(stats) as f:
        return exr, json.load(f)


def row(name, method, knobs, stats, metrics, truth_error):
    fig = stats["figures"]
    err = fig.get("image_mean_relative_stderr", 0.0)
    pixel_err = fig.get("mean_pixel_relative_stderr", 0.0)
    seconds = stats["wall_seconds"]
    return {
        "case": name, "method": method, "knobs": " ".join(knobs) or "defaults",
        "seconds": round(seconds, 3), "relative_rms": round(metrics["relative_rms"], 4),
        "ratio_r": round(metrics["mean_ratio_r"], 4), "ratio_g": round(metrics["mean_ratio_g"], 4),
        "ratio_b": round(metrics["mean_ratio_b"], 4),
        "ratio_stderr": round(math.hypot(err, truth_error), 4),
        "pixel_relative_stderr": round(pixel_err, 4),
        "seconds_to_1pc": round(seconds * (pixel_err / 0.01) ** 2, 1) if pixel_err > 0 else "",
    }


def main():
    os.makedirs(TMP, exist_ok=True)
    rows = []
    for name, options, spp in CASES:
        ref, ref_stats = truth(name, options, spp)
        truth_error = ref_stats["figures"].get("image_mean_relative_stderr", 0.0)
        rows.append(row(name, "pathtrace", [f"subsurface=1", f"spp={spp}"], ref_stats,
                        compare(ref, ref), truth_error) | {"ratio_stderr": round(truth_error, 4)})
        for method, knobs in SETTINGS:
            tag = f"{name}-{method}-{'-'.join(knobs) or 'defaults'}".replace("=", "")
            exr, stats = render(options, method, knobs, tag)
            rows.append(row(name, method, knobs, stats, compare(exr, ref), truth_error))
            print(f"{name:18} {method:10} {' '.join(knobs):28} {rows[-1]['seconds']:8.2f} s  "
                  f"rel RMS {rows[-1]['relative_rms']:.3f}", file=sys.stderr)
    path = os.path.join(OUT, "randomwalk-vs-pathtrace.csv")
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    print("| case | setting | s | relative RMS | mean ratio R / G / B | +- | pixel stderr | s to 1 % |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['case']} | {r['method']} {r['knobs']} | {r['seconds']} | {r['relative_rms']} | "
              f"{r['ratio_r']} / {r['ratio_g']} / {r['ratio_b']} | {r['ratio_stderr']} | "
              f"{r['pixel_relative_stderr']} | {r['seconds_to_1pc']} |")
    print(f"\nwrote {path}", file=sys.stderr)


if __name__ == "__main__":
    main()
