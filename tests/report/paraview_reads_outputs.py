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
and its inverse. (6) `framedyn transient`'s transient.xdmf: the times of
displacement_history.csv, and at every time each node's displacement and each
element's twelve end forces (N_end1 ... Mz_end2) equal to
displacement_history.csv and section_force_history.csv. Exit status 0 if all
hold."""
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

# (6) framedyn transient's series: a tip-mass cantilever under a step load (*MODAL DYNAMIC).
deck = """** units: m-N-s
*NODE, NSET=ALL
1, 0, 0, 0
2, 0.5, 0, 0
3, 1.0, 0, 0
4, 1.5, 0, 0
5, 2.0, 0, 0
*ELEMENT, TYPE=B33, ELSET=BEAM
1, 1, 2
2, 2, 3
3, 3, 4
4, 4, 5
*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=RECT
0.05, 0.1
0, 1, 0
*MATERIAL, NAME=STEEL
*ELASTIC
2.1e11, 0.3
*DENSITY
7850
*ELEMENT, TYPE=MASS, ELSET=TIPMASS
100, 5
*MASS, ELSET=TIPMASS
100
*BOUNDARY
1, 1, 6
*AMPLITUDE, NAME=STEP
0, 1, 1, 1
*STEP
*FREQUENCY
4
*END STEP
*STEP
*MODAL DYNAMIC
0.002, 0.1
*CLOAD, AMPLITUDE=STEP
5, 3, 1000.
5, 2, 300.
*END STEP
"""
with open(os.path.join(work, "tip_mass.inp"), "w") as f:
    f.write(deck)
out = os.path.join(work, "transient")
run("transient", os.path.join(work, "tip_mass.inp"), "--out", out)
nodes = {}  # time -> node -> (ux, uy, uz)
with open(os.path.join(out, "displacement_history.csv")) as f:
    for row in csv.reader(f):
        if not row[0].startswith("time"):
            nodes.setdefault(float(row[0]), {})[int(row[1])] = tuple(float(v) for v in row[2:5])
ends = {}  # time -> element -> [N, Vy, Vz, T, My, Mz of end 1, then of end 2]
with open(os.path.join(out, "section_force_history.csv")) as f:
    for row in csv.reader(f):
        if not row[0].startswith("time"):
            ends.setdefault(float(row[0]), {}).setdefault(int(row[1]), [0.0] * 12)[6 * (int(row[2]) - 1):6 * int(row[2])] = [float(v) for v in row[3:9]]
reader = Xdmf3ReaderS(FileName=[os.path.join(out, "transient.xdmf")])
reader.UpdatePipelineInformation()
times = list(reader.TimestepValues)
check(len(times) == len(nodes) and all(abs(a - b) <= 1e-9 for a, b in zip(times, sorted(nodes))),
      f"transient.xdmf: {len(times)} time steps, the {len(nodes)} times of displacement_history.csv")
names = [f"{c}_end{e} [{'N' if c in ('N', 'Vy', 'Vz') else 'N*m'}]" for e in (1, 2) for c in ("N", "Vy", "Vz", "T", "My", "Mz")]
u_scale = max(abs(v) for table in nodes.values() for u in table.values() for v in u)
f_scale = max(abs(v) for table in ends.values() for e in table.values() for v in e)
worst_u = worst_f = 0.0
for t in times:
    data = read(reader, t)
    got = point_values(data, "displacement [m]")
    worst_u = max([worst_u] + [abs(got[n][d] - u[d]) for n, u in nodes[min(nodes, key=lambda x: abs(x - t))].items() for d in range(3)])
    ids = data.GetCellData().GetArray("element_id")
    arrays = [data.GetCellData().GetArray(n) for n in names]
    if any(a is None for a in arrays):
        check(False, f"transient.xdmf: cell fields {names}")
        break
    table = ends[min(ends, key=lambda x: abs(x - t))]
    for i in range(data.GetNumberOfCells()):
        e = int(ids.GetValue(i))
        worst_f = max([worst_f] + [abs(arrays[k].GetValue(i) - table[e][k]) for k in range(12)])
check(worst_u <= 1e-8 * u_scale and worst_f <= 1e-8 * f_scale,
      f"transient.xdmf: displacement at every node and time = displacement_history.csv (worst {worst_u:.2e} m of {u_scale:.3e}), "
      f"the twelve end forces of every element = section_force_history.csv (worst {worst_f:.2e} of {f_scale:.3e})")

sys.exit(1 if failures else 0)
