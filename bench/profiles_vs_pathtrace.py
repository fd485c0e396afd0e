#!/usr/bin/env python3
"""Every diffusion profile through the brute-force sum (`--method reference --knob profile=P`) against
the volumetric path tracer with every scattering order, on the cases of dipole_vs_pathtrace.py
(spheres and the thin twirl at 1, 10, 30 mm, six materials, uniform environment, subsurface part only).

usage: bench/profiles_vs_pathtrace.py [BUILD_DIR] [OUT_DIR]   (defaults: build docs/accuracy/profiles)
writes OUT_DIR/profiles-vs-pathtrace.csv and prints Markdown tables. Standard library only.
"""
import csv
import os
import shutil
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import dipole_vs_pathtrace as base  # noqa: E402  (render, compare, the cases)

BUILD = sys.argv[1] if len(sys.argv) > 1 else "build"
OUT = sys.argv[2] if len(sys.argv) > 2 else "docs/accuracy/profiles"
base.LUCENT = os.path.join(BUILD, "lucent")
base.TMP = os.path.join(OUT, "tmp")


def profile_names():
    out = subprocess.run([base.LUCENT, "techniques", "--json"], check=True, capture_output=True, text=True).stdout
    import json
    for t in json.loads(out)["techniques"]:
        if t["name"] == "reference":
            return next(k["choices"] for k in t["knobs"] if k["name"] == "profile")
    raise SystemExit("the reference technique has no profile knob")


def main():
    os.makedirs(base.TMP, exist_ok=True)
    profiles = profile_names()
    rows, start = [], time.time()
    for shape in base.SHAPES:
        for size in base.SIZES:
            for material in base.MATERIALS:
                tag = f"{shape}-{size}-{material}"
                try:  # the same validity for every profile: diffusion needs 3 transport mean free paths
                    first = base.render(shape, size, material, "reference", f"{tag}-{profiles[0]}", (f"profile={profiles[0]}",))
                except subprocess.CalledProcessError:
                    print(f"{tag}: outside the reference's valid range, skipped", file=sys.stderr)
                    continue
                pt, _ = base.render(shape, size, material, "pathtrace", tag + "-pt", ("subsurface=1", f"spp={base.SPP}"))
                for p in profiles:
                    img, stats = first if p == profiles[0] else base.render(
                        shape, size, material, "reference", f"{tag}-{p}", (f"profile={p}",))
                    c = base.compare(img, pt)
                    rows.append({"shape": shape, "size_mm": size, "material": material, "profile": p,
                                 "ratio_r": c["mean_ratio_r"], "ratio_g": c["mean_ratio_g"], "ratio_b": c["mean_ratio_b"],
                                 "relative_rms": c["relative_rms"], "seconds": stats["wall_seconds"]})
                print(f"{tag} done ({time.time() - start:.0f} s)", file=sys.stderr)
    with open(os.path.join(OUT, "profiles-vs-pathtrace.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    print("| shape | mm | material | " + " | ".join(f"{p}: ratio R G B, rel. RMS" for p in profiles) + " |")
    print("|---|---|---|" + "---|" * len(profiles))
    for i in range(0, len(rows), len(profiles)):
        group = rows[i:i + len(profiles)]
        r0 = group[0]
        cells = [f"{r['ratio_r']:.2f} {r['ratio_g']:.2f} {r['ratio_b']:.2f}, {r['relative_rms']:.2f}" for r in group]
        print(f"| {r0['shape']} | {r0['size_mm']} | {r0['material']} | " + " | ".join(cells) + " |")
    print("\n| profile | median rel. RMS, all | median, spheres 10-30 mm | best in cases |")
    print("|---|---|---|---|")
    cases = {}
    for r in rows:
        cases.setdefault((r["shape"], r["size_mm"], r["material"]), []).append(r)
    for p in profiles:
        mine = [r for r in rows if r["profile"] == p]
        thick = [r["relative_rms"] for r in mine if r["shape"] == "sphere" and r["size_mm"] >= 10]
        best = sum(1 for g in cases.values() if min(g, key=lambda r: r["relative_rms"])["profile"] == p)
        print(f"| {p} | {statistics.median(r['relative_rms'] for r in mine):.3f} | {statistics.median(thick):.3f} | "
              f"{best} of {len(cases)} |")
    shutil.rmtree(base.TMP)
    print(f"\n{len(rows)} renders in {time.time() - start:.0f} s", file=sys.stderr)


if __name__ == "__main__":
    main()
