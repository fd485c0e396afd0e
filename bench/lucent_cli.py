"""The CLI calls the accuracy benches share: a render with its stats, and `lucent compare`. Standard library
only; the benches import it from their own folder."""
import json
import os
import subprocess


def render(lucent, folder, tag, options, method, knobs=()):
    """`lucent render` of OPTIONS with METHOD and KNOBS into FOLDER/TAG.exr; returns (exr, stats dict)."""
    exr, stats = os.path.join(folder, tag + ".exr"), os.path.join(folder, tag + ".json")
    cmd = [lucent, "render", "--quiet", *options, "--method", method, "--out", exr, "--stats", stats]
    for k in knobs:
        cmd += ["--knob", k]
    subprocess.run(cmd, check=True, stderr=subprocess.DEVNULL)
    with open(stats) as f:
        return exr, json.load(f)


def compare(lucent, test, ref):
    """`lucent compare TEST REF --json` as a dict (relative_rms, mean_ratio_r/g/b, ...)."""
    out = subprocess.run([lucent, "compare", test, ref, "--json"], check=True, capture_output=True, text=True)
    return json.loads(out.stdout)
