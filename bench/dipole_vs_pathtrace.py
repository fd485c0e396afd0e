#!/usr/bin/env python3
"""The dipole (model truth: `lucent render --method reference`) against the volumetric path tracer
(physical truth: `--method pathtrace`), for the materials, sizes and shapes of the path-tracing issue.

Light: a uniform environment (env:uniform), which both render exactly as specified: the dipole integrates
its irradiance with Fresnel transmission, the path tracer reaches it with every path that leaves (every
scattering order, no join needed). The path tracer renders the subsurface part only (subsurface=1), as the
dipole does, once with every order and once with multiple scattering only (what the dipole models).

usage: bench/dipole_vs_pathtrace.py [BUILD_DIR] [OUT_DIR]   (defaults: build docs/accuracy/pathtrace)
writes OUT_DIR/dipole-vs-pathtrace.csv and prints a Markdown table. Standard library only.
"""
import csv
import os
import shutil
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lucent_cli  # noqa: E402

BUILD = sys.argv[1] if len(sys.argv) > 1 else "build"
OUT = sys.argv[2] if len(sys.argv) > 2 else "docs/accuracy/pathtrace"
LUCENT = os.path.join(BUILD, "lucent")
MATERIALS = ["skin1", "skin2", "marble", "skimmilk", "ketchup", "spectralon"]
SIZES = [1, 10, 30]
SHAPES = ["sphere", "twirl"]
RES, SPP = 48, 256
TMP = os.path.join(OUT, "tmp")


def render(shape, size, material, method, tag, knobs=()):
    options = ["--shape", shape, "--size-mm", str(size), "--material", material, "--light", "env:uniform",
               "--width", str(RES), "--height", str(RES)]
    return lucent_cli.render(LUCENT, TMP, tag, options, method, knobs)


def compare(test, ref):
    return lucent_cli.compare(LUCENT, test, ref)


def main():
    os.makedirs(TMP, exist_ok=True)
    rows = []
    start = time.time()
    for shape in SHAPES:
        for size in SIZES:
            for material in MATERIALS:
                tag = f"{shape}-{size}-{material}"
                ref, ref_stats = render(shape, size, material, "reference", tag + "-dipole")
                knobs = ("subsurface=1", f"spp={SPP}")
                pt, pt_stats = render(shape, size, material, "pathtrace", tag + "-pt", knobs)
                ms, ms_stats = render(shape, size, material, "pathtrace", tag + "-ms", knobs + ("orders=multiple",))
                # Ratios dipole / path tracer: > 1 where the dipole is too bright.
                all_cmp, ms_cmp = compare(ref, pt), compare(ref, ms)
                fig = pt_stats["figures"]
                se_pixel = fig["mean_pixel_relative_stderr"]
                row = {
                    "shape": shape, "size_mm": size, "material": material,
                    "dipole_over_pt_all_r": all_cmp["mean_ratio_r"], "dipole_over_pt_all_g": all_cmp["mean_ratio_g"],
                    "dipole_over_pt_all_b": all_cmp["mean_ratio_b"],
                    "dipole_over_pt_multiple_r": ms_cmp["mean_ratio_r"], "dipole_over_pt_multiple_g": ms_cmp["mean_ratio_g"],
                    "dipole_over_pt_multiple_b": ms_cmp["mean_ratio_b"],
                    "relative_rms_vs_all": all_cmp["relative_rms"], "relative_rms_vs_multiple": ms_cmp["relative_rms"],
                    "pt_image_mean_relative_stderr": fig["image_mean_relative_stderr"],
                    "pt_pixel_relative_stderr": se_pixel,
                    "pt_seconds": pt_stats["wall_seconds"], "dipole_seconds": ref_stats["wall_seconds"],
                    "pt_seconds_to_1pct_pixel_stderr": pt_stats["wall_seconds"] * (se_pixel / 0.01) ** 2,
                    "pt_truncated_paths": fig["truncated_paths"],
                }
                rows.append(row)
                print(f"{tag}: dipole/pt all {row['dipole_over_pt_all_r']:.3f} {row['dipole_over_pt_all_g']:.3f} "
                      f"{row['dipole_over_pt_all_b']:.3f}, multiple {row['dipole_over_pt_multiple_r']:.3f} "
                      f"{row['dipole_over_pt_multiple_g']:.3f} {row['dipole_over_pt_multiple_b']:.3f}", file=sys.stderr)
    with open(os.path.join(OUT, "dipole-vs-pathtrace.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    print("| shape | mm | material | dipole / PT, all orders (R G B) | dipole / PT, multiple only (R G B) | "
          "rel. RMS vs all | PT s.e. image mean | PT s | PT s to 1 % pixel s.e. | dipole s |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['shape']} | {r['size_mm']} | {r['material']} | "
              f"{r['dipole_over_pt_all_r']:.2f} {r['dipole_over_pt_all_g']:.2f} {r['dipole_over_pt_all_b']:.2f} | "
              f"{r['dipole_over_pt_multiple_r']:.2f} {r['dipole_over_pt_multiple_g']:.2f} {r['dipole_over_pt_multiple_b']:.2f} | "
              f"{r['relative_rms_vs_all']:.2f} | {100 * r['pt_image_mean_relative_stderr']:.2f} % | {r['pt_seconds']:.2f} | "
              f"{r['pt_seconds_to_1pct_pixel_stderr']:.0f} | {r['dipole_seconds']:.2f} |")
    shutil.rmtree(TMP)
    print(f"\n{len(rows)} cases in {time.time() - start:.0f} s", file=sys.stderr)


if __name__ == "__main__":
    main()
