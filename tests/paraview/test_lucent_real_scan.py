"""A real MRI (the corpus' ch2bet brain, scripts/corpus.sh) in Debian's ParaView 5.11 as its users load it:
ParaView's own NIfTI reader, Lucent Translucent Volume with IsoValue the only property set, at ten thresholds
evenly spaced over the scan's range, then a screenshot of one, which must show the lit
brain (not black, not the background) in a render view showing the filter's own colours.

    xvfb-run -a pvbatch tests/paraview/test_lucent_real_scan.py PLUGIN.so SCAN.nii.gz OUT.png
Prints 'lucent paraview real scan: OK' and exits 0, or names the failed check and exits 1.
"""
import math
import os
import sys

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403 (ParaView's scripting API)
from vtkmodules.vtkIOImage import vtkPNGReader

plugin, scan_path, shot = sys.argv[1], sys.argv[2], sys.argv[3]
LoadPlugin(plugin, remote=False, ns=globals())


def fail(message):
    print("lucent paraview real scan: FAILED: " + message)
    sys.exit(1)


def open_scan(path):
    """ParaView's NIfTI reader (the AnalyzeNIfTIReaderWriter plugin, which a user loads from Tools > Manage
    Plugins); where it does not take the file, VTK's vtkNIFTIImageReader in a trivial producer."""
    try:
        LoadDistributedPlugin("AnalyzeNIfTIReaderWriter", remote=False, ns=globals())
        reader = OpenDataFile(path)
        if reader is not None:
            reader.UpdatePipeline()
            print("read by ParaView's %s" % reader.GetXMLName())
            return reader
    except Exception as e:  # noqa: BLE001 (any failure: fall back to VTK's reader)
        print("ParaView's NIfTI reader: %s" % e)
    from vtkmodules.vtkIOImage import vtkNIFTIImageReader
    vtk_reader = vtkNIFTIImageReader()
    vtk_reader.SetFileName(path)
    vtk_reader.Update()
    producer = TrivialProducer()
    producer.GetClientSideObject().SetOutput(vtk_reader.GetOutput())
    producer.UpdatePipeline()
    print("read by VTK's vtkNIFTIImageReader")
    return producer


reader = open_scan(os.path.abspath(scan_path))
# 1 mm -> 4 mm voxels (the scan's own data, averaged): shading every vertex stays quick in CI.
scan = ResampleToImage(Input=reader)
scan.UseInputBounds = 1
scan.SamplingDimensions = [46, 55, 46]
scan.UpdatePipeline()
low, high = scan.PointData[0].GetRange()
for i in range(10):
    iso = low + (high - low) * i / 10.0
    volume = LucentTranslucentVolume(Input=scan)
    volume.IsoValue = iso
    volume.UpdatePipeline()
    out = servermanager.Fetch(volume)
    radiance = out.GetPointData().GetArray("Radiance")
    if out.GetNumberOfPoints() == 0 or radiance is None:
        fail("no surface or no Radiance at IsoValue %g" % iso)
    values = [radiance.GetComponent(p, c) for p in range(radiance.GetNumberOfTuples()) for c in range(3)]
    if not all(math.isfinite(v) and v >= 0 for v in values) or sum(values) <= 0:
        fail("Radiance not finite, negative or black at IsoValue %g" % iso)
    print("IsoValue %7.2f: %d vertices, %s" % (iso, out.GetNumberOfPoints(),
                                               out.GetFieldData().GetAbstractArray("LucentTechnique").GetValue(0)))
    if i != 3:
        Delete(volume)

view = CreateView("RenderView")
view.ViewSize = [320, 320]
view.OrientationAxesVisibility = 0
display = Show(volume, view)
ColorBy(display, ("POINTS", "TranslucentColor"))
display.MapScalars = 0  # the filter's colours are display RGB already: show them unlit
display.Ambient, display.Diffuse = 1.0, 0.0
view.CameraPosition = [0.0, -1.0, 0.3]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.ResetCamera(False)
Render(view)
SaveScreenshot(shot, view, ImageResolution=[320, 320])
png = vtkPNGReader()
png.SetFileName(shot)
png.Update()
pixels = png.GetOutput().GetPointData().GetScalars()
rgb = [[pixels.GetComponent(p, c) for c in range(3)] for p in range(pixels.GetNumberOfTuples())]
background = rgb[0]  # a corner: the view's background, whatever the palette
brain = [p for p in rgb if sum(abs(a - b) for a, b in zip(p, background)) > 30]
if len(brain) < 0.02 * len(rgb):
    fail("the screenshot %s shows the brain in %d pixels only" % (shot, len(brain)))
brightness = sum(max(p) for p in brain) / len(brain)
if brightness < 40:
    fail("the brain in %s is black (mean brightest channel %.1f)" % (shot, brightness))
print("screenshot %s: the brain covers %d of %d pixels, mean brightest channel %.0f"
      % (shot, len(brain), len(rgb), brightness))
print("lucent paraview real scan: OK")
