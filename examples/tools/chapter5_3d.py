#!/usr/bin/env python3
"""Chapter V in 3-D: compare runs of `framedyn run` on rigid_3d studies.

Standard library only (and gnuplot for `overlay`). Three commands:

  examples/tools/chapter5_3d.py ratios STRAIGHT OFFSET_PLOW CENTRED OFFSET_CHAIN
      The thesis's qualitative results 6-9 (../shared/docs/thesis-figures.md,
      "Qualitative results") as ratios measured on four results folders of
      examples/r100_plow_straight.yaml, r100_plow_offset.yaml,
      r100_chain_center.yaml, r100_chain_offset.yaml (docs/validation.md P2).

  examples/tools/chapter5_3d.py check DOC [FRAMEDYN]
      Runs the four studies (`framedyn run`, FRAMEDYN default
      build/apps/framedyn) and compares every row of DOC's P2 table of results
      6-9 (docs/validation.md) with the ratios measured: each cell is one
      ratio, a list of them or the range (least-largest) of a group, to two
      decimals. Exit status 1 and the differing rows if they differ (ctest
      ValidationReport.P2RatiosAreWhatTheShippedMachineGives runs this).

  examples/tools/chapter5_3d.py overlay RUN_A RUN_B FIGURE OUT.png
      Draws one figure of two runs in one PNG (e.g. FIGURE =
      rear_pin_and_leveling_cylinder_forces: thesis Figure 24, straight and
      offset plowing), from the per-run CSVs that `framedyn run --figures`
      writes next to its PNGs.

Definitions used by `ratios` (all from frame_loads.csv and response.csv):
  peak(c)  largest |value| of a column over the run (the loads are dynamic
           parts: the static weight distribution is left out);
  pp(q)    peak-to-peak of a coordinate over the run.
Each ratio is given over the whole run and from t = 0.2 s on: the runs start
from rest under the steady soil and chain forces, and some peaks (offset
plowing's rear pin and cylinder) are those of the first instant.
"""
import csv
import os
import re
import subprocess
import sys
import tempfile


LATE = 0.2  # s: the second column of `ratios` leaves out the start from rest


def read_csv(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(line for line in f if not line.startswith("#"))]
    header, data = rows[0], rows[1:]
    cols = {h: [float(r[i]) for r in data] for i, h in enumerate(header)}
    return cols


def column(cols, prefix):
    for h, v in cols.items():
        if h == prefix or h.startswith(prefix + " ["):
            return v
    raise KeyError(f"no column {prefix!r} (have {list(cols)[:8]}...)")


def peak(v):
    return max(abs(x) for x in v)


def pp(v):
    return max(v) - min(v)


class Run:
    """One results folder; every value taken only from time t0 on."""

    def __init__(self, folder, t0=0.0):
        self.folder = folder
        self.loads = self._from(read_csv(os.path.join(folder, "frame_loads.csv")), t0)
        self.resp = self._from(read_csv(os.path.join(folder, "response.csv")), t0)

    @staticmethod
    def _from(cols, t0):
        keep = [i for i, t in enumerate(column(cols, "time")) if t >= t0 - 1e-12]
        return {h: [v[i] for i in keep] for h, v in cols.items()}

    def load(self, point, comp):
        return column(self.loads, f"{point}.{comp}")

    def peak(self, point, comp):
        return peak(self.load(point, comp))

    def rear_net_z(self):
        a, b = self.load("P26_REAR_AXLE_PIN", "FZ"), self.load("P27_LEVELING_CYLINDER", "FZ")
        return [x + y for x, y in zip(a, b)]

    def coord_pp(self, name):
        return pp(column(self.resp, name))


def measure(folders, t0):
    s, po, c, co = (Run(f, t0) for f in folders)
    out = []

    def line(result, what, value, thesis):
        out.append((result, what, value, thesis))

    # 6: in-plane (X-Z) forces and moments, offset over centred / straight.
    for name, a, b in (("chain", co, c), ("plow", po, s)):
        for point, comps in (("P24_REEL", ("FX", "FZ", "MY")), ("P25_FRONT_AXLE_PIN", ("FX", "FZ", "MY")),
                             ("P26_REAR_AXLE_PIN", ("FX", "FZ", "MY")), ("P28_CAB_MOUNT_FL", ("FX", "FZ"))):
            for comp in comps:
                line("6", f"{name} offset/{'centred' if name == 'chain' else 'straight'}: peak {point}.{comp}",
                     a.peak(point, comp) / b.peak(point, comp), "changes little (about 1)")
        line("6", f"{name} offset/{'centred' if name == 'chain' else 'straight'}: peak rear net FZ (P26 + P27)",
             peak(a.rear_net_z()) / peak(b.rear_net_z()), "changes little (about 1)")
    # 7: chain offset, side over fore-aft (in-plane) magnitudes, and the motions.
    for point in ("P25_FRONT_AXLE_PIN", "P26_REAR_AXLE_PIN", "P24_REEL", "P28_CAB_MOUNT_FL"):
        line("7", f"chain offset: peak {point}.FY / peak {point}.FX", co.peak(point, "FY") / co.peak(point, "FX"), "about 1/2")
    for point, out_of_plane in (("P24_REEL", "MX"), ("P24_REEL", "MZ"), ("P25_FRONT_AXLE_PIN", "MZ"), ("P26_REAR_AXLE_PIN", "MZ")):
        line("7", f"chain offset: peak {point}.{out_of_plane} / peak {point}.MY", co.peak(point, out_of_plane) / co.peak(point, "MY"), "about 1/2")
    th = {q: co.coord_pp(q) for q in ("theta_x", "theta_y", "theta_z")}
    line("7", "chain offset: pp roll theta_x / pp pitch theta_y", th["theta_x"] / th["theta_y"], "similar (about 1)")
    line("7", "chain offset: pp pitch theta_y / pp yaw theta_z", th["theta_y"] / th["theta_z"], "5-8")
    # 8: chain offset, where the rear-axle vertical load goes.
    line("8", "chain offset/centred: peak P26.FZ (rear pin)", co.peak("P26_REAR_AXLE_PIN", "FZ") / c.peak("P26_REAR_AXLE_PIN", "FZ"), "well below 1 (greatly reduced)")
    line("8", "chain offset: peak P27.FZ / peak P26.FZ (cylinder over pin)", co.peak("P27_LEVELING_CYLINDER", "FZ") / co.peak("P26_REAR_AXLE_PIN", "FZ"), "well above 1")
    line("8", "chain centred: peak P27.FZ / peak P26.FZ", c.peak("P27_LEVELING_CYLINDER", "FZ") / c.peak("P26_REAR_AXLE_PIN", "FZ"), "(about 0: symmetric)")
    right = sum(co.peak(p, "FZ") for p in ("P29_CAB_MOUNT_FR", "P31_CAB_MOUNT_RR"))
    left = sum(co.peak(p, "FZ") for p in ("P28_CAB_MOUNT_FL", "P30_CAB_MOUNT_RL"))
    line("8", "chain offset: right over left cab mounts, peak FZ", right / left, "right side loaded much more")
    # 9: offset plowing.
    th = {q: po.coord_pp(q) for q in ("theta_x", "theta_y", "theta_z")}
    line("9", "plow offset: pp yaw theta_z / pp pitch theta_y", th["theta_z"] / th["theta_y"], "about 1")
    line("9", "plow offset: pp yaw theta_z / pp roll theta_x", th["theta_z"] / th["theta_x"], "about 1")
    line("9", "plow offset/straight: peak rear net FZ (P26 + P27)", peak(po.rear_net_z()) / peak(s.rear_net_z()), "below 1 (drops)")
    line("9", "plow offset: peak P27.FZ / peak P26.FZ (couple)", po.peak("P27_LEVELING_CYLINDER", "FZ") / po.peak("P26_REAR_AXLE_PIN", "FZ"), "a couple: about 1")
    line("9", "plow offset/straight: peak P26.FZ (rear pin)", po.peak("P26_REAR_AXLE_PIN", "FZ") / s.peak("P26_REAR_AXLE_PIN", "FZ"), "about 7")

    return out


def ratios(*folders):
    whole, late = measure(folders, 0.0), measure(folders, LATE)
    print(f"| result | ratio | whole run | t >= {LATE:g} s | thesis |")
    print("|---|---|---:|---:|---|")
    for (r, what, v, thesis), (_, _, w, _) in zip(whole, late):
        print(f"| {r} | {what} | {v:.3g} | {w:.3g} | {thesis} |")


STUDIES = ("r100_plow_straight.yaml", "r100_plow_offset.yaml", "r100_chain_center.yaml", "r100_chain_offset.yaml")
IN_PLANE = [(p, c) for p, cs in (("P24_REEL", ("FX", "FZ", "MY")), ("P25_FRONT_AXLE_PIN", ("FX", "FZ", "MY")),
                                 ("P26_REAR_AXLE_PIN", ("FX", "FZ", "MY")), ("P28_CAB_MOUNT_FL", ("FX", "FZ"))) for c in cs]


def in_plane(name, leave_out=()):
    against = "centred" if name == "chain" else "straight"
    return [f"{name} offset/{against}: peak {p}.{c}" for p, c in IN_PLANE if (p, c) not in leave_out]


def fy_fx(point):
    return f"chain offset: peak {point}.FY / peak {point}.FX"


def over_my(point, comp):
    return f"chain offset: peak {point}.{comp} / peak {point}.MY"


# docs/validation.md P2's rows (the `ratio` cell) -> how each cell is made from `measure`'s
# lines: ("one", [line]), ("list", [lines]) or ("range", [lines]) (least-largest).
P2_ROWS = {
    "plow offset/straight, peaks of FX, FZ, MY at points 24, 25, 26 (FX, MY) and FX, FZ at mount 28":
        ("range", in_plane("plow", [("P26_REAR_AXLE_PIN", "FZ")])),
    "plow offset/straight, rear pin FZ alone": ("one", ["plow offset/straight: peak P26_REAR_AXLE_PIN.FZ"]),
    "plow offset/straight, rear net vertical (P26 + P27 FZ)": ("one", ["plow offset/straight: peak rear net FZ (P26 + P27)"]),
    "chain offset/centred, the same in-plane peaks (without P26 FZ)": ("range", in_plane("chain", [("P26_REAR_AXLE_PIN", "FZ")])),
    "chain offset/centred, rear net vertical (P26 + P27 FZ)": ("one", ["chain offset/centred: peak rear net FZ (P26 + P27)"]),
    "chain offset, front pin FY / FX": ("one", [fy_fx("P25_FRONT_AXLE_PIN")]),
    "chain offset, cab mount FL FY / FX": ("one", [fy_fx("P28_CAB_MOUNT_FL")]),
    "chain offset, rear pin FY / FX": ("one", [fy_fx("P26_REAR_AXLE_PIN")]),
    "chain offset, reel FY / FX": ("one", [fy_fx("P24_REEL")]),
    "chain offset, out-of-plane over in-plane moment: pins MZ / MY":
        ("list", [over_my("P25_FRONT_AXLE_PIN", "MZ"), over_my("P26_REAR_AXLE_PIN", "MZ")]),
    "chain offset, reel MX / MY, MZ / MY": ("list", [over_my("P24_REEL", "MX"), over_my("P24_REEL", "MZ")]),
    "chain offset, pp roll θx / pp pitch θy": ("one", ["chain offset: pp roll theta_x / pp pitch theta_y"]),
    "chain offset, pp pitch θy / pp yaw θz": ("one", ["chain offset: pp pitch theta_y / pp yaw theta_z"]),
    "chain offset/centred, rear pin FZ": ("one", ["chain offset/centred: peak P26.FZ (rear pin)"]),
    "chain offset, cylinder FZ / rear pin FZ": ("one", ["chain offset: peak P27.FZ / peak P26.FZ (cylinder over pin)"]),
    "chain offset, right over left cab mounts, peak FZ": ("one", ["chain offset: right over left cab mounts, peak FZ"]),
    "plow offset, pp yaw θz / pp pitch θy": ("one", ["plow offset: pp yaw theta_z / pp pitch theta_y"]),
    "plow offset, pp yaw θz / pp roll θx": ("one", ["plow offset: pp yaw theta_z / pp roll theta_x"]),
    "plow offset, cylinder FZ / rear pin FZ": ("one", ["plow offset: peak P27.FZ / peak P26.FZ (couple)"]),
    "plow offset/straight, rear pin FZ": ("one", ["plow offset/straight: peak P26.FZ (rear pin)"]),
}


def cell(kind, values):
    if kind == "range":
        return f"{min(values):.2f}–{max(values):.2f}"
    return ", ".join(f"{v:.2f}" for v in values)


def check(doc, framedyn):
    """P2's table of DOC against the ratios of fresh runs of the four studies; 0 if every row agrees."""
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    with tempfile.TemporaryDirectory(prefix="chapter5_3d_") as work:
        folders = []
        for study in STUDIES:
            folder = os.path.join(work, study[:-5])
            subprocess.run([framedyn, "run", os.path.join(root, "examples", study), "-o", folder, "-q"], check=True,
                           stdout=subprocess.DEVNULL)
            folders.append(folder)
        measured = [{what: v for _, what, v, _ in measure(folders, t0)} for t0 in (0.0, LATE)]
    with open(doc) as f:
        text = f.read()
    start = text.index("\n## P2.")
    section = text[start:text.index("\n## ", start + 1)].split("\n")
    rows = [[c.strip() for c in l.strip().strip("|").split("|")] for l in section if re.match(r"\| [0-9]+ \|", l)]
    bad, seen = [], set()
    for row in rows:
        ratio, documented = row[1], row[2:4]
        if ratio not in P2_ROWS:
            bad.append(f"  a row this check does not know: {ratio!r} (add it to P2_ROWS)")
            continue
        seen.add(ratio)
        kind, lines = P2_ROWS[ratio]
        generated = [cell(kind, [m[line] for line in lines]) for m in measured]
        if generated != documented:
            bad.append(f"  {ratio}: document {' | '.join(documented)}, measured {' | '.join(generated)}")
    bad += [f"  no row {r!r} in the document" for r in P2_ROWS if r not in seen]
    if not bad:
        print(f"P2 table of {doc}: {len(rows)} rows as measured")
        return 0
    print(f"P2 table of {doc} differs from what the shipped machine gives (examples/tools/chapter5_3d.py ratios):")
    print("\n".join(bad))
    return 1


def overlay(run_a, run_b, figure, png):
    a, b = (read_csv(os.path.join(r, figure + ".csv")) for r in (run_a, run_b))
    with tempfile.TemporaryDirectory() as tmp:
        plots = []
        # One colour per load component, solid for RUN_A and dashed for RUN_B.
        for label, cols, tag in ((os.path.basename(os.path.normpath(run_a)), a, "a"), (os.path.basename(os.path.normpath(run_b)), b, "b")):
            names = list(cols)
            data = os.path.join(tmp, tag + ".dat")
            with open(data, "w") as f:
                for i in range(len(cols[names[0]])):
                    f.write(" ".join(repr(cols[n][i]) for n in names) + "\n")
            for k, n in enumerate(names[1:], start=2):
                style = f"lw 1.5 lc {k - 1} dt {1 if tag == 'a' else 2}"
                plots.append(f"'{data}' using 1:{k} with lines {style} title '{label}: {n}'")
        unit = list(a)[1].split("[")[-1].rstrip("]")
        script = (f"set terminal pngcairo size 1400,700\nset output '{png}'\nset key outside right top vertical noenhanced\n"
                  f"set title '{figure}: {run_a} and {run_b}' noenhanced\nset xlabel 'time [s]'\nset ylabel 'force on the frame [{unit}]'\n"
                  f"set grid\nplot " + ", ".join(plots) + "\n")
        subprocess.run(["gnuplot"], input=script, text=True, check=True)


if __name__ == "__main__":
    if len(sys.argv) == 6 and sys.argv[1] == "ratios":
        ratios(*sys.argv[2:])
    elif len(sys.argv) in (3, 4) and sys.argv[1] == "check":
        default = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "build", "apps", "framedyn")
        sys.exit(check(sys.argv[2], sys.argv[3] if len(sys.argv) == 4 else default))
    elif len(sys.argv) == 6 and sys.argv[1] == "overlay":
        overlay(*sys.argv[2:])
    else:
        sys.exit(__doc__)
