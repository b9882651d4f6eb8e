"""The Python module framedyn (issue 20; docs/user-guide.md, "Python"), run by ctest with
Debian's python3 and pytest (tests/CMakeLists.txt: PythonModule, labels python and fast).

Checks: results equal the framedyn program's for the same input (modes, a static case,
a rainflow count, a study's summary.json); a parameter set from Python equals the same
study edited as YAML; batch gives one row per sample; arrays have the documented shapes and units and agree with closed
forms nobody tuned (a cantilever's bending frequencies and tip deflection, ASTM E1049's
worked example); bad input raises framedyn.Error with framedyn's own message, file, line
and key; a solve releases the GIL (a counter thread runs during it); the example runs.
"""
import csv
import json
import math
import os
import subprocess
import sys
import threading

import numpy as np
import pytest

import framedyn

BINARY = os.environ["FRAMEDYN_BINARY"]
SOURCE_DIR = os.environ["FRAMEDYN_SOURCE_DIR"]

# A steel cantilever along X, clamped at node 1: L = 1 m, a 0.05 m (local 1) x 0.1 m (local 2)
# rectangle, 20 Euler-Bernoulli elements (B33), 1 kN down (-Z) at the tip.
L, A_SIDE, B_SIDE, E, NU, RHO, P = 1.0, 0.05, 0.1, 2.1e11, 0.3, 7850.0, 1000.0
ELEMENTS = 20


def cantilever_text(elements=ELEMENTS, load=True, extra=""):
    nodes = "\n".join("%d, %.17g, 0, 0" % (i + 1, L * i / elements) for i in range(elements + 1))
    elems = "\n".join("%d, %d, %d" % (i + 1, i + 1, i + 2) for i in range(elements))
    text = ("** units: m-N-s\n*NODE, NSET=ALL\n%s\n*NSET, NSET=TIP\n%d\n*ELEMENT, TYPE=B33, ELSET=FRAME\n%s\n"
            "*BEAM SECTION, ELSET=FRAME, MATERIAL=STEEL, SECTION=RECT\n%g, %g\n0, 0, -1\n"
            "*MATERIAL, NAME=STEEL\n*ELASTIC\n%g, %g\n*DENSITY\n%g\n*BOUNDARY\n1, ENCASTRE\n%s"
            % (nodes, elements + 1, elems, A_SIDE, B_SIDE, E, NU, RHO, extra))
    if load:
        text += "*STEP\n*STATIC\n*CLOAD\n%d, 3, %g\n*END STEP\n" % (elements + 1, -P)
    return text


@pytest.fixture
def cantilever(tmp_path):
    path = tmp_path / "cantilever.inp"
    path.write_text(cantilever_text())
    return str(path)


def run_cli(*args, cwd):
    return subprocess.run([BINARY, *args], cwd=cwd, capture_output=True, text=True)


def read_csv(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:]


def close_to_printed(values, printed):
    """framedyn's CSV files print 10 significant digits (core/number_text)."""
    printed = np.asarray(printed, dtype=float)
    scale = np.max(np.abs(printed)) if printed.size else 0.0
    np.testing.assert_allclose(values, printed, rtol=1e-9, atol=1e-9 * scale)


def test_mesh_arrays_have_the_documented_shapes_and_ids(cantilever):
    mesh = framedyn.read_mesh(cantilever)
    assert mesh.nodes.shape == (ELEMENTS + 1, 3)
    assert mesh.elements.shape == (ELEMENTS, 3)
    assert list(mesh.node_ids) == list(range(1, ELEMENTS + 2))
    assert list(mesh.elements[0]) == [1, 2, -1]  # end a, end b, no midside node
    assert mesh.nodes[-1, 0] == pytest.approx(L)
    assert list(mesh.node_sets["TIP"]) == [ELEMENTS + 1]
    assert len(mesh.element_sets["FRAME"]) == ELEMENTS
    assert mesh.units == {"system": "m-N-s", "nodes": "m"}
    assert mesh.dof_count == 6 * (ELEMENTS + 1)


def test_cantilever_bending_frequencies_are_the_closed_form(cantilever):
    # f1 = (beta1 L)^2 / (2 pi) sqrt(E I / (rho A L^4)), beta1 L = 1.875104069 (Euler-Bernoulli),
    # in both bending planes: I = a b^3 / 12 and b a^3 / 12.
    r = framedyn.modes(cantilever, 4)
    area = A_SIDE * B_SIDE
    expected = sorted(1.875104069 ** 2 / (2 * math.pi) * math.sqrt(E * i / (RHO * area * L ** 4))
                      for i in (A_SIDE * B_SIDE ** 3 / 12, B_SIDE * A_SIDE ** 3 / 12))
    np.testing.assert_allclose(r.frequencies_hz[:2], expected, rtol=1e-6)  # 20 cubic elements: 5e-8 measured
    assert r.shapes.shape == (6 * (ELEMENTS + 1), 4)
    assert r.effective_masses.shape == (4, 6)
    assert r.units["frequencies_hz"] == "Hz"
    assert r.units["effective_masses"] == ["kg", "kg", "kg", "kg*m^2", "kg*m^2", "kg*m^2"]
    assert r.certified
    # Mass-normalised shapes: phi^T M phi = 1 makes the effective masses Gamma^2 <= the total mass.
    assert np.all(r.effective_masses[:, :3] <= r.total_mass[:3] * (1 + 1e-12))


def test_modes_equal_the_command_lines(cantilever, tmp_path):
    r = framedyn.modes(cantilever, 6)
    out = tmp_path / "modes_cli"
    run = run_cli("modes", cantilever, "-n", "6", "-o", str(out), "--paraview", "none", "-q", cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    header, rows = read_csv(out / "modes.csv")
    close_to_printed(r.frequencies_hz, [row[1] for row in rows])
    for d in range(6):
        close_to_printed(r.effective_masses[:, d], [row[3 + d] for row in rows])
        close_to_printed(r.effective_mass_fractions[:, d], [row[9 + d] for row in rows])


def test_static_cantilever_tip_deflection_and_reactions(cantilever):
    # Euler-Bernoulli elements are exact for end loads: tip deflection P L^3 / (3 E I2), root moment P L.
    r = framedyn.static(cantilever)
    # The 0.05 m side (a, local 1) lies along n1 = -Z, so the Z load bends the beam about local 2: I = b a^3 / 12.
    i_bending = B_SIDE * A_SIDE ** 3 / 12
    assert r.displacements[-1, 2] == pytest.approx(-P * L ** 3 / (3 * E * i_bending), rel=1e-9)
    assert r.displacements.shape == (ELEMENTS + 1, 6)
    assert list(r.reaction_nodes) == [1]
    assert r.reactions[0, 2] == pytest.approx(P, rel=1e-9)
    assert abs(r.reactions[0, 4]) == pytest.approx(P * L, rel=1e-9)
    assert r.units["displacements"] == ("m", "m", "m", "rad", "rad", "rad")
    assert r.units["section_forces"]["My"] == "N*m"
    assert len(r.section_forces["element"]) == 3 * ELEMENTS


def test_static_equals_the_command_line(cantilever, tmp_path):
    r = framedyn.static(cantilever)
    out = tmp_path / "static_cli"
    run = run_cli("static", cantilever, "-o", str(out), "-q", cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    _, rows = read_csv(out / "displacements.csv")
    assert [int(row[0]) for row in rows] == list(r.node_ids)
    for k in range(6):
        close_to_printed(r.displacements[:, k], [row[1 + k] for row in rows])
    _, rows = read_csv(out / "reactions.csv")
    for k in range(6):
        close_to_printed(r.reactions[:, k], [row[1 + k] for row in rows])
    header, rows = read_csv(out / "section_forces.csv")
    assert [int(row[0]) for row in rows] == list(r.section_forces["element"])
    for name, column in (("N", 6), ("Vz", 8), ("My", 10), ("Mz", 11), ("fiber_stress_max", 12), ("fiber_stress_min", 13)):
        assert header[column].startswith(name + " [")
        close_to_printed(r.section_forces[name], [row[column] for row in rows])


def test_rainflow_counts_astm_e1049_fig6_and_equals_the_command_line(tmp_path):
    history = np.array([-2, 1, -3, 5, -1, 3, -4, 4, -2], dtype=float)
    r = framedyn.rainflow(history, unit="MPa")
    # ASTM E1049-85 Fig. 6(f): range 9: 0.5, 8: 1.0, 6: 0.5, 4: 1.5, 3: 0.5; 4 cycles in all.
    by_range = {}
    for rng, n in zip(r.range, r.count):
        by_range[rng] = by_range.get(rng, 0.0) + n
    assert by_range == {9.0: 0.5, 8.0: 1.0, 6.0: 0.5, 4.0: 1.5, 3.0: 0.5}
    assert r.cycles == 4.0 and r.max_range == 9.0 and r.damage is None
    # With an S-N curve, the damage of the command line (the same stresses x 20 so that they count).
    series = tmp_path / "series.csv"
    series.write_text("stress [MPa]\n" + "\n".join("%g" % (20 * v) for v in history) + "\n")
    d = framedyn.rainflow(20 * history, unit="MPa", sn="FAT90")
    run = run_cli("rainflow", str(series), "--sn", "FAT90", "-o", str(tmp_path / "rf"), "-q", cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    summary = json.loads((tmp_path / "rf" / "summary.json").read_text())
    damage = summary["fatigue"]["damage"]
    assert d.damage == pytest.approx(damage["value"] if isinstance(damage, dict) else damage, rel=1e-9)
    assert d.damage > 0


def test_bad_input_raises_framedyn_error_with_the_command_lines_message(tmp_path):
    bad = tmp_path / "frame.inp"
    bad.write_text(cantilever_text(load=False, extra="*SURFACE, NAME=S\n"))
    with pytest.raises(framedyn.Error) as caught:
        framedyn.read_mesh(str(bad))
    e = caught.value
    assert isinstance(e, RuntimeError)
    assert e.file == str(bad) and e.line > 0 and e.key == "*SURFACE"
    run = run_cli("modes", str(bad), cwd=tmp_path)
    assert run.returncode == 1
    assert run.stderr.strip() == "framedyn: error: " + str(e)
    # A static case without loads: the same message as `framedyn static`, naming *CLOAD.
    unloaded = tmp_path / "unloaded.inp"
    unloaded.write_text(cantilever_text(load=False))
    with pytest.raises(framedyn.Error) as caught:
        framedyn.static(str(unloaded))
    assert caught.value.key == "*CLOAD"
    run = run_cli("static", str(unloaded), cwd=tmp_path)
    assert run.stderr.strip() == "framedyn: error: " + str(caught.value)
    with pytest.raises(ValueError, match="FAT"):
        framedyn.rainflow(np.zeros(3), sn="FAT-nonsense")


def test_a_solve_does_not_block_another_python_thread(tmp_path):
    # The worker is inside the C++ solve while `inside` is set; the main thread counts how often it
    # runs meanwhile, waking every millisecond. The switch interval is made huge so that Python never
    # takes the GIL from a thread by force: the main thread runs only when the worker gives the GIL
    # up itself, so the count is exactly 0 if the solve holds it (checked with the release removed)
    # and the main thread's wake-ups while the solve runs if it does not.
    path = tmp_path / "long.inp"
    path.write_text(cantilever_text(elements=1500, load=False))
    mesh = framedyn.read_mesh(str(path))
    inside, done = threading.Event(), threading.Event()

    def worker():
        inside.set()
        framedyn.modes(mesh, 40)
        inside.clear()
        done.set()

    counted = 0
    interval = sys.getswitchinterval()
    sys.setswitchinterval(1000.0)
    try:
        t = threading.Thread(target=worker)
        t.start()
        while not done.wait(0.001):
            if inside.is_set():
                counted += 1
        t.join()
    finally:
        sys.setswitchinterval(interval)
    print("main-thread wake-ups during the solve:", counted)
    assert counted > 0


# ------------------------------------------------------------------ studies

PLOW_2D = os.path.join(SOURCE_DIR, "examples", "r100_plow_2d.yaml")


def short_copy(tmp_path, name="study.yaml", replace=()):
    """examples/r100_plow_2d.yaml with 0.1 s of plowing (and the given text edits) in tmp_path."""
    text = open(PLOW_2D).read().replace("response: {duration: 0.5,", "response: {duration: 0.1,")
    for old, new in replace:
        assert old in text
        text = text.replace(old, new)
    path = tmp_path / name
    path.write_text(text)
    return str(path)


def test_study_summary_equals_the_command_lines_summary_json(tmp_path):
    path = short_copy(tmp_path)
    r = framedyn.load_study(path).run()
    run = run_cli("run", path, "-o", str(tmp_path / "cli"), "-q", cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    with open(tmp_path / "cli" / "summary.json") as f:
        assert r.summary == json.load(f)
    # The series have the documented shapes and units.
    n = len(r.time)
    assert n > 100 and r.units["time"] == "s"
    assert all(len(v) == n for v in r.coordinates.values())
    assert set(r.coordinates) == set(r.summary["rigid"]["coordinates"])
    assert all(len(v) == n for v in r.frame_loads.values()) and r.frame_loads
    assert r.units[next(iter(r.frame_loads))] == "lbf"
    assert r.rail_stress and r.units[next(iter(r.rail_stress))] == "psi"


def test_a_parameter_set_from_python_equals_the_study_edited_as_yaml(tmp_path):
    study = framedyn.load_study(short_copy(tmp_path))
    study.set("soil.damping", 450)
    study.set("analysis.response.output_interval", 0.001)
    r = study.run()
    edited = tmp_path / "edited"
    edited.mkdir()
    path = short_copy(edited, replace=[("damping: 300,", "damping: 450,"), ("output_interval: 0.0005", "output_interval: 0.001")])
    run = run_cli("run", path, "-o", str(tmp_path / "cli"), "-q", cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    with open(tmp_path / "cli" / "summary.json") as f:
        cli = json.load(f)
    assert r.summary["input"].pop("study") != cli["input"].pop("study")  # the two files' names
    assert r.summary == cli


def test_key_path_errors_name_the_file_line_and_key(tmp_path):
    path = short_copy(tmp_path)
    study = framedyn.load_study(path)
    with pytest.raises(framedyn.Error) as caught:
        study.set("soil.dampng", 1)
    e = caught.value
    assert e.file == path and e.line > 0 and e.key == "soil.dampng"
    with pytest.raises(framedyn.Error) as caught:
        study.set("name", 1)
    assert "a number there" in str(caught.value)


def test_batch_tabulates_one_row_per_sample(tmp_path):
    study = framedyn.load_study(short_copy(tmp_path))
    samples = [{"soil.damping": d} for d in (200, 300)]
    table = framedyn.batch(study, samples)
    assert list(table["soil.damping"]) == [200, 300]
    assert list(table["error"]) == ["", ""]
    single = framedyn.load_study(short_copy(tmp_path))
    single.set("soil.damping", 300)
    response = single.run().summary["rigid"]["response"]
    assert table["rigid.response.peak_cutting_force [lbf]"][1] == response["peak_cutting_force"]["value"]
    assert table["rigid.response.steps"][1] == response["steps"]
    assert table["rigid.response.peak_cutting_force [lbf]"][0] != table["rigid.response.peak_cutting_force [lbf]"][1]


def test_batch_on_two_threads_gives_the_serial_table(tmp_path):
    # The batch engine's threads, each run in its own row: the table of one thread, value for value.
    study = framedyn.load_study(short_copy(tmp_path))
    samples = [{"soil.damping": d} for d in (150, 250, 350, 450)] + [{"soil.damping": -5}]  # the last is refused
    serial, threaded = framedyn.batch(study, samples), framedyn.batch(study, samples, threads=2)
    assert list(serial.keys()) == list(threaded.keys())
    for column in serial.keys():
        a, b = list(serial[column]), list(threaded[column])
        assert [repr(x) for x in a] == [repr(x) for x in b], column
    assert serial["error"][4] != "" and list(serial["error"][:4]) == ["", "", "", ""]
    with pytest.raises(ValueError):
        framedyn.batch(study, samples, threads=0)


BATCH_OUTPUTS = ["rigid.response.peak_cutting_force", "rigid.modes[0].frequency", "rigid.response.steps",
                 "rigid.modes[99].frequency"]  # the last is in no run's summary (the 2-D plow has 6 modes)


def test_batch_outputs_are_the_columns_and_numbers_of_the_command_lines_runs_csv(tmp_path):
    # outputs= is a design file's `outputs:`: the same design run by `framedyn batch` and by
    # framedyn.batch gives the same output columns in the same order, named alike, and the
    # same numbers (runs.csv prints 10 significant digits, core/number_text); a number no run's
    # summary has is an empty cell there and NaN here.
    short_copy(tmp_path)
    damping = (150, 300, 450)
    (tmp_path / "design.yaml").write_text(
        "framedyn_batch: 1\nstudy: study.yaml\nsampling: {method: grid}\nparameters:\n"
        "  - {key: soil.damping, values: [%s]}\noutputs:\n%s" % (", ".join(str(d) for d in damping),
                                                                   "".join("  - %s\n" % o for o in BATCH_OUTPUTS)))
    run = run_cli("batch", "design.yaml", "--out", "out", "-q", cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    header, rows = read_csv(tmp_path / "out" / "runs.csv")
    printed = header[2:2 + len(BATCH_OUTPUTS)]
    assert [h.split(" [")[0] for h in printed] == BATCH_OUTPUTS and header[2 + len(BATCH_OUTPUTS)] == "status"
    table = framedyn.batch(framedyn.load_study(str(tmp_path / "study.yaml")), [{"soil.damping": d} for d in damping],
                           threads=2, outputs=BATCH_OUTPUTS)
    assert list(table.keys()) == ["soil.damping"] + printed + ["error"]
    assert list(table["error"]) == ["", "", ""] and [r[-2] for r in rows] == ["done"] * 3
    for column, name in enumerate(printed):
        cells = [r[2 + column] for r in rows]
        values = list(table[name])
        assert ["" if math.isnan(v) else ("0" if v == 0 else "%.10g" % v) for v in values] == cells, name
    assert all(math.isnan(v) for v in table["rigid.modes[99].frequency"])
    assert len(set(table["rigid.response.peak_cutting_force [lbf]"])) == 3  # the samples differ
    # The numbers are those of each run's whole summary (outputs= only saves work).
    single = framedyn.load_study(str(tmp_path / "study.yaml"))
    single.set("soil.damping", 300)
    summary = single.run().summary["rigid"]
    assert table["rigid.response.peak_cutting_force [lbf]"][1] == summary["response"]["peak_cutting_force"]["value"]
    assert table["rigid.modes[0].frequency [Hz]"][1] == summary["modes"][0]["frequency"]["value"]


def test_the_example_script_runs_and_writes_its_figure(tmp_path):
    out = tmp_path / "offset_plowing.png"
    run = subprocess.run([sys.executable, os.path.join(SOURCE_DIR, "examples", "python", "offset_plowing.py"),
                          "--duration", "0.05", "--out", str(out)], capture_output=True, text=True, cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert "peak" in run.stdout


# docs/errors.md, "Python module": each row's call on examples/r100_plow_2d.yaml saved as study.yaml
# gives the row's message word for word, and the table's IDs are exactly these.
ERROR_CASES = {
    "PY-01": lambda s: s.set("soil.dampng", 450),
    "PY-02": lambda s: s.set("frame_output.points[99]", 1),
    "PY-03": lambda s: s.set("name", 1),
    "PY-04": lambda s: s.set("soil..damping", 1),
    "PY-05": lambda s: s.set("soil.damping", float("nan")),
}


def python_error_rows():
    rows, inside = {}, False
    with open(os.path.join(SOURCE_DIR, "docs", "errors.md")) as f:
        for line in f:
            if line.startswith("## "):
                inside = line.startswith("## Python module")
            elif inside and line.startswith("| PY-"):
                cells = [c.strip() for c in line.strip().strip("|").split(" | ")]
                rows[cells[0]] = cells[-1].strip("`")
    return rows


# The keyword arguments' rows: each call on the CIRC cantilever saved as frame.inp or on study.yaml;
# the error names the argument (key) and no file (the file is not at fault).
ARGUMENT_ERROR_CASES = {
    "PY-06": ("dialect", lambda: framedyn.read_mesh("frame.inp", dialect="nastran")),
    "PY-07": ("dialect", lambda: framedyn.modes(framedyn.read_mesh("frame.inp", dialect="abaqus"), 2, dialect="calculix")),
    "PY-08": ("outputs", lambda: framedyn.batch(framedyn.load_study("study.yaml"), [{"soil.damping": 300}],
                                                outputs=["rigid..response"])),
    "PY-09": ("outputs", lambda: framedyn.batch(framedyn.load_study("study.yaml"), [{"soil.damping": 300}],
                                                outputs=["rigid.response.steps", "rigid.response.steps"])),
}


def test_the_error_table_rows_of_the_python_module(tmp_path, monkeypatch):
    rows = python_error_rows()
    assert sorted(rows) == sorted(list(ERROR_CASES) + list(ARGUMENT_ERROR_CASES))
    monkeypatch.chdir(tmp_path)
    short_copy(tmp_path)
    for error_id, case in ERROR_CASES.items():
        study = framedyn.load_study("study.yaml")
        with pytest.raises(framedyn.Error) as caught:
            case(study)
        assert str(caught.value) == rows[error_id], error_id
        assert caught.value.file == "study.yaml" and caught.value.key
    (tmp_path / "frame.inp").write_text(circ_cantilever_text())
    for error_id, (argument, case) in ARGUMENT_ERROR_CASES.items():
        with pytest.raises(framedyn.Error) as caught:
            case()
        assert str(caught.value) == rows[error_id], error_id
        assert caught.value.file is None and caught.value.key == argument and isinstance(caught.value, RuntimeError)


# ------------------------------------------------------------------ 3-D tire forces (issue 20)

PLOW_3D = os.path.join(SOURCE_DIR, "examples", "r100_plow_offset.yaml")
TIRES_3D = ("front_left_tire", "front_right_tire", "rear_left_tire", "rear_right_tire")


def test_3d_tire_forces_are_series_equal_to_the_command_lines_response_csv(tmp_path):
    text = open(PLOW_3D).read()
    assert "response: {duration: 0.5," in text
    path = tmp_path / "offset.yaml"
    path.write_text(text.replace("response: {duration: 0.5,", "response: {duration: 0.1,"))
    r = framedyn.load_study(str(path)).run()
    run = run_cli("run", str(path), "-o", str(tmp_path / "cli"), "-q", cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    header, rows = read_csv(tmp_path / "cli" / "response.csv")
    for tire in TIRES_3D:
        for direction in ("vertical", "longitudinal", "lateral"):
            name = "%s_%s_force" % (tire, direction)
            assert len(r.recovered[name]) == len(r.time) and r.units[name] == "lbf"
            close_to_printed(r.recovered[name], [row[header.index(name + " [lbf]")] for row in rows])
    # An independent path to the same numbers: the contact summary (coupling/contact_report, the
    # contact's transmitted force) gives each tire's least and largest vertical force, and the
    # response starts from the static equilibrium, whose contact forces the summary states.
    for tire in TIRES_3D:
        vertical = r.recovered[tire + "_vertical_force"]
        contact = r.summary["rigid"]["contacts"][tire]
        assert min(vertical) == pytest.approx(contact["min_force"]["value"], rel=1e-12)
        assert max(vertical) == pytest.approx(contact["max_force"]["value"], rel=1e-12)
        assert vertical[0] == pytest.approx(r.summary["rigid"]["static"]["contact_forces"][tire]["value"], rel=1e-9)


# ------------------------------------------------------------------ dialect= and the reader's warnings (issue 20)

CIRC_RADIUS = 0.03  # the value on the CIRC line: a radius for Abaqus, a diameter for CalculiX 2.20


def circ_cantilever_text(load=True):
    text = cantilever_text(load=load)
    rect = "SECTION=RECT\n%g, %g\n" % (A_SIDE, B_SIDE)
    assert rect in text
    return text.replace(rect, "SECTION=CIRC\n%g\n" % CIRC_RADIUS)


@pytest.fixture
def circ_cantilever(tmp_path):
    path = tmp_path / "circ.inp"
    path.write_text(circ_cantilever_text())
    return str(path)


def circle_bending_frequency(radius):
    # f1 = (beta1 L)^2 / (2 pi) sqrt(E I / (rho A L^4)), I = pi r^4 / 4, A = pi r^2: sqrt(I / A) = r / 2.
    return 1.875104069 ** 2 / (2 * math.pi) * math.sqrt(E / RHO) * (radius / 2) / L ** 2


def test_a_circ_section_read_without_a_dialect_is_a_user_warning_and_listed_on_the_results(circ_cantilever):
    with pytest.warns(UserWarning, match=r"\[circ_radius_or_diameter\].*give dialect= abaqus or calculix") as caught:
        mesh = framedyn.read_mesh(circ_cantilever)
    assert len([w for w in caught if "circ_radius_or_diameter" in str(w.message)]) == 1  # once per read
    assert mesh.dialect is None
    [w] = mesh.warnings
    assert w["code"] == "circ_radius_or_diameter" and circ_cantilever + ":" in w["message"]
    assert w["figures"]["radius_read"] == {"value": CIRC_RADIUS, "unit": "m"}
    assert w["figures"]["radius_calculix"] == {"value": CIRC_RADIUS / 2, "unit": "m"}
    # A path read by modes/static warns the same, and the result carries the list as summary.json does.
    with pytest.warns(UserWarning, match="circ_radius_or_diameter"):
        r = framedyn.modes(circ_cantilever, 2)
    assert [x["code"] for x in r.warnings] == ["circ_radius_or_diameter"]
    with pytest.warns(UserWarning, match="circ_radius_or_diameter"):
        s = framedyn.static(circ_cantilever)
    assert s.warnings == r.warnings
    # Abaqus's reading (the default): the value is the radius; the bending pair at the closed form.
    np.testing.assert_allclose(r.frequencies_hz, [circle_bending_frequency(CIRC_RADIUS)] * 2, rtol=1e-6)


def test_the_dialect_keyword_reads_circ_values_as_the_command_line_does_and_warns_nothing(circ_cantilever, tmp_path):
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # any warning fails the test
        calculix = framedyn.modes(circ_cantilever, 2, dialect="calculix")
        abaqus = framedyn.modes(framedyn.read_mesh(circ_cantilever, dialect="abaqus"), 2, dialect="abaqus")
        static_ccx = framedyn.static(circ_cantilever, dialect="calculix")
        static_abq = framedyn.static(circ_cantilever, dialect="abaqus")
        mesh = framedyn.read_mesh(circ_cantilever, dialect="calculix")
    assert calculix.warnings == [] and abaqus.warnings == [] and static_ccx.warnings == [] and mesh.warnings == []
    assert mesh.dialect == "calculix"
    # CalculiX's reading: the value is the diameter, a circle of radius 0.015 m (closed form, Euler-Bernoulli).
    np.testing.assert_allclose(calculix.frequencies_hz, [circle_bending_frequency(CIRC_RADIUS / 2)] * 2, rtol=1e-6)
    np.testing.assert_allclose(abaqus.frequencies_hz, [circle_bending_frequency(CIRC_RADIUS)] * 2, rtol=1e-6)
    # Tip deflection P L^3 / (3 E I), I = pi r^4 / 4: 16 times larger for the half radius.
    for result, radius in ((static_ccx, CIRC_RADIUS / 2), (static_abq, CIRC_RADIUS)):
        i = math.pi * radius ** 4 / 4
        assert result.displacements[-1, 2] == pytest.approx(-P * L ** 3 / (3 * E * i), rel=1e-9)
    # The same numbers as `framedyn modes --inp-dialect calculix` and `framedyn static --inp-dialect calculix`.
    out = tmp_path / "modes_cli"
    run = run_cli("modes", circ_cantilever, "-n", "2", "--inp-dialect", "calculix", "-o", str(out), "--paraview", "none", "-q",
                  cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    _, rows = read_csv(out / "modes.csv")
    close_to_printed(calculix.frequencies_hz, [row[1] for row in rows])
    assert json.loads((out / "summary.json").read_text())["warnings"] == []
    out = tmp_path / "static_cli"
    run = run_cli("static", circ_cantilever, "--inp-dialect", "calculix", "-o", str(out), "-q", cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    _, rows = read_csv(out / "displacements.csv")
    for k in range(6):
        close_to_printed(static_ccx.displacements[:, k], [row[1 + k] for row in rows])
    # The warning's list equals summary.json's without a dialect.
    out = tmp_path / "plain_cli"
    run = run_cli("static", circ_cantilever, "-o", str(out), "-q", cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    with pytest.warns(UserWarning):
        plain = framedyn.static(circ_cantilever)
    cli_warnings = json.loads((out / "summary.json").read_text())["warnings"]
    assert [w["code"] for w in cli_warnings] == [w["code"] for w in plain.warnings]
    assert cli_warnings[0]["figures"] == plain.warnings[0]["figures"]


# ------------------------------------------------------------------ installing, pandas, the build check (issue 20)

def test_batch_without_pandas_is_a_dict_of_arrays_and_with_pandas_a_dataframe(tmp_path, monkeypatch):
    import types
    study = framedyn.load_study(short_copy(tmp_path))
    samples = [{"soil.damping": d} for d in (200, 300)]
    monkeypatch.setitem(sys.modules, "pandas", None)  # `import pandas` raises ImportError, as without pandas
    table = framedyn.batch(study, samples)
    assert type(table) is dict
    assert list(table)[0] == "soil.damping" and list(table)[-1] == "error"
    for column, values in table.items():
        assert len(values) == len(samples), column
        if column != "error":
            assert isinstance(values, np.ndarray) and values.dtype == np.float64, column
    assert list(table["error"]) == ["", ""]
    # With pandas importable the same dict goes to pandas.DataFrame (a stand-in module records the call).
    calls = []
    fake = types.ModuleType("pandas")
    fake.DataFrame = lambda d: calls.append(d) or "a DataFrame"
    monkeypatch.setitem(sys.modules, "pandas", fake)
    assert framedyn.batch(study, samples) == "a DataFrame"
    assert list(calls[0]) == list(table)
    for column in table:
        if column != "error":
            np.testing.assert_array_equal(calls[0][column], table[column])


@pytest.fixture(scope="module")
def installed(tmp_path_factory):
    """`cmake --install BUILD --prefix STAGE` with DESTDIR=STAGE too, so that an absolute
    FRAMEDYN_PYTHON_INSTALL_DIR (the default: the interpreter's site-packages) is staged as well:
    nothing outside the temporary folder is written. The folder holding the installed package framedyn/."""
    stage = tmp_path_factory.mktemp("install") / "stage"
    env = dict(os.environ, DESTDIR=str(stage))
    run = subprocess.run([os.environ.get("FRAMEDYN_CMAKE", "cmake"), "--install", os.environ["FRAMEDYN_BUILD_DIR"], "--prefix",
                          str(stage / "prefix")], capture_output=True, text=True, env=env)
    assert run.returncode == 0, run.stdout + run.stderr
    found = sorted(p.parent.parent for p in stage.rglob("framedyn/__init__.py"))
    assert len(found) == 1, found
    return found[0]


def import_in_subprocess(path, code, tmp_path):
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PYTHONPATH"] = str(path)
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, cwd=tmp_path)


@pytest.mark.skipif("FRAMEDYN_BUILD_DIR" not in os.environ, reason="needs the build tree (ctest sets FRAMEDYN_BUILD_DIR)")
def test_cmake_install_gives_an_importable_module_with_the_build_trees_results(tmp_path, cantilever, installed):
    site = installed
    code = "import framedyn; r = framedyn.modes(%r, 4); print(framedyn.__file__); print(repr(list(r.frequencies_hz)))" % cantilever
    run = import_in_subprocess(site, code, tmp_path)
    assert run.returncode == 0, run.stderr
    where, frequencies = run.stdout.strip().splitlines()
    assert where.startswith(str(site))  # the installed copy, not the build tree's
    assert eval(frequencies) == list(framedyn.modes(cantilever, 4).frequencies_hz)  # bit for bit


@pytest.mark.skipif("FRAMEDYN_BUILD_DIR" not in os.environ, reason="needs the build tree (ctest sets FRAMEDYN_BUILD_DIR)")
def test_a_copy_built_for_another_processor_says_so_on_import(tmp_path, installed):
    # The installed package with one vector extension this processor lacks added to the build's list
    # (_build.cpu_features): `import framedyn` must refuse with the build's flags and the missing
    # extension named, before the extension (which would stop with SIGILL) is loaded.
    import shutil
    site = tmp_path / "site"
    shutil.copytree(installed / "framedyn", site / "framedyn")  # a copy: the installed one stays as built
    build_py = site / "framedyn" / "_build.py"
    text = build_py.read_text()
    assert "cpu_features = [" in text
    build_py.write_text(text.replace("cpu_features = [", "cpu_features = [\"avx_from_the_future\", "))
    run = import_in_subprocess(site, "import framedyn", tmp_path)
    assert run.returncode != 0
    assert "ImportError: framedyn: this copy was built with" in run.stderr
    assert "this processor lacks avx_from_the_future" in run.stderr
    assert "Rebuild framedyn on this machine" in run.stderr
    run = import_in_subprocess(site, "import sys\ntry:\n    import framedyn\nexcept ImportError:\n    pass\n"
                               "print('framedyn._framedyn' in sys.modules)", tmp_path)
    assert run.stdout.strip() == "False"
