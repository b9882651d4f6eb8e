#!/usr/bin/python3
"""Chapter V of the thesis, old contacts against new: the figure pairs of docs/validation.md P5.

Runs the thesis's Chapter V studies (docs/validation.md P1 in 2-D, P2 in 3-D, and the offset-plowing
pipeline for Figure 25) twice each with the same framedyn:

  thesis  `contacts: linear`: the thesis's bilateral tire and bounce-tire springs, whose static state
          is the thesis's linear statics (the springs may pull);
  new     the shipped studies as they are: contacts that only push (`contacts: unilateral`, the
          default), the response started from the static equilibrium solved on those contacts
          (docs/theory/rigid.md sections 4a and 11).

and draws one PNG per thesis figure with the two runs side by side on the same axes (left: thesis
contacts, right: new), into this folder. It prints the figures P5 quotes: for each figure the largest
difference between the two runs' plotted series, the static contact forces, the contacts' least
forces and lift-off, and the pipeline's peak total rail stress.

Usage: docs/figures/chapter5/regenerate.py FRAMEDYN [WORKDIR]
  FRAMEDYN  the framedyn program (e.g. build/apps/framedyn)
  WORKDIR   where the results folders go (default: a temporary folder, removed at the end)
Needs the system Python 3 with matplotlib (Debian: python3-matplotlib). Dynamic loads throughout
(the frame loads and resultants leave out the static weight distribution) except the pipeline's
total stress (static plus dynamic).
"""
import csv
import json
import os
import shutil
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
EXAMPLES = os.path.join(SOURCE, "examples")

# (run name, study file in examples/)
STUDIES = [
    ("plow_2d", "r100_plow_2d.yaml"),
    ("chain_2d", "r100_chain_2d.yaml"),
    ("plow_straight", "r100_plow_straight.yaml"),
    ("plow_offset", "r100_plow_offset.yaml"),
    ("chain_center", "r100_chain_center.yaml"),
    ("chain_offset", "r100_chain_offset.yaml"),
    ("pipeline", "offset_plowing.yaml"),
]
VARIANTS = ("thesis", "new")
LABELS = {"thesis": "thesis contacts (contacts: linear)", "new": "new contacts (push only, contact-consistent statics)"}


def study_text(name, variant):
    """The study as shipped, or with `contacts: linear` after its attachment; absolute mesh path."""
    with open(os.path.join(EXAMPLES, name)) as f:
        text = f.read()
    text = text.replace("mesh: ../meshes/", "mesh: " + os.path.join(SOURCE, "meshes") + "/")
    if variant == "thesis":
        lines = text.split("\n")
        at = next(i for i, line in enumerate(lines) if line.startswith("attachment:"))
        lines.insert(at + 1, "contacts: linear")
        text = "\n".join(lines)
    if name == "offset_plowing.yaml":
        text = text.replace("paraview: xdmf", "paraview: none")  # the ParaView series is not drawn here
    return text


def run(framedyn, work, key, name, variant):
    folder = os.path.join(work, key + "_" + variant)
    study = folder + ".yaml"
    with open(study, "w") as f:
        f.write(study_text(name, variant))
    if os.path.exists(folder):
        shutil.rmtree(folder)
    subprocess.run([framedyn, "run", study, "--out", folder, "-q"], check=True)
    return folder


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(line for line in f if not line.startswith("#")))
    header, data = rows[0], rows[1:]
    return {h: [float(r[i]) for r in data] for i, h in enumerate(header)}


def summary(folder):
    with open(os.path.join(folder, "summary.json")) as f:
        return json.load(f)


def envelope(table, column):
    """Largest |value| at each X of frame_resultants.csv (one row per time and X)."""
    peak = {}
    for x, v in zip(table["X [in]"], table[column]):
        peak[x] = max(peak.get(x, 0.0), abs(v))
    xs = sorted(peak)
    return xs, [peak[x] for x in xs]


def pair_figure(file, title, xlabel, ylabel, series_of):
    """One PNG: the same series under the two contact laws, side by side. series_of(variant) gives
    [(label, x, y)]. Returns the largest |difference| between the two runs' series (same samples)."""
    fig, axes = plt.subplots(1, 2, figsize=(13, 4.5), sharey=True)
    data = {v: series_of(v) for v in VARIANTS}
    for ax, v in zip(axes, VARIANTS):
        for label, x, y in data[v]:
            ax.plot(x, y, label=label, linewidth=0.8)
        ax.set_title(LABELS[v], fontsize=9)
        ax.set_xlabel(xlabel)
        ax.grid(True, linewidth=0.3)
    axes[0].set_ylabel(ylabel)
    axes[0].legend(fontsize=7)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, file), dpi=90)
    plt.close(fig)
    diff, scale = 0.0, 0.0
    for (_, xa, ya), (_, xb, yb) in zip(data["thesis"], data["new"]):
        if len(xa) == len(xb):
            diff = max([diff] + [abs(a - b) for a, b in zip(ya, yb)])
        else:
            diff = float("nan")
        scale = max([scale] + [abs(a) for a in ya])
    return diff, scale


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    framedyn = os.path.abspath(sys.argv[1])
    work = os.path.abspath(sys.argv[2]) if len(sys.argv) == 3 else tempfile.mkdtemp(prefix="chapter5_")
    os.makedirs(work, exist_ok=True)
    folders = {(k, v): run(framedyn, work, k, n, v) for k, n in STUDIES for v in VARIANTS}
    resp = {kv: read_csv(os.path.join(f, "response.csv")) for kv, f in folders.items()}
    loads = {kv: read_csv(os.path.join(f, "frame_loads.csv")) for kv, f in folders.items()}
    res = {kv: read_csv(os.path.join(f, "frame_resultants.csv")) for kv, f in folders.items() if os.path.exists(os.path.join(f, "frame_resultants.csv"))}
    rows = []

    def history(key, columns, table=None):
        t = (table or resp)
        return lambda v: [(c, t[(key, v)]["time [s]"], t[(key, v)][c]) for c in columns]

    figures = [
        ("fig09_blade_motion_plow.png", "Figure 9/10: blade vertical motion, 2-D plow", "time [s]", "blade z [in]", history("plow_2d", ["blade_z [in]"])),
        ("fig11_plow_force_plow.png", "Figure 11: plow force (signed magnitude), 2-D plow", "time [s]", "force [lbf]",
         history("plow_2d", ["plow_force_signed_magnitude [lbf]"])),
        ("fig12_plow_force_angle_plow.png", "Figure 12: plow force angle, 2-D plow", "time [s]", "angle [deg]", history("plow_2d", ["plow_force_angle_deg"])),
        ("fig17_chain_force.png", "Figure 17: chain force, 2-D chain", "time [s]", "force [lbf]", history("chain_2d", ["chain_force [lbf]"])),
        ("bounce_tire_force_plow.png", "Bounce tire force (compression positive, static part included), 2-D plow", "time [s]", "force [lbf]",
         history("plow_2d", ["bounce_tire_force [lbf]"])),
    ]
    for fig, attachment, key in ((13, "plow", "plow_2d"), (18, "chain", "chain_2d")):
        for k, (column, what, unit) in enumerate([("SRX [lbf]", "axial resultant SRX", "lbf"), ("SRZ [lbf]", "shear resultant SRZ", "lbf"),
                                                  ("SRMY [lbf*in]", "bending resultant SRMY", "lbf*in")]):
            figures.append((f"fig{fig + k}_{column.split()[0].lower()}_envelope_{attachment}.png",
                            f"Figure {fig + k}: {what} along the frame, envelope over the run, 2-D {attachment}", "X [in]", f"peak |{column.split()[0]}| [{unit}]",
                            (lambda key, column: lambda v: [(column, *envelope(res[(key, v)], column))])(key, column)))
    for fig, attachment, key in ((16, "plow", "plow_2d"), (21, "chain", "chain_2d")):
        def stress_at_36(v, key=key):
            t = res[(key, v)]
            rows_36 = [i for i, x in enumerate(t["X [in]"]) if x == 36.0]
            return [("rail top stress at X = 36 in", [t["time [s]"][i] for i in rows_36], [t["rail_top_stress [psi]"][i] for i in rows_36])]
        figures.append((f"fig{fig}_rail_stress_x36_{attachment}.png", f"Figure {fig}: rail top-fiber stress at X = 36 in, 2-D {attachment}", "time [s]",
                        "stress [psi]", stress_at_36))
    for fig, key, group in ((22, "chain_offset", ["P25_FRONT_AXLE_PIN.FX [lbf]", "P25_FRONT_AXLE_PIN.FY [lbf]", "P25_FRONT_AXLE_PIN.FZ [lbf]"]),
                            (23, "chain_offset", ["P26_REAR_AXLE_PIN.FX [lbf]", "P26_REAR_AXLE_PIN.FY [lbf]", "P26_REAR_AXLE_PIN.FZ [lbf]",
                                                  "P27_LEVELING_CYLINDER.FZ [lbf]"]),
                            (24, "plow_offset", ["P26_REAR_AXLE_PIN.FX [lbf]", "P26_REAR_AXLE_PIN.FY [lbf]", "P26_REAR_AXLE_PIN.FZ [lbf]",
                                                 "P27_LEVELING_CYLINDER.FZ [lbf]"])):
        figures.append((f"fig{fig}_load_points_{key}.png", f"Figure {fig}: frame loads at the load points, {key.replace('_', ' ')} (3-D)", "time [s]",
                        "force on the frame [lbf]", history(key, group, loads)))

    def rail_envelope(v):
        """frame_rails_envelope.csv: each rail's largest resultant bending moment at each station, along X."""
        with open(os.path.join(folders[("pipeline", v)], "frame_rails_envelope.csv"), newline="") as f:
            rows = list(csv.DictReader(f))
        out = []
        for rail in sorted({r["rail"] for r in rows}):
            pts = sorted((float(r["X [in]"]), float(r["max_bending_moment [lbf*in]"])) for r in rows if r["rail"] == rail)
            out.append((rail, [p[0] for p in pts], [p[1] for p in pts]))
        return out
    figures.append(("fig25_rail_bending_moment_pipeline.png", "Figure 25: rail bending moment envelope, offset-plowing pipeline (3-D)", "X [in]",
                    "peak bending moment [lbf*in]", rail_envelope))

    print("| figure | largest difference between the runs | largest magnitude (thesis contacts) |")
    print("|---|---|---|")
    for file, title, xl, yl, of in figures:
        diff, scale = pair_figure(file, title, xl, yl, of)
        print(f"| {file} | {diff:.6g} | {scale:.6g} |")

    print("\n| study | contact | static force, thesis / new [lbf] | least force, thesis / new [lbf] | tension fraction (thesis) | lift-off fraction (new) |")
    print("|---|---|---|---|---|---|")
    for key, _ in STUDIES:
        a, b = summary(folders[(key, "thesis")]), summary(folders[(key, "new")])
        for c in a["rigid"]["contacts"]:
            sa = a["rigid"]["static"]["contact_forces"][c]["value"]
            sb = b["rigid"]["static"]["contact_forces"][c]["value"]
            ma, mb = a["rigid"]["contacts"][c]["min_force"]["value"], b["rigid"]["contacts"][c]["min_force"]["value"]
            print(f"| {key} | {c} | {sa:,.0f} / {sb:,.0f} | {ma:,.0f} / {mb:,.0f} | {a['rigid']['contacts'][c]['tension_fraction']:.3f} | "
                  f"{b['rigid']['contacts'][c]['lift_off_fraction']:.3f} |")
    a, b = summary(folders[("pipeline", "thesis")]), summary(folders[("pipeline", "new")])
    for what in ("peak_total_normal_stress", "peak_normal_stress"):
        if what in a.get("frame", {}):
            print(f"\npipeline frame.{what}: thesis {a['frame'][what]['value']:,.0f}, new {b['frame'][what]['value']:,.0f} {a['frame'][what]['unit']}")
    if len(sys.argv) == 2:
        shutil.rmtree(work)


if __name__ == "__main__":
    main()
