#!/usr/bin/env python3
"""The isosurface of a scan as lucent extracted it before the iso margin (commit 98d6891): flying edges on the
scan padded one voxel below the threshold, then vtkCleanPolyData welding points within 1e-5 of the box, with
the edge counts of lucent's mesh check, at the whole-number thresholds 10, 20, ..., 100. The measurement
behind docs/real-data.md's "before" table.

    /usr/bin/python3 bench/isosurface_weld_before.py SCAN.nii.gz ...
"""
import sys, collections
from vtkmodules.vtkIOImage import vtkNIFTIImageReader
from vtkmodules.vtkImagingCore import vtkImageConstantPad
from vtkmodules.vtkFiltersCore import vtkFlyingEdges3D, vtkCleanPolyData
def counts(pd):
    uses = collections.Counter(); dirs = collections.Counter()
    polys = pd.GetPolys(); polys.InitTraversal()
    from vtkmodules.vtkCommonCore import vtkIdList
    ids = vtkIdList()
    deg = 0
    while polys.GetNextCell(ids):
        t = [ids.GetId(k) for k in range(ids.GetNumberOfIds())]
        if len(set(t)) < 3: deg += 1; continue
        for k in range(3):
            a, b = t[k], t[(k+1)%3]
            uses[(min(a,b),max(a,b))] += 1
    nm = sum(1 for v in uses.values() if v > 2); bd = sum(1 for v in uses.values() if v == 1)
    return nm, bd, deg
for path in sys.argv[1:]:
    r = vtkNIFTIImageReader(); r.SetFileName(path); r.Update()
    lo, hi = r.GetOutput().GetScalarRange()
    x0,x1,y0,y1,z0,z1 = r.GetOutput().GetExtent()
    pad = vtkImageConstantPad(); pad.SetInputConnection(r.GetOutputPort())
    pad.SetOutputWholeExtent(x0-1,x1+1,y0-1,y1+1,z0-1,z1+1)
    bad = 0
    for iso in [10, 20, 30, 40, 50, 60, 70, 80, 90, 100]:
        pad.SetConstant(min(lo, iso) - 1); pad.Update()
        fe = vtkFlyingEdges3D(); fe.SetInputConnection(pad.GetOutputPort()); fe.SetValue(0, iso)
        fe.ComputeNormalsOff(); fe.ComputeScalarsOff(); fe.ComputeGradientsOff()
        cl = vtkCleanPolyData(); cl.SetInputConnection(fe.GetOutputPort()); cl.SetTolerance(1e-5)
        cl.ConvertPolysToLinesOff(); cl.ConvertLinesToPointsOff(); cl.Update()
        nm, bd, deg = counts(cl.GetOutput())
        bad += (nm > 0 or bd > 0)
        print("%s iso %.1f: %d non-manifold edges, %d boundary edges, %d collapsed faces" % (path.split('/')[-1], iso, nm, bd, deg), flush=True)
    print("%s: %d of the 10 integer thresholds fail the mesh check" % (path.split('/')[-1], bad), flush=True)
