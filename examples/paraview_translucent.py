"""ParaView (pvpython or pvbatch): make a scan translucent, with the scan as the medium.

    pvpython examples/paraview_translucent.py PATH/TO/LucentPlugin.so [OUT.png]
    (headless: xvfb-run -a pvbatch ...; the plugin is built by scripts/paraview-plugin.sh)

The scan is ParaView's built-in Wavelet (a 41^3 volume of values 37..277; read a CT or MRI with
ParaView's readers the same way). The Lucent Translucent Volume filter takes the closed isosurface
at 160 (the volume is padded, so the surface closes where it meets the scan's border) and shades it
with the voxel optical-thickness LUT, the medium given by a transfer function of the scan's values:
clearer where the value is near the threshold, denser where it is high (OUT-filter.png, per-vertex
colours in a plain view). The same surface is then drawn by the Lucent Render View's GPU pass with
the same technique (taulut's GPU twin), as homogeneous marble (OUT.png).
"""
import sys

from paraview.simple import *  # noqa: F401,F403 (ParaView's scripting API)

plugin = sys.argv[1]
out = sys.argv[2] if len(sys.argv) > 2 else "paraview-translucent.png"
LoadPlugin(plugin, remote=False, ns=globals())

scan = Wavelet(WholeExtent=[-20, 20, -20, 20, -20, 20])

# A front light (from the camera's side, a little above) and an exposure that keeps marble white.
light = [0.3, 0.5, 1.0]

# CPU: per-vertex radiosity (arrays Radiosity, TranslucentColor) of the scan's isosurface, its
# medium sigma_a, sigma_s' (mm^-1, R,G,B) interpolated between the transfer function's points.
translucent = LucentTranslucentVolume(Input=scan)
translucent.SelectInputScalars = ["POINTS", "RTData"]
translucent.IsoValue = 160.0
translucent.Transfer = ("points:160/0.002,0.004,0.007/0.5,0.6,0.7;"
                       "260/0.02,0.04,0.07/2.6,3.0,3.6")
translucent.Material = "marble"      # its index of refraction; the coefficients are the scan's
translucent.SizeMm = 40.0            # the isosurface's bounding-box diagonal, in mm
translucent.LightDirection = light
translucent.Exposure = 1.5
translucent.Technique = "taulut"
translucent.TaulutVoxels = 40
# A continuous transfer function is up to 254 media (binned by extinction); a table of path lengths
# per medium between every pair of surface voxels would take gigabytes, so walk them per query.
translucent.TaulutStorage = "march"
translucent.UpdatePipeline()
info = translucent.PointData["Radiosity"]
plain = CreateView("RenderView")
plain.ViewSize = [640, 480]
plain.OrientationAxesVisibility = 0
shown = Show(translucent, plain)
ColorBy(shown, ("POINTS", "TranslucentColor"))
shown.MapScalars = 0                 # the colours are display RGB already
shown.Ambient, shown.Diffuse = 1.0, 0.0
for v in (plain,):
    v.CameraPosition = [0.0, 0.0, 120.0]
    v.CameraFocalPoint = [0.0, 0.0, 0.0]
    v.CameraViewUp = [0.0, 1.0, 0.0]
    v.ResetCamera(False)
Render(plain)
filter_out = out[:-4] + "-filter.png" if out.endswith(".png") else out + "-filter.png"
SaveScreenshot(filter_out, plain, ImageResolution=[640, 480])

# GPU: the view renders every opaque surface as marble, here with taulut's GPU twin.
view = CreateView("LucentRenderView")
view.ViewSize = [640, 480]
view.OrientationAxesVisibility = 0
view.LucentTechnique = "taulut"
view.LucentTaulutVoxels = 40         # the accuracy / time knob (with LucentTaulutMap, ...Storage)
view.LucentMaterial = "marble"
view.LucentSizeMm = 40.0
view.LucentLightDirection = light
view.LucentExposure = 1.5
display = Show(translucent, view)
ColorBy(display, None)
display.Diffuse = 0.0                # the pass supplies the subsurface (diffuse) part
display.Specular = 0.3
view.CameraPosition = [0.0, 0.0, 120.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
view.ResetCamera(False)
Render(view)
SaveScreenshot(out, view, ImageResolution=[640, 480])
print("Lucent Translucent Volume (taulut): Radiosity range R %s; wrote %s and %s"
      % (info.GetRange(0), filter_out, out))
