"""Python + VTK (Debian python3-vtk9): the lucent filter and render pass from a script.

    PYTHONPATH=build/python xvfb-run -a python3 examples/vtk_translucent.py [OUT.png]

The filter computes per-vertex radiosity on the CPU (printed); the pass renders the same torus,
back-lit, on the GPU with texture-space importance sampling.
"""
import sys

from vtkmodules.vtkFiltersSources import vtkSuperquadricSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkPolyDataMapper, vtkRenderWindow, vtkRenderer,
                                         vtkWindowToImageFilter)
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass
import vtkmodules.vtkInteractionStyle  # noqa: F401 (VTK's object factories)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

from lucent_vtk import vtkLucentFilter, vtkLucentPass

out = sys.argv[1] if len(sys.argv) > 1 else "translucent-python.png"
shape = vtkSuperquadricSource()
shape.ToroidalOn()
shape.SetThickness(0.35)
shape.SetThetaResolution(64)
shape.SetPhiResolution(32)

# CPU: per-vertex radiosity (TSIS technique, 2048 samples) as point arrays.
translucent = vtkLucentFilter()
translucent.SetInputConnection(shape.GetOutputPort())
translucent.SetMaterial("skin1")
translucent.SetSizeMm(30)
translucent.SetTechnique("tsis")
translucent.SetKnob("tsis.samples", "2048")  # a technique's knob by its qualified name
translucent.SetLightDirection(0.0, 0.5, -1.0)
translucent.Update()
radiosity = translucent.GetOutput().GetPointData().GetArray("Radiosity")
print("vtkLucentFilter: %d samples, Radiosity R range %s" % (translucent.GetSampleCount(), radiosity.GetRange(0)))

# GPU: the render pass around VTK's usual render steps.
mapper = vtkPolyDataMapper()
mapper.SetInputConnection(shape.GetOutputPort())
actor = vtkActor()
actor.SetMapper(mapper)
actor.GetProperty().SetDiffuse(0.0)
actor.GetProperty().SetSpecular(0.3)
renderer = vtkRenderer()
renderer.AddActor(actor)
light = vtkLight()
light.SetLightTypeToSceneLight()
light.PositionalOff()
light.SetPosition(0.0, 0.5, -1.0)  # behind the object, as seen from the camera
light.SetFocalPoint(0.0, 0.0, 0.0)
renderer.AddLight(light)
camera = renderer.GetActiveCamera()
camera.SetPosition(0.0, 0.6, 1.0)
camera.SetViewUp(0.0, 1.0, 0.0)
renderer.ResetCamera()
steps = vtkRenderStepsPass()
lucent = vtkLucentPass()
lucent.SetDelegatePass(steps)
lucent.SetMaterial("skin1")
lucent.SetSizeMm(30)
lucent.SetSamples(512)
lucent.SetExposure(16)
renderer.SetPass(lucent)
window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.AddRenderer(renderer)
window.SetSize(320, 320)
window.Render()
grab = vtkWindowToImageFilter()
grab.SetInput(window)
png = vtkPNGWriter()
png.SetFileName(out)
png.SetInputConnection(grab.GetOutputPort())
png.Write()
print("vtkLucentPass: %d translucent actor(s); wrote %s" % (lucent.GetTranslucentActorCount(), out))
