#!/usr/bin/env python3
"""Side-by-side pictures: PNGs of one height appended left to right, with a 4-pixel gap (VTK's image
filters, so no imaging package is needed). Used by bench/real_data.py for docs/real-data.md.

    /usr/bin/python3 bench/montage.py OUT.png IN1.png IN2.png ...
"""
import sys

from vtkmodules.vtkFiltersCore import vtkImageAppend
from vtkmodules.vtkImagingCore import vtkImageConstantPad, vtkImageExtractComponents
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter


def montage(out, paths):
    append = vtkImageAppend()
    append.SetAppendAxis(0)
    keep = []
    for path in paths:
        reader = vtkPNGReader()
        reader.SetFileName(path)
        reader.Update()
        rgb = vtkImageExtractComponents()  # alpha dropped: every picture as RGB
        rgb.SetInputConnection(reader.GetOutputPort())
        rgb.SetComponents(0, 1, 2)
        rgb.Update()
        x0, x1, y0, y1, _, _ = rgb.GetOutput().GetExtent()
        pad = vtkImageConstantPad()
        pad.SetInputConnection(rgb.GetOutputPort())
        pad.SetOutputWholeExtent(x0, x1 + 4, y0, y1, 0, 0)
        pad.SetConstant(255)
        keep += [reader, rgb, pad]
        append.AddInputConnection(pad.GetOutputPort())
    writer = vtkPNGWriter()
    writer.SetFileName(out)
    writer.SetInputConnection(append.GetOutputPort())
    writer.Write()


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    montage(sys.argv[1], sys.argv[2:])
