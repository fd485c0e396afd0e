"""The lucent plugin in Debian's ParaView 5.11, headless: pvbatch loads it, applies the Lucent Translucent
filter and the Lucent Render View to built-in sources, saves screenshots and checks them.

    xvfb-run -a pvbatch tests/paraview/test_lucent_plugin.py PLUGIN.so OUTDIR [TECHNIQUES.json [ENV.exr]]
With TECHNIQUES.json (`lucent techniques --json`), it first checks that the filter's properties, generated at
build time from the technique descriptions, are exactly the registry's knobs, with the same defaults, ranges
and choices. With ENV.exr, an environment map, it relights a sphere by prt and turns the map. Prints 'lucent paraview plugin: OK' and exits 0, or names the failed check and exits 1.
"""
import json
import math
import os
import sys

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403 (ParaView's scripting API)
from vtkmodules.vtkIOImage import vtkPNGReader

plugin, outdir = sys.argv[1], sys.argv[2]
techniques_json = sys.argv[3] if len(sys.argv) > 3 else None
environment_exr = sys.argv[4] if len(sys.argv) > 4 else None
os.makedirs(outdir, exist_ok=True)
LoadPlugin(plugin, remote=False, ns=globals())


def fail(message):
    print("lucent paraview plugin: FAILED: " + message)
    sys.exit(1)


def png_pixels(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    scalars = image.GetPointData().GetScalars()
    n, c = scalars.GetNumberOfTuples(), scalars.GetNumberOfComponents()
    return [[scalars.GetComponent(i, k) for k in range(3)] for i in range(n)], c


def place_camera(view):
    view.CameraPosition = [0.0, 0.6, 1.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.ResetCamera(False)


# 0. The generated properties against the registry, as the CLI prints it (`lucent techniques --json`).
SCENE_PROPERTIES = {"Input", "Material", "SizeMm", "LightDirection", "LightIrradiance", "EnvironmentFileName",
                    "EnvironmentScale", "Exposure", "Technique",
                    "BudgetMs", "MaxError", "CalibrationDirectory"}  # the last three: Technique auto's


def close(a, b):
    return a == b or abs(a - b) <= 1e-9 * max(abs(a), abs(b))


def check_knob_property(proxy, name, knob, max_bound=None):
    prop = proxy.GetProperty(name)
    if prop is None:
        fail("no property %s for the knob %s" % (name, knob["name"]))
    kind = knob["kind"]
    if kind in ("integer", "real"):
        if not close(float(prop.GetElement(0)), float(knob["default"])):
            fail("%s default %s, the registry says %s" % (name, prop.GetElement(0), knob["default"]))
        domain = prop.GetDomain("range")
        if domain is None or not domain.GetMinimumExists(0):
            fail("%s has no range minimum" % name)
        low = domain.GetMinimum(0)
        if knob["min_exclusive"]:  # an inclusive domain stands just above an exclusive bound
            if not knob["min"] < low <= knob["min"] + max(abs(knob["min"]) * 1e-12, 1e-300):
                fail("%s: minimum %s does not stand just above the registry's exclusive %s" % (name, low, knob["min"]))
        elif not close(low, knob["min"]):
            fail("%s: the range's minimum is not the registry's %s" % (name, knob["min"]))
        high = knob["max"] if max_bound is None else min(x for x in (knob["max"], max_bound) if x is not None)
        if (high is None) != (not domain.GetMaximumExists(0)):
            fail("%s: the range's maximum disagrees with the registry's %s" % (name, high))
        if high is not None and not close(domain.GetMaximum(0), high):
            fail("%s: maximum %s, the registry says %s" % (name, domain.GetMaximum(0), high))
    else:
        if prop.GetElement(0) != knob["default"]:
            fail("%s default '%s', the registry says '%s'" % (name, prop.GetElement(0), knob["default"]))
    if kind == "choice":
        domain = prop.GetDomain("list")
        strings = [domain.GetString(i) for i in range(domain.GetNumberOfStrings())]
        if strings != knob["choices"]:
            fail("%s offers %s, the registry %s" % (name, strings, knob["choices"]))
    return name


def check_generated_properties(path):
    registry = json.load(open(path))["techniques"]
    # The filter holds the header-only techniques and prt, whose adapter it compiles in (Eigen); quadgraph's
    # (TetGen, AGPL) is not linked (vtk_plugin/Common/lucentFilterTechniques.h).
    offered = [t for t in registry if t["capabilities"]["per_vertex"] and not t["capabilities"]["needs_camera"]
               and (not t["required_library"] or t["name"] == "prt")]
    probe = LucentTranslucent(Input=Sphere())  # fresh: every property holds its XML default
    proxy = probe.SMProxy
    domain = proxy.GetProperty("Technique").GetDomain("list")
    listed = [domain.GetString(i) for i in range(domain.GetNumberOfStrings())]
    if listed != [t["name"] for t in offered] + ["auto"]:
        fail("the Technique property offers %s, the registry's per-vertex techniques (and auto) are %s"
             % (listed, [t["name"] for t in offered]))
    truth = next(t["name"] for t in registry if t["capabilities"]["ground_truth"] and not t["capabilities"]["needs_camera"])
    if proxy.GetProperty("Technique").GetElement(0) != truth:
        fail("the Technique property's default is not the registry's ground truth, %s" % truth)
    expected = {check_knob_property(proxy, t["vtk_name"] + k["vtk_name"], k)
                for t in offered for k in t["knobs"] if k["kind"] != "output-file"}
    it = proxy.NewPropertyIterator()
    it.Begin()
    present = set()
    while not it.IsAtEnd():
        present.add(it.GetKey())
        it.Next()
    extra = present - expected - SCENE_PROPERTIES
    if extra or expected - present:
        fail("properties not in the registry: %s; registry knobs without a property: %s"
             % (sorted(extra), sorted(expected - present)))
    # The properties reach the filter's knobs by their qualified names (the XML's initial_string).
    probe.SizeMm = 20.0  # a 20 mm skin sphere: inside tsis's valid range (1.7 mm is not)
    probe.Technique = "tsis"
    probe.TsisSamples = 512
    probe.TsisSampler = "row"
    probe.TsisChartAngle = 30.0
    probe.UpdatePipeline()
    held = str(probe.GetClientSideObject())  # vtkLucentFilter::PrintSelf lists the knobs it holds
    for knob, value in (("tsis.samples", "512"), ("tsis.sampler", "row"), ("tsis.chart-angle", "30")):
        if "%s: %s\n" % (knob, value) not in held:
            fail("the property for %s was set to %s, but the filter holds: %s" % (knob, value, held))
    if probe.PointData["Radiosity"] is None:
        fail("the tsis technique chosen through the properties gave no Radiosity")
    Delete(probe)
    # The view's properties for the knobs its GPU pass shares with its technique (tsis).
    view_proxy = CreateView("LucentRenderView").SMProxy
    twins = 0
    for t in registry:
        if t["capabilities"]["gpu_twin"] == "vtkLucentPass":
            for twin in t["capabilities"]["gpu_twin_knobs"]:
                knob = next(k for k in t["knobs"] if k["name"] == twin["knob"])
                check_knob_property(view_proxy, "Lucent" + t["vtk_name"] + knob["vtk_name"], knob, twin["max"])
                twins += 1
    if twins == 0:
        fail("no technique names vtkLucentPass as its GPU twin")
    print("generated properties: %d knobs of %d techniques and %d of the view, equal to the registry"
          % (len(expected), len(offered), twins))


if techniques_json:
    check_generated_properties(techniques_json)

# 1. The filter (runs where the data is, on pvserver too): per-vertex Radiosity, finite, lit side bright.
sphere = Sphere(Radius=0.5, ThetaResolution=64, PhiResolution=32)
translucent = LucentTranslucent(Input=sphere)
translucent.Material = "skin1"
translucent.SizeMm = 20.0
translucent.LightDirection = [1.0, 0.0, 0.0]
translucent.UpdatePipeline()
data = servermanager.Fetch(translucent)
radiosity = data.GetPointData().GetArray("Radiosity")
if radiosity is None:
    fail("the filter's output has no Radiosity array")
lit, unlit = [], []
for i in range(data.GetNumberOfPoints()):
    b = radiosity.GetTuple3(i)
    if not all(math.isfinite(v) and v >= 0 for v in b):
        fail("Radiosity is not finite and non-negative at point %d: %s" % (i, b))
    x = data.GetPoint(i)[0]
    (lit if x > 0.4 else unlit if x < -0.4 else []).append(b[0])
if not (lit and unlit and min(lit) > 10 * max(unlit)):
    fail("the lit side (+x) is not far brighter than the far side")
# 1b. prt under an environment map: turning the map (PrtRotate, a frame-phase knob) keeps the precomputation.
def printed(proxy, name):
    """A value vtkLucentFilter::PrintSelf lists (the plugin's classes are not wrapped for Python)."""
    for line in str(proxy.GetClientSideObject()).splitlines():
        if line.strip().startswith(name + ": "):
            return line.strip()[len(name) + 2:]
    fail("the filter does not print %s" % name)


def radiance_of(proxy):
    array = servermanager.Fetch(proxy).GetPointData().GetArray("Radiance")
    if array is None:
        fail("prt under %s gave no Radiance" % environment_exr)
    return [array.GetTuple3(i) for i in range(array.GetNumberOfTuples())]


if environment_exr:
    relit = LucentTranslucent(Input=sphere)
    relit.SizeMm = 20.0
    relit.Technique = "prt"
    relit.EnvironmentFileName = environment_exr
    relit.PrtCube = 8
    relit.PrtMaxSamples = 1500
    relit.PrtSingle = "off"
    relit.UpdatePipeline()
    if printed(relit, "PrepareReused") != "0":
        fail("prt's first run claims to have reused a precomputation")
    before, prepare_s = radiance_of(relit), float(printed(relit, "PrepareSeconds"))
    if not all(math.isfinite(v) and v >= 0 for b in before for v in b) or max(b[0] for b in before) <= 0:
        fail("prt under the environment map is not finite, non-negative and lit somewhere")
    relit.PrtRotate = 90.0
    relit.UpdatePipeline()
    if printed(relit, "PrepareReused") != "1":
        fail("turning the environment (PrtRotate) ran prt's precomputation again")
    after = radiance_of(relit)
    if max(abs(a[0] - b[0]) for a, b in zip(after, before)) <= 1e-6 * max(b[0] for b in before):
        fail("turning the environment by 90 degrees left the radiance unchanged")
    print("prt under %s: precompute %.2f s, a turn of the map %.3f s (the frame only)"
          % (os.path.basename(environment_exr), prepare_s, float(printed(relit, "FrameSeconds"))))
    Delete(relit)
# 1a. Technique auto: the planner's choice, one of the offered techniques, with its reasons in field data.
planned = LucentTranslucent(Input=sphere)
planned.SizeMm = 20.0
planned.LightDirection = [1.0, 0.0, 0.0]
planned.Technique = "auto"
planned.BudgetMs = 2000.0
planned.UpdatePipeline()
chosen_data = servermanager.Fetch(planned)
chosen = chosen_data.GetFieldData().GetAbstractArray("LucentTechnique")
plan = chosen_data.GetFieldData().GetAbstractArray("LucentPlan")
if chosen is None or plan is None or plan.GetNumberOfValues() < 3:
    fail("Technique auto left no LucentTechnique or LucentPlan in the output's field data")
chosen_name = chosen.GetValue(0).split(":")[0]
if chosen_name == "auto" or chosen_data.GetPointData().GetArray("Radiance") is None:
    fail("Technique auto shaded nothing, or reports no technique: %s" % chosen.GetValue(0))
print("auto: %s; plan of %d lines" % (chosen.GetValue(0), plan.GetNumberOfValues()))
# 1b. The volume filter: a scan's isosurface with the scan as the medium. A transfer function of one
# point is marble's coefficients everywhere, so it must shade as the plain filter shades the same
# isosurface as marble (both by taulut).
scan = Wavelet(WholeExtent=[-10, 10, -10, 10, -10, 10])
volume = LucentTranslucentVolume(Input=scan)
volume.SelectInputScalars = ["POINTS", "RTData"]
volume.IsoValue = 150.0
volume.Material = "marble"
volume.Transfer = "points:0/0.0021,0.0041,0.0071/2.19,2.62,3.00"
volume.SizeMm = 20.0
volume.Technique = "taulut"
volume.TaulutVoxels = 16
volume.UpdatePipeline()
scanned = servermanager.Fetch(volume)
plain = LucentTranslucent(Input=ExtractSurface(Input=volume))
plain.Material = "marble"
plain.SizeMm = 20.0
plain.Technique = "taulut"
plain.TaulutVoxels = 16
plain.UpdatePipeline()
homogeneous = servermanager.Fetch(plain)
a, b = scanned.GetPointData().GetArray("Radiosity"), homogeneous.GetPointData().GetArray("Radiosity")
if a is None or b is None or a.GetNumberOfTuples() != b.GetNumberOfTuples() or a.GetNumberOfTuples() == 0:
    fail("the volume filter gave no Radiosity, or not on the plain filter's vertices")
worst = max(abs(a.GetComponent(i, c) - b.GetComponent(i, c)) / max(abs(b.GetComponent(i, c)), 1e-30)
            for i in range(a.GetNumberOfTuples()) for c in range(3) if b.GetComponent(i, c) > 1e-6)
if not worst < 1e-4:
    fail("the volume filter with marble's coefficients differs from marble by %g" % worst)
print("volume filter: %d vertices, largest relative difference to homogeneous marble %.2g"
      % (a.GetNumberOfTuples(), worst))

view = CreateView("RenderView")
view.ViewSize = [512, 512]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.05, 0.05, 0.07]
shape = Superquadric(Toroidal=1, Thickness=0.35, ThetaResolution=96, PhiResolution=48)
glow = LucentTranslucent(Input=shape)
glow.SizeMm = 30.0
glow.LightDirection = [0.0, 0.5, -1.0]
glow.Exposure = 5.0
shown = Show(glow, view)
ColorBy(shown, ("POINTS", "TranslucentColor"))
shown.MapScalars = 0  # the colours are display values already: show them unlit
shown.Ambient = 1.0
shown.Diffuse = 0.0
place_camera(view)
Render(view)
SaveScreenshot(os.path.join(outdir, "paraview-filter.png"), view, ImageResolution=[512, 512])

# 2. The Lucent Render View (the GPU pass inside ParaView's view), back-lit torus.
lucent_view = CreateView("LucentRenderView")
lucent_view.ViewSize = [512, 512]
lucent_view.OrientationAxesVisibility = 0
lucent_view.UseColorPaletteForBackground = 0
view.Background = [0.05, 0.05, 0.07]
lucent_view.LucentMaterial = "skin1"
lucent_view.LucentSizeMm = 30.0
lucent_view.LucentLightDirection = [0.0, 0.5, -1.0]  # from behind, as seen by the camera
lucent_view.LucentExposure = 16.0
lucent_view.LucentTsisSamples = 1024
surface = Show(shape, lucent_view)
surface.Diffuse = 0.0  # the pass supplies the diffuse (subsurface) part
surface.Specular = 0.4
place_camera(lucent_view)
Render(lucent_view)
with_pass = os.path.join(outdir, "paraview-lucent-view.png")
SaveScreenshot(with_pass, lucent_view, ImageResolution=[512, 512])
lucent_view.LucentEnabled = 0
Render(lucent_view)
without_pass = os.path.join(outdir, "paraview-plain-view.png")
SaveScreenshot(without_pass, lucent_view, ImageResolution=[512, 512])

a, _ = png_pixels(with_pass)
b, _ = png_pixels(without_pass)
background = a[0]
object_pixels = [i for i in range(len(a)) if max(abs(a[i][k] - background[k]) for k in range(3)) > 8]
if len(object_pixels) < 5000:
    fail("the Lucent Render View shows almost nothing (%d object pixels)" % len(object_pixels))
mean_with = sum(sum(a[i]) for i in object_pixels) / len(object_pixels)
mean_without = sum(sum(b[i]) for i in object_pixels) / len(object_pixels)
red = sum(a[i][0] for i in object_pixels) / len(object_pixels)
blue = sum(a[i][2] for i in object_pixels) / len(object_pixels)
print("object pixels %d; mean byte sum with the pass %.1f, without %.1f; red %.1f blue %.1f"
      % (len(object_pixels), mean_with, mean_without, red, blue))
if not mean_with > 2 * mean_without + 30:
    fail("the pass does not light the back-lit object")
if not red > 1.5 * blue:
    fail("the translucent colour is not skin-like (red should travel furthest)")
# 2b. LucentTechnique auto: the planner's choice per frame lights the same back-lit torus.
lucent_view.LucentEnabled = 1
lucent_view.LucentTechnique = "auto"
Render(lucent_view)
planned_shot = os.path.join(outdir, "paraview-lucent-view-auto.png")
SaveScreenshot(planned_shot, lucent_view, ImageResolution=[512, 512])
c, _ = png_pixels(planned_shot)
mean_auto = sum(sum(c[i]) for i in object_pixels) / len(object_pixels)
print("LucentTechnique auto: mean byte sum %.1f" % mean_auto)
if not mean_auto > 2 * mean_without + 30:
    fail("the view with LucentTechnique auto does not light the back-lit object")
print("lucent paraview plugin: OK")
