"""The Lucent Translucent filter on a surface split across MPI ranks equals the one-process result.

    pvbatch tests/paraview/test_lucent_mpi.py PLUGIN.so OUT.csv                      # one process: the reference
    mpiexec -n 2 pvbatch --mpi tests/paraview/test_lucent_mpi.py PLUGIN.so OUT.csv REFERENCE.csv

The surface is split by RedistributeDataSet; every rank gathers all ranks' triangles and shades its own
vertices (vtk_plugin/Filters/lucentSurfaceGather.h). The distributed run checks that the data really is split
(more than one rank holds points) and that every vertex's radiosity equals the reference's within 1e-4
relative (the sums run in another order). Prints 'lucent paraview mpi: OK', or names the failed check and exits 1.
"""
import csv
import sys

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403 (ParaView's scripting API)

plugin, out_csv = sys.argv[1], sys.argv[2]
reference_csv = sys.argv[3] if len(sys.argv) > 3 else None
LoadPlugin(plugin, remote=False, ns=globals())
ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()


def fail(message):
    print("lucent paraview mpi: FAILED: " + message)
    sys.exit(1)


# The surface comes from a file, as a user's scan does: the one-process run writes it, the distributed run
# reads it (a source generating its own pieces on each rank may compute boundary points differently).
surface_file = (reference_csv or out_csv) + ".vtp"
if reference_csv is None:
    SaveData(surface_file, proxy=Sphere(Radius=10.0, ThetaResolution=48, PhiResolution=24))
split = RedistributeDataSet(Input=XMLPolyDataReader(FileName=[surface_file]))
surface = ExtractSurface(Input=split)
owners = ProcessIdScalars(Input=surface)
translucent = LucentTranslucent(Input=surface)
translucent.Material = "skin1"
translucent.LightDirection = [1.0, 0.3, 0.4]
translucent.Technique = "reference"
translucent.ReferenceFraction = 1.0
translucent.UpdatePipeline()
data = servermanager.Fetch(translucent)
radiosity = data.GetPointData().GetArray("Radiosity")
if radiosity is None:
    fail("the output lacks the Radiosity array")
rows = {}
for i in range(data.GetNumberOfPoints()):
    rows[tuple(round(c, 6) for c in data.GetPoint(i))] = radiosity.GetTuple3(i)
pieces = servermanager.Fetch(owners)
owner = pieces.GetPointData().GetArray("ProcessId")
holders = {int(owner.GetTuple1(i)) for i in range(pieces.GetNumberOfPoints())}
print("%d ranks; points held by ranks %s; %d distinct vertices" % (ranks, sorted(holders), len(rows)))
with open(out_csv, "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["x", "y", "z", "R", "G", "B"])
    for key in sorted(rows):
        w.writerow(list(key) + ["%.9g" % v for v in rows[key]])

if reference_csv:
    if ranks < 2 or len(holders) < 2:
        fail("the surface is not split across ranks (%d ranks, points on %s)" % (ranks, sorted(holders)))
    reference = {}
    with open(reference_csv) as f:
        for r in csv.DictReader(f):
            reference[(float(r["x"]), float(r["y"]), float(r["z"]))] = [float(r[c]) for c in "RGB"]
    if set(reference) != set(rows):
        fail("the distributed output has other vertices than the one-process output")
    worst = 0.0
    for key, b in rows.items():
        ref = reference[key]
        for c in range(3):
            worst = max(worst, abs(b[c] - ref[c]) / max(abs(ref[c]), 1e-3 * max(max(ref), 1e-30)))
    print("largest relative difference to the one-process result: %.3g" % worst)
    if not worst < 1e-4:
        fail("the distributed result differs from the one-process result by %.3g" % worst)
print("lucent paraview mpi: OK")
