"""ParaView (pvpython or pvbatch): make the isosurface of a scan-like volume translucent.

    pvpython examples/paraview_translucent.py PATH/TO/LucentPlugin.so [OUT.png]
    (headless: xvfb-run -a pvbatch ...; the plugin is built by scripts/paraview-plugin.sh)

The volume is ParaView's built-in Wavelet, resampled onto a box 5 voxels larger on every side: outside
the Wavelet's domain the samples are 0, below the threshold, so the isosurface closes and bounds a
volume (contoured as it is, it would be cut open by the domain's faces and light would leak through
the cut). The closed surface is shown twice: in a Lucent Render View (the GPU pass: every opaque
surface in the view becomes a measured material), and through the Lucent Translucent filter with the
voxel optical-thickness LUT (CPU, per-vertex colours) in a plain render view (OUT-filter.png).
"""
import sys

from paraview.simple import *  # noqa: F401,F403 (ParaView's scripting API)

plugin = sys.argv[1]
out = sys.argv[2] if len(sys.argv) > 2 else "paraview-translucent.png"
LoadPlugin(plugin, remote=False, ns=globals())

volume = Wavelet(WholeExtent=[-20, 20, -20, 20, -20, 20])
padded = ResampleToImage(Input=volume)
padded.UseInputBounds = 0
padded.SamplingBounds = [-25, 25, -25, 25, -25, 25]
padded.SamplingDimensions = [51, 51, 51]
surface = Contour(Input=padded, ContourBy=["POINTS", "RTData"], Isosurfaces=[160.0])
surface = ExtractSurface(Input=surface)

# A front light (from the camera's side, a little above) and an exposure that keeps marble white.
light = [0.3, 0.5, 1.0]

# GPU: the view renders every opaque surface as marble.
view = CreateView("LucentRenderView")
view.ViewSize = [640, 480]
view.OrientationAxesVisibility = 0
view.LucentMaterial = "marble"
view.LucentSizeMm = 40.0             # the isosurface's bounding-box diagonal, in mm
view.LucentLightDirection = light
view.LucentSamples = 512             # the accuracy / time knob
view.LucentExposure = 1.5
display = Show(surface, view)
display.Diffuse = 0.0                # the pass supplies the subsurface (diffuse) part
display.Specular = 0.3
view.CameraPosition = [0.0, 0.0, 120.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
view.ResetCamera(False)
Render(view)
SaveScreenshot(out, view, ImageResolution=[640, 480])

# CPU: the filter computes per-vertex radiosity (arrays Radiosity, TranslucentColor) where the data
# lives, here with the voxel optical-thickness LUT.
translucent = LucentTranslucent(Input=surface)
translucent.Material = "marble"
translucent.SizeMm = 40.0
translucent.LightDirection = light
translucent.Exposure = 1.5
translucent.Technique = "taulut"
translucent.TaulutVoxels = 40
translucent.UpdatePipeline()
info = translucent.PointData["Radiosity"]
plain = CreateView("RenderView")
plain.ViewSize = [640, 480]
plain.OrientationAxesVisibility = 0
shown = Show(translucent, plain)
ColorBy(shown, ("POINTS", "TranslucentColor"))
shown.MapScalars = 0                 # the colours are display RGB already
shown.Ambient, shown.Diffuse = 1.0, 0.0
plain.CameraPosition = [0.0, 0.0, 120.0]
plain.CameraFocalPoint = [0.0, 0.0, 0.0]
plain.CameraViewUp = [0.0, 1.0, 0.0]
plain.ResetCamera(False)
Render(plain)
filter_out = out[:-4] + "-filter.png" if out.endswith(".png") else out + "-filter.png"
SaveScreenshot(filter_out, plain, ImageResolution=[640, 480])
print("Lucent Translucent (taulut): Radiosity range R %s; wrote %s and %s"
      % (info.GetRange(0), out, filter_out))
