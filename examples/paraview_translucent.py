"""ParaView (pvpython or pvbatch): make an isosurface of a scanned-like volume translucent.

    pvpython examples/paraview_translucent.py PATH/TO/LucentPlugin.so [OUT.png]
    (headless: xvfb-run -a pvbatch ...; the plugin is built by scripts/paraview-plugin.sh)

The volume is ParaView's built-in Wavelet; its contour is shown twice: in a Lucent Render View (the GPU
pass: every opaque surface in the view becomes a measured material) and through the Lucent Translucent
filter (CPU, per-vertex colours) in a plain render view.
"""
import sys

from paraview.simple import *  # noqa: F401,F403 (ParaView's scripting API)

plugin = sys.argv[1]
out = sys.argv[2] if len(sys.argv) > 2 else "paraview-translucent.png"
LoadPlugin(plugin, remote=False, ns=globals())

volume = Wavelet(WholeExtent=[-20, 20, -20, 20, -20, 20])
surface = Contour(Input=volume, ContourBy=["POINTS", "RTData"], Isosurfaces=[160.0])
surface = ExtractSurface(Input=surface)

# GPU: the view renders every opaque surface as marble, lit from behind.
view = CreateView("LucentRenderView")
view.ViewSize = [640, 480]
view.OrientationAxesVisibility = 0
view.LucentMaterial = "marble"
view.LucentSizeMm = 40.0             # the isosurface's bounding-box diagonal, in mm
view.LucentLightDirection = [0.2, 0.6, -1.0]
view.LucentSamples = 512             # the accuracy / time knob
view.LucentExposure = 8.0
display = Show(surface, view)
display.Diffuse = 0.0                # the pass supplies the subsurface (diffuse) part
display.Specular = 0.3
view.CameraPosition = [0.0, 0.0, 120.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
view.ResetCamera(False)
Render(view)
SaveScreenshot(out, view, ImageResolution=[640, 480])

# CPU: the filter computes per-vertex radiosity (arrays Radiosity, TranslucentColor) where the data lives.
translucent = LucentTranslucent(Input=surface)
translucent.Material = "marble"
translucent.SizeMm = 40.0
translucent.LightDirection = [0.2, 0.6, -1.0]
translucent.UpdatePipeline()
info = translucent.PointData["Radiosity"]
print("Lucent Translucent: Radiosity range R %s; wrote %s" % (info.GetRange(0), out))
