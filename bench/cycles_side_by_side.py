#!/usr/bin/env python3
"""Side by side with Blender Cycles: lucent's volumetric path tracer (--method pathtrace) and Cycles
render the same scene -- lucent's built-in sphere (the level-5 icosphere, 20480 flat triangles, its
bounding-box diagonal 30 mm, so radius 8.66 mm), a smooth dielectric boundary at the material's eta
(boundary=fresnel, 1.3; --boundary matched: eta 1, no surface), the material's homogeneous medium
(sigma_s = sigma_s' / (1 - g), sigma_a, HG g; mm^-1, one Blender unit = 1 mm), a uniform
environment of radiance 1, and lucent's pinhole camera (30 degree vertical field of view, framed on
view 0,0.6,1, one ray through each pixel's centre) -- at several sample counts, each K times with
independent seeds. Prints per material and sample count each renderer's seconds per render, mean
radiance per channel, mean relative standard error of one render and the time to 1 % noise, and
lucent / Cycles: the mean ratio per channel and the largest deviation over radial bins. Where
Blender is absent it says so and exits 0; nothing depends on it.

  /usr/bin/python3 bench/cycles_side_by_side.py build/lucent [--blender blender] [--size 64]
      [--spp 16,64,256] [--seeds 4] [--materials marble,skin1] [--threads 2]
      [--boundary fresnel|matched]

Scene. The mesh is rebuilt here exactly as lucent builds it (scene/shapes.hpp: icosahedron,
midpoints normalised, float positions, centred and scaled to the bounding-box diagonal), and the
camera exactly as scene/camera.hpp frames it (distance = half the box diagonal / (sin 15 deg x 0.9)).
Cycles: CPU, --threads threads, Sharp Glass BSDF (IOR = eta, white; no surface shader for
--boundary matched, which Cycles passes straight through), Volume Scatter (colour x density
= sigma_s, anisotropy g) + Volume Absorption ((1 - colour) x density = sigma_a), homogeneous volume,
distance sampling, world colour 1 strength 1 (Cycles' automatic world light sampling; its shadow
rays cannot pass the glass, and --world-sampling NONE leaves it out), every bounce limit at its
maximum 1024 (lucent's cap is 200000 events; capped at 1024 it drops under 0.1 % of its marble
paths), no clamping, caustics on, no filter glossy, no denoising or adaptive sampling, a Gaussian
pixel filter 0.01 px wide (lucent traces each pixel's centre; Cycles widens a box filter to 1 px),
transparent film (the mask), standard view transform, 32-bit EXR.
Both run under taskset on --threads CPUs where the machine has more (lucent takes every core).

Figures, over the pixels both renderers cover in every render (the common mask):
  per pixel reference m = the renderer's mean over all its renders (spp-weighted);
  rel. stderr of one S-spp render = mean over the mask of (mean over channels of the seed standard
    deviation s_c) / (mean over channels of m_c), s_c from the K renders at S spp, divided by
    c4(K) (the bias of a sample standard deviation); lucent's own per-render figure
    (mean_pixel_relative_stderr, the same definition) is printed beside it;
  s to 1 % = seconds per render x (rel. stderr / 0.01)^2;
  seconds: each renderer's own path-tracing time -- lucent's figures.frame_seconds (--stats),
    Cycles' render_time from its EXR's metadata (0.01 s steps; scene sync excluded); Blender's
    start-up, scene building, Cycles' sync and the bpy.ops.render.render wall time are printed apart;
  ratio = mean over the mask of lucent / the same of Cycles per channel, its stderr propagated from
    the spread of the K renders' image means; pooled over all sample counts (spp-weighted) in the
    summary, with the largest |ratio - 1| over 8 equal-area rings around the sphere's image centre.

The same file runs inside Blender (blender -b -P this -- --blender-job JOB.json) to build the Cycles
scene, render, and dump every EXR (lucent's too) as raw float RGBA: no numpy or OpenEXR module is
needed on either side.
"""
import argparse
import array
import json
import math
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import time

try:
    import bpy  # present only inside Blender
except ImportError:
    bpy = None

FOV_DEG = 30.0  # PinholeCamera::frame's default vertical field of view
FILL = 0.9  # ... and the fraction of it the bounding sphere fills
ICOSPHERE_LEVELS = 5  # makeBuiltinShape("sphere"): shapes::sphere(1.0, 5)
RADIAL_BINS = 8


# ----------------------------------------------------------------------------- lucent's geometry

def f32(x):
    """x rounded to float, as glm::vec3 stores it."""
    return struct.unpack("f", struct.pack("f", x))[0]


def normalize(v):
    n = math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
    return (v[0] / n, v[1] / n, v[2] / n)


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def icosphere(levels):
    """shapes::sphere(1, levels): unit positions (double) and triangles, before orientation."""
    t = (1.0 + math.sqrt(5.0)) / 2.0
    verts = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t),
             (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    tris = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
            (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
            (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    p = [normalize(v) for v in verts]
    for _ in range(levels):
        mid, nxt = {}, []
        for x, y, z in tris:
            a, b, c = midpoint(p, mid, x, y), midpoint(p, mid, y, z), midpoint(p, mid, z, x)
            nxt += [(x, a, c), (y, b, a), (z, c, b), (a, b, c)]
        tris = nxt
    return p, tris


def midpoint(p, mid, a, b):
    """The index of the normalised midpoint of edge (a, b), appended to p on first use."""
    key = (min(a, b), max(a, b))
    if key not in mid:
        p.append(normalize(tuple(p[a][k] + p[b][k] for k in range(3))))
        mid[key] = len(p) - 1
    return mid[key]


def signed_volume(pos, tris):
    return sum(sum(a * b for a, b in zip(pos[i], cross(pos[j], pos[k]))) for i, j, k in tris) / 6


def bounds(pos):
    lo = tuple(min(q[c] for q in pos) for c in range(3))
    hi = tuple(max(q[c] for q in pos) for c in range(3))
    return lo, hi


def lucent_sphere(size_mm):
    """The mesh of `lucent render --shape sphere --size-mm X`: float positions, outward triangles."""
    unit, tris = icosphere(ICOSPHERE_LEVELS)
    pos = [tuple(f32(c) for c in q) for q in unit]
    if signed_volume(pos, tris) < 0:  # detail::orientOutward
        tris = [(a, c, b) for a, b, c in tris]
    lo, hi = bounds(pos)  # TriangleMesh::scaleToSize
    diag = math.sqrt(sum((h - l) ** 2 for l, h in zip(lo, hi)))
    s, c = size_mm / diag, tuple(0.5 * (l + h) for l, h in zip(lo, hi))
    pos = [tuple(f32((q[k] - c[k]) * s) for k in range(3)) for q in pos]
    return pos, tris


def lucent_camera(pos, view, width, height):
    """PinholeCamera::frame: eye, target and the camera's right, up and forward axes."""
    lo, hi = bounds(pos)
    target = tuple(0.5 * (l + h) for l, h in zip(lo, hi))
    radius = 0.5 * math.sqrt(sum((h - l) ** 2 for l, h in zip(lo, hi)))
    half = 0.5 * math.radians(FOV_DEG)
    aspect = width / height
    half_min = math.atan(math.tan(half) * aspect) if aspect < 1 else half
    distance = radius / (math.sin(half_min) * FILL)
    v = normalize(view)
    eye = tuple(t + d * distance for t, d in zip(target, v))
    up = (0.0, 0.0, 1.0) if abs(v[1]) > 0.999 else (0.0, 1.0, 0.0)
    forward = normalize(tuple(t - e for t, e in zip(target, eye)))
    right = normalize(cross(forward, up))
    return {"eye": eye, "right": right, "up": cross(right, forward), "forward": forward,
            "distance": distance, "radius": radius}


# ----------------------------------------------------------------------------- inside Blender

def blender_mesh_object(size_mm):
    pos, tris = lucent_sphere(size_mm)
    mesh = bpy.data.meshes.new("lucent_sphere")
    mesh.from_pydata(pos, [], tris)
    mesh.update()
    for poly in mesh.polygons:
        poly.use_smooth = False  # lucent refracts at the flat facets' geometric normals
    obj = bpy.data.objects.new("lucent_sphere", mesh)
    bpy.context.scene.collection.objects.link(obj)
    return obj, len(pos), len(tris)


def normalised_colour(values):
    """(colour, density) with colour x density = values, colour within [0, 1]."""
    d = max(values)
    return ([v / d for v in values] if d > 0 else [0.0, 0.0, 0.0]), d


def blender_material(medium, boundary):
    mat = bpy.data.materials.new("lucent_medium")
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")
    glass = nodes.new("ShaderNodeBsdfGlass")
    glass.distribution = "SHARP"
    glass.inputs["Color"].default_value = (1, 1, 1, 1)
    glass.inputs["Roughness"].default_value = 0.0
    glass.inputs["IOR"].default_value = medium["eta"]
    if boundary == "fresnel":
        links.new(glass.outputs[0], out.inputs["Surface"])
    scatter = nodes.new("ShaderNodeVolumeScatter")
    colour, density = normalised_colour(medium["sigma_s"])
    scatter.inputs["Color"].default_value = colour + [1]
    scatter.inputs["Density"].default_value = density
    scatter.inputs["Anisotropy"].default_value = medium["g"]
    absorb = nodes.new("ShaderNodeVolumeAbsorption")
    colour, density = normalised_colour(medium["sigma_a"])
    absorb.inputs["Color"].default_value = [1 - c for c in colour] + [1]
    absorb.inputs["Density"].default_value = density
    add = nodes.new("ShaderNodeAddShader")
    links.new(scatter.outputs[0], add.inputs[0])
    links.new(absorb.outputs[0], add.inputs[1])
    links.new(add.outputs[0], out.inputs["Volume"])
    mat.cycles.homogeneous_volume = True
    mat.cycles.volume_sampling = "DISTANCE"
    return mat


def blender_world(radiance, sampling):
    world = bpy.data.worlds.new("uniform")
    world.use_nodes = True
    bg = world.node_tree.nodes["Background"]
    bg.inputs["Color"].default_value = (1, 1, 1, 1)
    bg.inputs["Strength"].default_value = radiance
    world.cycles.sampling_method = sampling
    bpy.context.scene.world = world


def blender_camera(cam):
    import mathutils
    data = bpy.data.cameras.new("lucent_camera")
    data.type = "PERSP"
    data.sensor_fit = "VERTICAL"
    data.angle_y = math.radians(FOV_DEG)
    data.shift_x = data.shift_y = 0.0
    data.clip_start, data.clip_end = 1e-3 * cam["distance"], 1e3 * cam["distance"]
    obj = bpy.data.objects.new("lucent_camera", data)
    back = tuple(-f for f in cam["forward"])  # a Blender camera looks down its local -z
    m = mathutils.Matrix.Identity(4)
    for row in range(3):
        m[row][0], m[row][1], m[row][2] = cam["right"][row], cam["up"][row], back[row]
        m[row][3] = cam["eye"][row]
    obj.matrix_world = m
    bpy.context.scene.collection.objects.link(obj)
    bpy.context.scene.camera = obj


def blender_cycles_settings(scene, job):
    scene.render.engine = "CYCLES"
    c = scene.cycles
    c.device = "CPU"
    c.use_denoising = c.use_adaptive_sampling = c.use_animated_seed = False
    c.sample_clamp_direct = c.sample_clamp_indirect = 0.0
    c.blur_glossy = 0.0
    c.caustics_reflective = c.caustics_refractive = True
    for name in ("max_bounces", "diffuse_bounces", "glossy_bounces", "transmission_bounces",
                 "volume_bounces", "transparent_max_bounces"):
        setattr(c, name, 1024)
    c.min_light_bounces = c.min_transparent_bounces = 0
    if hasattr(c, "use_guiding"):
        c.use_guiding = False
    # Cycles forces a box filter to 1 px (sync_film); a 0.01 px Gaussian is a pixel-centre sample.
    c.pixel_filter_type, c.filter_width = "GAUSSIAN", 0.01
    r = scene.render
    r.threads_mode, r.threads = "FIXED", job["threads"]
    r.resolution_x, r.resolution_y, r.resolution_percentage = job["width"], job["height"], 100
    r.pixel_aspect_x = r.pixel_aspect_y = 1
    # The mask comes from Cycles' alpha, but a transparent film also drops the sky seen straight
    # through a surface with no shader: with --boundary matched the mask is lucent's alone.
    r.film_transparent = job["boundary"] == "fresnel"
    r.use_compositing = r.use_sequencer = False
    r.image_settings.file_format, r.image_settings.color_mode = "OPEN_EXR", "RGBA"
    r.image_settings.color_depth, r.image_settings.exr_codec = "32", "ZIP"
    blender_colour_management(scene)


def blender_colour_management(scene):
    """Linear, untouched output (float EXR is written scene-linear whatever the view)."""
    vs = scene.view_settings
    for view in ("Standard", "Raw"):  # a dynamic enum: its items show only on assignment
        try:
            vs.view_transform = view
            break
        except TypeError:
            pass
    try:
        vs.look = "None"
    except TypeError:
        pass
    vs.exposure, vs.gamma = 0.0, 1.0


def blender_build(job):
    t0 = time.perf_counter()
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    obj, nverts, ntris = blender_mesh_object(job["size_mm"])
    obj.data.materials.append(blender_material(job["medium"], job["boundary"]))
    pos = [v.co[:] for v in obj.data.vertices]
    cam = lucent_camera(pos, job["view"], job["width"], job["height"])
    blender_camera(cam)
    blender_world(job["radiance"], job["world_sampling"])
    blender_cycles_settings(scene, job)
    radii = [math.sqrt(sum(c * c for c in p)) for p in pos]
    return {"build_seconds": time.perf_counter() - t0, "vertices": nverts, "triangles": ntris,
            "version": bpy.app.version_string,
            "radius_min": min(radii), "radius_max": max(radii), "camera_distance": cam["distance"]}


def blender_render_all(job):
    scene, times = bpy.context.scene, []
    for item in job["renders"]:
        scene.cycles.samples, scene.cycles.seed = item["spp"], item["seed"]
        scene.render.filepath = item["out"]
        t0 = time.perf_counter()
        bpy.ops.render.render(write_still=True)
        times.append(time.perf_counter() - t0)
    return times


def blender_dump(exrs, out_dir):
    """Each EXR's pixels (RGBA float, bottom row first) as raw float32 in out_dir/N.f32."""
    sizes = []
    for n, path in enumerate(exrs):
        img = bpy.data.images.load(path)
        img.colorspace_settings.name = "Non-Color"
        w, h = img.size
        buf = array.array("f", bytes(4 * 4 * w * h))
        img.pixels.foreach_get(buf)
        with open(os.path.join(out_dir, f"{n}.f32"), "wb") as f:
            buf.tofile(f)
        sizes.append([w, h])
        bpy.data.images.remove(img)
    return sizes


def blender_main(argv):
    job_file = argv[argv.index("--blender-job") + 1]
    with open(job_file) as f:
        job = json.load(f)
    result = blender_build(job)
    result["render_seconds"] = blender_render_all(job)
    result["sizes"] = blender_dump(job["dump"], job["dump_dir"])
    with open(job["result"], "w") as f:
        json.dump(result, f)


# ----------------------------------------------------------------------------- running renderers

def pinned(cmd, threads):
    """cmd under taskset on `threads` CPUs where the machine has more (lucent takes every core)."""
    if (os.cpu_count() or 1) > threads and shutil.which("taskset"):
        return ["taskset", "-c", f"0-{threads - 1}"] + cmd
    return cmd


def run_quietly(cmd):
    """Runs cmd; its output is shown only when it fails."""
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if p.returncode != 0:
        sys.stderr.write(p.stdout[-4000:])
        raise subprocess.CalledProcessError(p.returncode, cmd)


def lucent_render(a, material, spp, seed, out, stats):
    cmd = [a.lucent, "render", "--quiet", "--shape", "sphere", "--size-mm", str(a.size_mm),
           "--material", material, "--light", "env:uniform", "--view", a.view,
           "--width", str(a.size), "--height", str(a.size), "--method", "pathtrace",
           "--knob", f"spp={spp}", "--knob", f"seed={seed}", "--knob", f"boundary={a.boundary}",
           "--knob", f"g={a.g}", "--out", out, "--stats", stats]
    t0 = time.perf_counter()
    run_quietly(pinned(cmd, a.threads))
    wall = time.perf_counter() - t0
    with open(stats) as f:
        s = json.load(f)
    return s, wall


def medium_from_stats(s):
    """lucent's medium: sigma_s = sigma_s' / (1 - g) (mediumFromMaterial), sigma_a, g, eta."""
    m, g = s["material"], float(s["knobs"]["g"])
    return {"name": m["name"], "eta": m["eta"], "g": g,
            "sigma_a": [m[f"sigma_a_{c}"] for c in "rgb"],
            "sigma_s": [m[f"sigma_s_prime_{c}"] / (1 - g) for c in "rgb"]}


def plan(a):
    """(spp, seed, index) of every render: distinct seeds, so no two renders share samples."""
    return [(spp, 1 + i * a.seeds + k, k) for i, spp in enumerate(a.spp) for k in range(a.seeds)]


def run_lucent(a, material, workdir):
    runs = {}
    for spp, seed, k in plan(a):
        out = os.path.join(workdir, f"lucent_{spp}_{k}.exr")
        s, wall = lucent_render(a, material, spp, seed, out, os.path.join(workdir, "stats.json"))
        f = s["figures"]
        runs[(spp, k)] = {"exr": out, "seconds": f["frame_seconds"], "wall": wall,
                          "own_stderr": f["mean_pixel_relative_stderr"], "stats": s}
    return runs


def run_cycles(a, medium, lucent_runs, workdir):
    renders = [{"spp": spp, "seed": seed, "out": os.path.join(workdir, f"cycles_{spp}_{k}.exr")}
               for spp, seed, k in plan(a)]
    dump = [r["out"] for r in renders] + [lucent_runs[(spp, k)]["exr"] for spp, _, k in plan(a)]
    job = {"size_mm": a.size_mm, "view": [float(x) for x in a.view.split(",")], "width": a.size,
           "height": a.size, "medium": medium, "radiance": 1.0, "threads": a.threads,
           "world_sampling": a.world_sampling, "boundary": a.boundary, "renders": renders,
           "dump": dump,
           "dump_dir": workdir, "result": os.path.join(workdir, "blender.json")}
    job_file = os.path.join(workdir, "job.json")
    with open(job_file, "w") as f:
        json.dump(job, f)
    cmd = [a.blender, "-b", "--factory-startup", "-noaudio", "--python-exit-code", "1",
           "-P", os.path.abspath(__file__), "--", "--blender-job", job_file]
    t0 = time.perf_counter()
    run_quietly(pinned(cmd, a.threads))
    wall = time.perf_counter() - t0
    with open(job["result"]) as f:
        res = json.load(f)
    res["wall"] = wall
    res["cycles"] = [cycles_times(r["out"]) for r in renders]
    return res, load_dumps(workdir, res["sizes"], plan(a))


def exr_header_string(path, suffix):
    """The value of the first string attribute whose name ends with `suffix` in an EXR's header."""
    with open(path, "rb") as f:
        head = f.read(1 << 16)
    key = suffix.encode() + b"\0string\0"
    at = head.find(key)
    if at < 0:
        return None
    at += len(key)
    size = struct.unpack("<i", head[at:at + 4])[0]
    return head[at + 4:at + 4 + size].decode()


def duration(text):
    """Seconds of Blender's "[[HH:]MM:]SS.cc" time stamps."""
    seconds = 0.0
    for part in text.split(":"):
        seconds = 60 * seconds + float(part)
    return seconds


def cycles_times(path):
    """Cycles' own path-tracing and scene-sync seconds of a render, from its EXR's metadata."""
    return {k: duration(exr_header_string(path, f".{k}_time") or "nan")
            for k in ("render", "synchronization", "total")}


def load_dumps(workdir, sizes, renders):
    images = {}
    n = len(renders)
    for idx, (w, h) in enumerate(sizes):
        buf = array.array("f")
        with open(os.path.join(workdir, f"{idx}.f32"), "rb") as f:
            buf.fromfile(f, 4 * w * h)
        spp, _, k = renders[idx % n]
        images[("cycles" if idx < n else "lucent", spp, k)] = buf
    return images


# ----------------------------------------------------------------------------- statistics

def c4(k):
    """E[sample standard deviation] / sigma for k Gaussian draws."""
    return math.sqrt(2.0 / (k - 1)) * math.exp(math.lgamma(k / 2) - math.lgamma((k - 1) / 2))


def masks(images, npix, cycles_alpha):
    """Pixels covered (alpha > 0.5) in every render of both renderers, and the disagreements;
    without `cycles_alpha` (an opaque film) Cycles covers what lucent covers."""
    cover = {"lucent": [True] * npix, "cycles": [True] * npix}
    for (who, _, _), img in images.items():
        m = cover[who]
        for p in range(npix):
            m[p] = m[p] and img[4 * p + 3] > 0.5
    if not cycles_alpha:
        cover["cycles"] = list(cover["lucent"])
    common = [p for p in range(npix) if cover["lucent"][p] and cover["cycles"][p]]
    only = {w: sum(1 for p in range(npix) if cover[w][p] and not cover[o][p])
            for w, o in (("lucent", "cycles"), ("cycles", "lucent"))}
    return common, only, sum(cover["lucent"]), sum(cover["cycles"])


def pixel_reference(images, who, mask):
    """Per mask pixel and channel: the spp-weighted mean over all of `who`'s renders."""
    total = [[0.0] * 3 for _ in mask]
    weight = 0
    for (w, spp, _), img in images.items():
        if w != who:
            continue
        weight += spp
        for i, p in enumerate(mask):
            for c in range(3):
                total[i][c] += spp * img[4 * p + c]
    return [[v / weight for v in t] for t in total]


def relative_stderr(renders, ref, mask):
    """Mean over the mask of (channel-mean seed std) / (channel-mean reference), c4-corrected."""
    k, acc = len(renders), 0.0
    for i, p in enumerate(mask):
        sd = 0.0
        for c in range(3):
            v = [img[4 * p + c] for img in renders]
            mu = sum(v) / k
            sd += math.sqrt(sum((x - mu) ** 2 for x in v) / (k - 1))
        acc += (sd / 3) / (sum(ref[i]) / 3)
    return acc / len(mask) / c4(k)


def image_mean(img, pixels):
    return [sum(img[4 * p + c] for p in pixels) / len(pixels) for c in range(3)]


def weighted_mean_and_se(values, weights):
    """Mean of values weighted by spp (their variance ~ 1/spp) and its standard error."""
    wsum = sum(weights)
    mean = sum(w * v for w, v in zip(weights, values)) / wsum
    if len(values) < 2:
        return mean, float("nan")
    var1 = sum(w * (v - mean) ** 2 for w, v in zip(weights, values)) / (len(values) - 1)
    return mean, math.sqrt(var1 / wsum)


def channel_stats(images, who, pixels, spp=None):
    """Per channel (mean, se) of the image mean over `pixels`, over who's renders (at spp)."""
    sel = [(s, img) for (w, s, _), img in images.items() if w == who and spp in (None, s)]
    means = [image_mean(img, pixels) for _, img in sel]
    weights = [s for s, _ in sel]
    return [weighted_mean_and_se([m[c] for m in means], weights) for c in range(3)]


def quotient(a, b):
    return a / b if b else float("nan")


def ratio(num, den):
    """(a / b, its se) from (mean, se) pairs, the errors independent."""
    (a, sa), (b, sb) = num, den
    r = a / b
    return r, abs(r) * math.sqrt((sa / a) ** 2 + (sb / b) ** 2)


def radial_bins(mask, width):
    """The mask's pixels in RADIAL_BINS rings of equal area around its centroid."""
    xy = [(p % width + 0.5, p // width + 0.5) for p in mask]
    cx, cy = sum(x for x, _ in xy) / len(xy), sum(y for _, y in xy) / len(xy)
    d = [math.hypot(x - cx, y - cy) for x, y in xy]
    rmax = max(d) + 1e-9
    bins = [[] for _ in range(RADIAL_BINS)]
    for p, r in zip(mask, d):
        bins[min(RADIAL_BINS - 1, int(RADIAL_BINS * (r / rmax) ** 2))].append(p)
    return [b for b in bins if b]


def radial_ratios(images, mask, width):
    """Per radial bin (centre to rim) and channel: lucent / Cycles and its se, all spp pooled."""
    out = []
    for pixels in radial_bins(mask, width):
        lu, cy = channel_stats(images, "lucent", pixels), channel_stats(images, "cycles", pixels)
        out.append([ratio(lu[c], cy[c]) for c in range(3)])
    return out


def largest_deviation(bins):
    """(ratio - 1, se, bin, channel) of the largest |ratio - 1| over bins and channels."""
    return max(((r - 1, se, b, c) for b, row in enumerate(bins) for c, (r, se) in enumerate(row)),
               key=lambda t: abs(t[0]))


# ----------------------------------------------------------------------------- report

def measure_material(a, material, workdir):
    lucent_runs = run_lucent(a, material, workdir)
    medium = medium_from_stats(lucent_runs[(a.spp[0], 0)]["stats"])
    blender, images = run_cycles(a, medium, lucent_runs, workdir)
    common, only, n_lucent, n_cycles = masks(images, a.size * a.size, a.boundary == "fresnel")
    return {"medium": medium, "lucent": lucent_runs, "blender": blender, "images": images,
            "mask": common, "only": only, "covered": (n_lucent, n_cycles)}


def renderer_row(m, who, spp, a):
    imgs = [m["images"][(who, spp, k)] for k in range(a.seeds)]
    ref = pixel_reference(m["images"], who, m["mask"])
    err = relative_stderr(imgs, ref, m["mask"])
    if who == "lucent":
        secs = [m["lucent"][(spp, k)]["seconds"] for k in range(a.seeds)]
        own = sum(m["lucent"][(spp, k)]["own_stderr"] for k in range(a.seeds)) / a.seeds
    else:
        i0 = [s for s, _, _ in plan(a)].index(spp)
        secs = [t["render"] for t in m["blender"]["cycles"][i0:i0 + a.seeds]]
        own = None
    sec = sum(secs) / len(secs)
    means = channel_stats(m["images"], who, m["mask"], spp)
    return {"seconds": sec, "means": means, "err": err, "own": own, "t1": sec * (err / 0.01) ** 2}


def print_table(results, a):
    print(f"| material | spp | renderer | s / render | mean R | mean G | mean B | rel. stderr "
          f"(seeds) | lucent's own | s to 1 % |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    summary = {}
    for material, m in results.items():
        for spp in a.spp:
            rows = {w: renderer_row(m, w, spp, a) for w in ("lucent", "cycles")}
            for who, name in (("lucent", "lucent"), ("cycles", "Cycles")):
                r = rows[who]
                own = f"{r['own']:.4f}" if r["own"] is not None else ""
                cols = " | ".join(f"{mu:.4f}" for mu, _ in r["means"])
                print(f"| {material} | {spp} | {name} | {r['seconds']:.2f} | {cols} | "
                      f"{r['err']:.4f} | {own} | {r['t1']:.0f} |")
            rat = [ratio(rows["lucent"]["means"][c], rows["cycles"]["means"][c]) for c in range(3)]
            cols = " | ".join(f"{r:.4f} ± {se:.4f}" for r, se in rat)
            t = quotient(rows["lucent"]["t1"], rows["cycles"]["t1"])
            print(f"| {material} | {spp} | lucent / Cycles | | {cols} | | | {t:.2f} |")
            summary[material] = rows
    return summary


def print_summary(results, summary, a):
    for material, m in results.items():
        lu, cy = channel_stats(m["images"], "lucent", m["mask"]), \
            channel_stats(m["images"], "cycles", m["mask"])
        rat = [ratio(lu[c], cy[c]) for c in range(3)]
        bins = radial_ratios(m["images"], m["mask"], a.size)
        dev, se, b, c = largest_deviation(bins)
        rows = summary[material]
        print(f"{material}: lucent / Cycles mean (all spp) R {rat[0][0]:.4f} ± {rat[0][1]:.4f}, "
              f"G {rat[1][0]:.4f} ± {rat[1][1]:.4f}, B {rat[2][0]:.4f} ± {rat[2][1]:.4f}; "
              f"largest radial-bin deviation {100 * dev:+.2f} % ± {100 * se:.2f} % "
              f"(bin {b + 1} of {len(bins)}, channel {'RGB'[c]}); time to 1 % at {a.spp[-1]} spp: "
              f"lucent {rows['lucent']['t1']:.0f} s, Cycles {rows['cycles']['t1']:.0f} s, "
              f"lucent / Cycles {quotient(rows['lucent']['t1'], rows['cycles']['t1']):.2f}")
        print(f"  radial bins, centre to rim, lucent / Cycles R/G/B: " + ", ".join(
            "/".join(f"{r:.3f}" for r, _ in row) for row in bins))


def print_setup(results, a):
    for material, m in results.items():
        b, me = m["blender"], m["medium"]
        renders = sum(b["render_seconds"])
        lwall = sum(r["wall"] for r in m["lucent"].values())
        lframe = sum(r["seconds"] for r in m["lucent"].values())
        print(f"{material} ({me['name']}): sigma_s {me['sigma_s']}, sigma_a {me['sigma_a']} mm^-1, "
              f"g {me['g']}, eta {me['eta']}; mesh {b['vertices']} vertices, {b['triangles']} "
              f"triangles, radius {b['radius_min']:.4f}-{b['radius_max']:.4f} mm, camera at "
              f"{b['camera_distance']:.3f} mm")
        print(f"  mask: {len(m['mask'])} common pixels; lucent covers {m['covered'][0]}, Cycles "
              f"{m['covered'][1]}; only lucent {m['only']['lucent']}, only Cycles "
              f"{m['only']['cycles']}")
        sync = sum(t["synchronization"] for t in b["cycles"])
        traced = sum(t["render"] for t in b["cycles"])
        print(f"  Blender {b['version']}: {b['wall']:.1f} s in all = start-up and EXR dumps "
              f"{b['wall'] - b['build_seconds'] - renders:.1f} s + scene build "
              f"{b['build_seconds']:.2f} s + render calls {renders:.1f} s (Cycles: sync "
              f"{sync:.1f} s, path tracing {traced:.1f} s); lucent: {lwall:.1f} s in all, "
              f"{lframe:.1f} s of it frames")


# ----------------------------------------------------------------------------- main

def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("lucent")
    p.add_argument("--blender", default="blender", help="Blender executable (default: on PATH)")
    p.add_argument("--size", type=int, default=64, help="image width and height")
    p.add_argument("--spp", default="16,64,256", help="sample counts, comma-separated")
    p.add_argument("--seeds", type=int, default=4, help="renders per sample count (>= 2)")
    p.add_argument("--materials", default="marble,skin1")
    p.add_argument("--threads", type=int, default=2, help="CPU threads for each renderer")
    p.add_argument("--size-mm", type=float, default=30.0, help="bounding-box diagonal (mm)")
    p.add_argument("--view", default="0,0.6,1", help="direction from the object to the camera")
    p.add_argument("--g", type=float, default=0.0, help="HG mean cosine (lucent's g knob)")
    p.add_argument("--world-sampling", default="AUTOMATIC", choices=["AUTOMATIC", "NONE"],
                   help="Cycles' world light sampling (its shadow rays cannot pass the glass)")
    p.add_argument("--boundary", default="fresnel", choices=["fresnel", "matched"],
                   help="fresnel: a smooth dielectric at the material's eta; "
                   "matched: eta 1, no surface")
    a = p.parse_args(argv)
    a.spp = sorted(int(s) for s in a.spp.split(","))
    if a.seeds < 2:
        p.error("--seeds must be at least 2: the noise comes from the spread between seeds")
    return a


def find_blender(name):
    """The Blender executable, or None."""
    if os.sep in name:
        return name if os.path.isfile(name) and os.access(name, os.X_OK) else None
    return shutil.which(name)


def main(argv):
    a = parse_args(argv)
    blender = find_blender(a.blender)
    if blender is None:
        print(f"skipped: Blender ('{a.blender}') not found; install it or pass --blender PATH")
        return 0
    a.blender, a.lucent = blender, os.path.abspath(a.lucent)
    t0, load0 = time.perf_counter(), os.getloadavg()[0]
    results = {}
    for material in a.materials.split(","):
        with tempfile.TemporaryDirectory() as workdir:
            results[material] = measure_material(a, material, workdir)
    print(f"lucent pathtrace vs Cycles: {a.size_mm:g} mm sphere, {a.boundary} boundary, "
          f"uniform environment, "
          f"{a.size}x{a.size}, {a.seeds} seeds per sample count, {a.threads} threads; load average "
          f"{load0:.2f} before, {os.getloadavg()[0]:.2f} after")
    print_setup(results, a)
    summary = print_table(results, a)
    print_summary(results, summary, a)
    print(f"bench wall time {time.perf_counter() - t0:.0f} s")
    return 0


if __name__ == "__main__":
    if bpy is not None:
        argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
        blender_main(argv)
    else:
        sys.exit(main(sys.argv[1:]))
