#!/usr/bin/env python3
"""What a refracting boundary costs the path tracer: the time to 1 % relative noise per pixel with the
material's eta (boundary=fresnel) against eta 1 (boundary=matched), on 30 mm spheres under a uniform
environment, measured in one run. With --baseline OTHER_LUCENT the same table is printed for another
build (before a change) beside it.

  /usr/bin/python3 bench/pathtrace_eta_cost.py build/lucent [--baseline OLD_LUCENT] [--spp 64]

Time to 1 % = seconds x (mean per-pixel relative standard error / 0.01)^2 (the error falls as
1/sqrt(spp)); the error is lucent's own per-pixel estimate (`--stats`: mean_pixel_relative_stderr).
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile


def measure(lucent, material, boundary, spp, size, workdir):
    stats = os.path.join(workdir, "stats.json")
    out = os.path.join(workdir, "pt.exr")
    cmd = [lucent, "render", "--quiet", "--shape", "sphere", "--size-mm", "30", "--material", material,
           "--light", "env:uniform", "--width", str(size), "--height", str(size), "--method", "pathtrace",
           "--knob", f"spp={spp}", "--knob", f"boundary={boundary}", "--out", out, "--stats", stats]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    with open(stats) as f:
        s = json.load(f)
    f = s["figures"]
    seconds, err = f["frame_seconds"], f["mean_pixel_relative_stderr"]
    paths = f["camera_samples"]
    scatters = f["scatter_events"] / paths
    ended = f.get("roulette_terminations", float("nan")) / paths  # absent in older builds
    return seconds, err, seconds * (err / 0.01) ** 2, scatters, ended


def table(lucent, spp, size, workdir):
    rows = {}
    for material in ("marble", "skin1"):
        for boundary in ("matched", "fresnel"):
            rows[(material, boundary)] = measure(lucent, material, boundary, spp, size, workdir)
    return rows


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("lucent")
    p.add_argument("--baseline", help="another lucent binary, measured in the same run")
    p.add_argument("--spp", type=int, default=64)
    p.add_argument("--size", type=int, default=64, help="image width and height")
    a = p.parse_args()
    builds = [("this build", a.lucent)] + ([("baseline", a.baseline)] if a.baseline else [])
    with tempfile.TemporaryDirectory() as workdir:
        results = {name: table(binary, a.spp, a.size, workdir) for name, binary in builds}
    print(f"30 mm spheres, uniform environment, {a.size}x{a.size}, {a.spp} spp")
    print("| build | material | boundary | s | mean rel. stderr | s to 1 % | fresnel / matched "
          "| scatters / path | roulette ends / path |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name, rows in results.items():
        for material in ("marble", "skin1"):
            base = rows[(material, "matched")][2]
            for boundary in ("matched", "fresnel"):
                s, e, t, scatters, ended = rows[(material, boundary)]
                ratio = f"{t / base:.2f}" if boundary == "fresnel" else ""
                print(f"| {name} | {material} | {boundary} | {s:.2f} | {e:.4f} | {t:.0f} | {ratio} "
                      f"| {scatters:.0f} | {ended:.3f} |")
    if a.baseline:
        for material in ("marble", "skin1"):
            now = results["this build"][(material, "fresnel")][2]
            then = results["baseline"][(material, "fresnel")][2]
            print(f"{material}, fresnel: time to 1 % this build / baseline = {now / then:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
