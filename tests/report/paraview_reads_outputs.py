"""ParaView opens framedyn's ParaView files: its own readers (XDMF 3 and PVD,
from Debian's python3-paraview) read what `framedyn modes` and `framedyn
frame-response` write, and the numbers they read agree with framedyn's CSV
tables, written by another path (text, not HDF5/VTU).

  python3 paraview_reads_outputs.py FRAMEDYN SOURCE_DIR WORK_DIR

Checks: (1) modes.xdmf: one time step per mode (times 1..n), the mesh's
points and cells, and every node's mode_shape at every mode equal to
mode_shapes.csv's translations scaled to a largest nodal translation of 1.
(2) frame_response.xdmf (examples/portal_frame_sway.yaml) and (3) the same
study's frame_response.pvd: as many time steps as frame_nodes_corners.csv has
times, the same times, and the displacement of each corner node at the time
of its largest |UX| equal to the CSV's. (4) A mesh of three-node beams
(B32R, B32) and a two-node beam (B31): the XDMF Mixed topology reads as two
VTK quadratic edges (type 21, midside node third) and one line (VTK_LINE 3 or
VTK_POLY_LINE 4 of two points). (5) The life map in the series: the portal
frame with a fatigue block: frame_response.xdmf's cell fields
fatigue_damage_per_hour and fatigue_life at the last time step equal, element
by element, the largest damage per hour of life_map.csv's rows of that element
and its inverse. Exit status 0 if all hold."""
import csv
import math
import os
import shutil
import subprocess
import sys

from paraview import servermanager as sm
from paraview.simple import PVDReader, Xdmf3ReaderS

framedyn, source, work = sys.argv[1:4]
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def close(a, b, scale):  # CSV text holds 10 significant digits
    return abs(a - b) <= 1e-8 * scale


def run(*args):
    subprocess.run([framedyn, *args, "-q"], check=True, stdout=subprocess.DEVNULL)


def read(reader, time):
    reader.UpdatePipeline(time)
    data = sm.Fetch(reader)
    return data


def point_values(data, name):
    ids = data.GetPointData().GetArray("node_id")
    a = data.GetPointData().GetArray(name)
    return {int(ids.GetValue(i)): a.GetTuple3(i) for i in range(data.GetNumberOfPoints())}


shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)

# (1) Mode shapes.
modes_dir = os.path.join(work, "modes")
run("modes", os.path.join(source, "meshes", "r100_frame.inp"), "-n", "4", "--mode-shapes-csv", "--out", modes_dir)
shapes = {}  # mode -> node -> (ux, uy, uz)
with open(os.path.join(modes_dir, "mode_shapes.csv")) as f:
    for row in csv.DictReader(f):
        shapes.setdefault(int(row["mode"]), {})[int(row["node"])] = tuple(float(v) for k, v in row.items() if k[:2] in ("ux", "uy", "uz"))
reader = Xdmf3ReaderS(FileName=[os.path.join(modes_dir, "modes.xdmf")])
reader.UpdatePipelineInformation()
check(list(reader.TimestepValues) == [1.0, 2.0, 3.0, 4.0], f"modes.xdmf: times {list(reader.TimestepValues)} are the mode numbers 1..4")
for mode, table in sorted(shapes.items()):
    data = read(reader, float(mode))
    check(data.GetNumberOfPoints() == len(table) and data.GetNumberOfCells() == 61,
          f"modes.xdmf mode {mode}: {data.GetNumberOfPoints()} points, {data.GetNumberOfCells()} cells (mesh: {len(table)} nodes, 61 elements)")
    largest = max(math.sqrt(sum(c * c for c in u)) for u in table.values())
    got = point_values(data, "mode_shape")
    worst = max(abs(got[n][d] - table[n][d] / largest) for n in table for d in range(3))
    check(worst <= 1e-8, f"modes.xdmf mode {mode}: mode_shape at all {len(table)} nodes = mode_shapes.csv / largest translation (worst difference {worst:.2e})")

# (2), (3) The frame response, as XDMF and as a PVD series.
study = open(os.path.join(source, "examples", "portal_frame_sway.yaml")).read()
study = study.replace("../meshes/", os.path.join(source, "meshes") + "/").replace("loads: portal_frame_sway_loads.csv",
                                                                                     "loads: " + os.path.join(source, "examples", "portal_frame_sway_loads.csv"))
corners = {}  # node -> [(time, ux, uy, uz)]
for fmt in ("xdmf", "vtu"):
    study_file = os.path.join(work, f"portal_{fmt}.yaml")
    with open(study_file, "w") as f:
        f.write(study.replace("  stations: 3\n", f"  stations: 3\n  paraview: {fmt}\n"))
    out = os.path.join(work, f"portal_{fmt}")
    run("frame-response", study_file, "--out", out)
    if fmt == "xdmf":
        with open(os.path.join(out, "frame_nodes_corners.csv")) as f:
            for row in csv.reader(f):
                if row[0].startswith("time"):
                    continue
                corners.setdefault(int(row[1]), []).append((float(row[0]), float(row[2]), float(row[3]), float(row[4])))
        reader = Xdmf3ReaderS(FileName=[os.path.join(out, "frame_response.xdmf")])
    else:
        reader = PVDReader(FileName=os.path.join(out, "frame_response.pvd"))
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues)
    csv_times = [t for t, *_ in next(iter(corners.values()))]
    check(len(times) == len(csv_times) and all(abs(a - b) <= 1e-9 for a, b in zip(times, csv_times)),
          f"frame_response.{'xdmf' if fmt == 'xdmf' else 'pvd'}: {len(times)} time steps, the {len(csv_times)} times of frame_nodes_corners.csv")
    for node, history in sorted(corners.items()):
        t, ux, uy, uz = max(history, key=lambda h: (abs(h[1]), -h[0]))  # the largest |UX|, the earliest of equals
        data = read(reader, t)
        got = point_values(data, "displacement [m]")[node]
        scale = max(abs(ux), abs(uy), abs(uz))
        check(all(close(g, c, scale) for g, c in zip(got, (ux, uy, uz))),
              f"frame_response ({fmt}) node {node} at t = {t} s: displacement {got} = frame_nodes_corners.csv {(ux, uy, uz)} m")

# (5) The life map as cell fields of the frame's XDMF series (report/fatigue_outputs.h). The portal's
# sway is mild: a low class (FAT5, not a real detail) gives every element on the outputs a life below
# the 1e12-h cap, so that the field's values, not only the cap, are compared.
study_file = os.path.join(work, "portal_life.yaml")
with open(study_file, "w") as f:
    f.write(study.replace("  stations: 3\n", "  stations: 3\n  paraview: xdmf\n  steady_from: 0\n  fatigue: {default: FAT5}\n"))
out = os.path.join(work, "portal_life")
run("frame-response", study_file, "--out", out)
damage = {}  # element -> largest damage per hour over its stations and points
with open(os.path.join(out, "life_map.csv")) as f:
    for row in csv.DictReader(f):
        d = float(row["damage_per_hour [1/h]"])
        damage[int(row["element"])] = max(damage.get(int(row["element"]), 0.0), d)
reader = Xdmf3ReaderS(FileName=[os.path.join(out, "frame_response.xdmf")])
reader.UpdatePipelineInformation()
data = read(reader, list(reader.TimestepValues)[-1])
ids = data.GetCellData().GetArray("element_id")
field = data.GetCellData().GetArray("fatigue_damage_per_hour [1/h]")
life = data.GetCellData().GetArray("fatigue_life [h]")
check(field is not None and life is not None, "frame_response.xdmf: cell fields fatigue_damage_per_hour [1/h] and fatigue_life [h]")
if field is not None and life is not None:
    got = {int(ids.GetValue(i)): (field.GetValue(i), life.GetValue(i)) for i in range(data.GetNumberOfCells())}
    damaged = [e for e, d in damage.items() if d > 0.0]
    worst = max(abs(got[e][0] - damage[e]) / damage[e] for e in damaged) if damaged else 1.0
    # The life is 1 / damage, capped at 1e12 h (no infinity in the files).
    worst_life = max(abs(got[e][1] * damage[e] - 1.0) if damage[e] > 1e-12 else abs(got[e][1] / 1e12 - 1.0) for e in damaged) if damaged else 1.0
    off = all(got[e][0] == 0.0 and got[e][1] == 1e12 for e in got if e not in damage)
    check(len(damaged) > 0 and worst <= 1e-8 and worst_life <= 1e-8 and off,
          f"frame_response.xdmf: fatigue fields of {len(damaged)} damaged elements = life_map.csv's largest damage per hour and its inverse "
          f"(worst relative difference {worst:.2e}, life {worst_life:.2e}); elements off the outputs 0 and 1e12 h")

# (4) Three-node and two-node beams in one mesh.
deck = open(os.path.join(source, "tests", "fuzz", "seeds", "inp", "three_node_beams.inp")).read()
deck = deck.replace("5, 1.5, 0.5, 0\n", "5, 1.5, 0.5, 0\n6, 1.5, 1.0, 0\n")
deck = deck.replace("*MATERIAL", "*ELEMENT, TYPE=B31, ELSET=TIE\n3, 5, 6\n*MATERIAL", 1)
deck = deck.replace("*BOUNDARY", "*BEAM SECTION, ELSET=TIE, MATERIAL=STEEL, SECTION=RECT\n0.1, 0.1\n0, 0, 1\n*BOUNDARY")
with open(os.path.join(work, "mixed.inp"), "w") as f:
    f.write(deck)
run("modes", os.path.join(work, "mixed.inp"), "-n", "2", "--out", os.path.join(work, "mixed"))
reader = Xdmf3ReaderS(FileName=[os.path.join(work, "mixed", "modes.xdmf")])
data = read(reader, 1.0)
cells = [(data.GetCellType(i), [int(data.GetCell(i).GetPointIds().GetId(k)) for k in range(data.GetCell(i).GetNumberOfPoints())])
         for i in range(data.GetNumberOfCells())]
check(data.GetNumberOfPoints() == 6 and cells[0] == (21, [0, 2, 1]) and cells[1] == (21, [2, 4, 3]) and cells[2][0] in (3, 4) and cells[2][1] == [4, 5],
      f"mixed mesh: 6 points and cells {cells} (B32R 1-3 mid 2, B32 3-5 mid 4, B31 5-6)")

sys.exit(1 if failures else 0)
