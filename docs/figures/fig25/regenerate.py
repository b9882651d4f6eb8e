#!/usr/bin/python3
"""Figure 25 revisited: why the left and right rails bend alike in offset plowing (docs/validation.md P7).

Runs the shipped offset-plowing pipeline (examples/offset_plowing.yaml) and variants, and splits the
rails' vertical bending moment M_z (theory/coupling.md section 5: M_z is Figure 25's moment) into

  * the parts due to each load group on the frame: the reel (point 24), the front axle pin (25), the
    rear axle (26 with the leveling cylinder 27), the cab mounts (28-31), the plow at its swing pin (19).
    Each group is run alone through `framedyn frame-response` on the pipeline's own frame model (the
    mesh with the run's `frame_parts.inp`): the beam model is linear, so the groups add up to the
    whole (checked, printed); free-free, each group is balanced by the frame model's inertia;
  * the part symmetric and the part antisymmetric about the machine's X-Z plane. The frame model is
    mirror-symmetric (rails at Y = +-15 in, every part on the centreline with mounts in pairs), so at
    every station and time S = (M_zL + M_zR)/2 is the response to the mirror-symmetric half of the
    loads and A = (M_zL - M_zR)/2 the response to the antisymmetric half (lateral forces, roll and yaw
    moments, the leveling cylinder's one-sided force): the rails differ by 2A and by nothing else.

Variants: supports (free-free inertia relief as shipped, `axle_pins`, the thesis's clamped rear end);
with and without the plow's load at point 19; with and without the frame assembly's parts on the frame
model; straight plowing (symmetric plow) against offset; the plow's offset (blade angle beta and the
steering); the thesis's own SAPIV set-up (bare frame, rear end clamped, cab loads left out); and what
would have to be true for Figure 25's difference: the antisymmetric loads scaled until the rails'
peak moments differ by 25 %, and the centreline loads (axle pins, reel) put on the right rail.

Draws fig25_left_right_envelopes.png (this folder): the two rails' envelopes of |M_z| along X.

Usage: docs/figures/fig25/regenerate.py FRAMEDYN [WORKDIR]
  FRAMEDYN  the framedyn program (e.g. build/apps/framedyn)
  WORKDIR   where the results folders go (default: a temporary folder, removed at the end)
Needs the system Python 3 with numpy and matplotlib (Debian: python3-numpy, python3-matplotlib).
FIG25_REUSE=1 reuses the results folders an earlier run left in WORKDIR. Dynamic part only (the static state, computed by every pipeline run, is printed apart).
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
import numpy as np  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
MESH = os.path.join(SOURCE, "meshes", "r100_frame.inp")

GROUPS = [
    ("reel (24)", ["P24_REEL"]),
    ("front axle pin (25)", ["P25_FRONT_AXLE_PIN"]),
    ("rear axle: pin and leveling cylinder (26, 27)", ["P26_REAR_AXLE_PIN", "P27_LEVELING_CYLINDER"]),
    ("cab mounts (28-31)", ["P28_CAB_MOUNT_FL", "P29_CAB_MOUNT_FR", "P30_CAB_MOUNT_RL", "P31_CAB_MOUNT_RR"]),
    ("plow at its swing pin (19)", ["P19_PLOW_SWING_PIN"]),
]
REUSE = os.environ.get("FIG25_REUSE") == "1"  # keep the results folders of an earlier run in WORKDIR (while editing this script)
COMPONENTS = ["FX", "FY", "FZ", "MX", "MY", "MZ"]


# ---------------------------------------------------------------- running framedyn

def run_pipeline(framedyn, work, key, example, replacements=()):
    """`framedyn run` on examples/EXAMPLE with text replacements; returns the results folder."""
    with open(os.path.join(SOURCE, "examples", example)) as f:
        text = f.read()
    text = text.replace("mesh: ../meshes/", "mesh: " + os.path.join(SOURCE, "meshes") + "/")
    text = text.replace("paraview: xdmf", "paraview: none")
    for old, new in replacements:
        if old not in text:
            raise RuntimeError(f"{example}: '{old}' not found")
        text = text.replace(old, new)
    folder = os.path.join(work, key)
    with open(folder + ".yaml", "w") as f:
        f.write(text)
    return run_framedyn(framedyn, "run", folder)


def run_framedyn(framedyn, command, folder):
    """`framedyn COMMAND FOLDER.yaml --out FOLDER` (an earlier results folder removed first, or kept
    with FIG25_REUSE=1 if it is complete); returns the results folder."""
    if os.path.exists(folder):
        if REUSE and os.path.exists(os.path.join(folder, "summary.json")):
            return folder
        shutil.rmtree(folder)
    subprocess.run([framedyn, command, folder + ".yaml", "--out", folder, "-q"], check=True, stdout=subprocess.DEVNULL)
    return folder


def read_loads(path):
    """A load-history file: ({name: [X, Y, Z]}, header, rows as a float array)."""
    points, lines = {}, []
    with open(path) as f:
        for line in f:
            if line.startswith("# point "):
                p = line.split()
                points[p[2]] = [float(v) for v in p[3:6]]
            elif not line.startswith("#"):
                lines.append(line)
    rows = list(csv.reader(lines))
    return points, rows[0], np.array([[float(v) for v in r] for r in rows[1:]])


def write_loads(path, points, header, data):
    with open(path, "w") as f:
        f.write("# framedyn load history, version 1\n# units: in-lbf-s\n")
        for name, p in points.items():
            f.write(f"# point {name} {p[0]:.17g} {p[1]:.17g} {p[2]:.17g}\n")
        f.write(",".join(header) + "\n")
        for r in data:
            f.write(",".join(f"{v:.17g}" for v in r) + "\n")


def keep_points(header, data, names):
    """The load history with every column but those of the points NAMES set to zero."""
    out = data.copy()
    for j, h in enumerate(header):
        if j > 0 and h.split(".")[0] not in names:
            out[:, j] = 0.0
    return out


def frame_response(framedyn, work, key, loads, parts_inp, supports, points=None, damping=0.02):
    """`framedyn frame-response` of the rails, history on; loads = (points, header, data)."""
    folder = os.path.join(work, key)
    pts, header, data = loads
    write_loads(folder + "_loads.csv", points or pts, header, data)
    with open(folder + ".inp", "w") as f:
        f.write(f"*INCLUDE, INPUT={MESH}\n")
        if parts_inp:
            f.write(f"*INCLUDE, INPUT={parts_inp}\n")
    support = "none" if supports == "none" else "clamped\n  support_set: REAR_END"
    with open(folder + ".yaml", "w") as f:
        f.write(f"""framedyn_study: 1
name: fig25 {key}
units: in-lbf-s
model: frame_transient
frame:
  mesh: {folder}.inp
  loads: {folder}_loads.csv
  supports: {support}
  modes: all
  method: mode_acceleration
  damping: {{modal_ratio: {damping}}}
  output_interval: 0.001
  stations: 5
  paraview: none
  outputs:
    left_rail: {{element_set: LEFT_RAIL}}
    right_rail: {{element_set: RIGHT_RAIL}}
""")
    return run_framedyn(framedyn, "frame-response", folder)


# ---------------------------------------------------------------- reading the rails

def node_x():
    xs, in_nodes = {}, False
    with open(MESH) as f:
        for line in f:
            if line.startswith("*"):
                in_nodes = line.upper().startswith("*NODE") and "OUTPUT" not in line.upper()
                continue
            if in_nodes and line.strip() and not line.startswith("**"):
                p = line.split(",")
                xs[int(p[0])] = float(p[1])
    return xs


X_OF_NODE = node_x()


def rail_sections(folder, rail):
    """(X of each station, times, M_z [station, time], M_y [station, time]) from frame_sections_RAIL.csv."""
    d = np.genfromtxt(os.path.join(folder, f"frame_sections_{rail}.csv"), delimiter=",", names=True)
    times = np.unique(d["time_s"])
    first = 1 if rail == "left_rail" else 23          # first node of the rail's first element
    offset = 1 if rail == "left_rail" else 22
    keys = sorted(set(zip(d["element"].astype(int), d["station"].astype(int))))
    n = len(keys)
    order = np.lexsort((d["station"], d["element"], d["time_s"]))
    mz = d["Mz_lbfin"][order].reshape(len(times), n).T
    my = d["My_lbfin"][order].reshape(len(times), n).T
    x_local = d["x_in"][order][:n]
    xs = np.array([X_OF_NODE[e - offset + first] + xl for (e, _), xl in zip(keys, x_local)])
    return xs, times, mz, my


class Rails:
    def __init__(self, folder):
        self.x, self.t, self.mzl, self.myl = rail_sections(folder, "left_rail")
        _, _, self.mzr, self.myr = rail_sections(folder, "right_rail")
        self.s = 0.5 * (self.mzl + self.mzr)
        self.a = 0.5 * (self.mzl - self.mzr)

    def snapshots(self, t_from=0.5):
        """Instants t >= T_FROM: the rails' largest |M_z| over X at that instant, how far apart (median, and
        the share of instants above 25 %): Figure 25 may be one instant rather than an envelope."""
        late = self.t >= t_from - 1e-12
        pl, pr = np.abs(self.mzl[:, late]).max(axis=0), np.abs(self.mzr[:, late]).max(axis=0)
        d = np.abs(pl - pr) / np.maximum(np.maximum(pl, pr), 1e-300)
        return np.median(d), np.mean(d > 0.25)

    def envelopes(self, k=1.0):
        """|M_z| envelopes of the two rails with the antisymmetric part scaled by k."""
        return np.abs(self.s + k * self.a).max(axis=1), np.abs(self.s - k * self.a).max(axis=1)

    def measures(self, k=1.0):
        el, er = self.envelopes(k)
        peak = max(el.max(), er.max())
        big = np.maximum(el, er) >= 0.1 * peak
        station = np.abs(el - er)[big] / np.maximum(el, er)[big]
        return {"peak_left": el.max(), "x_left": self.x[el.argmax()], "peak_right": er.max(), "x_right": self.x[er.argmax()],
                "peak_diff": abs(el.max() - er.max()) / peak, "station_diff": station.max(),
                "x_station_diff": self.x[big][station.argmax()], "max_A": np.abs(self.a).max(), "max_S": np.abs(self.s).max()}


def k_for(rails, target):
    """The smallest factor k (grid 1 to 100, steps of 5 %) on the antisymmetric part for which the rails'
    peak |M_z| differ by TARGET, or None with the largest difference reached on the grid. (Not monotone:
    for k large both rails' peaks are k max|A|, equal again.)"""
    best = (0.0, 1.0)
    k = 1.0
    while k <= 100.0:
        d = rails.measures(k)["peak_diff"]
        if d >= target:
            return k, d
        best = max(best, (d, k))
        k *= 1.05
    return None, best


def resultants(loads, names, about):
    """Peak over time of the six resultant components, about the point ABOUT, of the points NAMES;
    split into the mirror-symmetric (FX, FZ, MY) and antisymmetric (FY, MX, MZ) components."""
    points, header, data = loads
    col = {h.split(" ")[0]: j for j, h in enumerate(header)}
    total = np.zeros((data.shape[0], 6))
    for name in names:
        f = np.stack([data[:, col[f"{name}.{c}"]] for c in COMPONENTS[:3]], axis=1)
        m = np.stack([data[:, col[f"{name}.{c}"]] for c in COMPONENTS[3:]], axis=1)
        r = np.array(points[name]) - np.array(about)
        total[:, :3] += f
        total[:, 3:] += m + np.cross(r, f)
    return np.abs(total).max(axis=0)


# ---------------------------------------------------------------- the study

def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    framedyn = os.path.abspath(sys.argv[1])
    temporary = len(sys.argv) == 2
    work = tempfile.mkdtemp(prefix="fig25_") if temporary else os.path.abspath(sys.argv[2])
    os.makedirs(work, exist_ok=True)
    out = []

    def say(text=""):
        print(text)
        out.append(text)

    # 1. The pipeline runs: supports, straight against offset, the plow's offset.
    runs = {
        "offset, none": ("offset_plowing.yaml", []),
        "offset, axle_pins": ("offset_plowing.yaml", [("supports: none ", "supports: axle_pins ")]),
        "offset, fixed_rear_end": ("offset_plowing.yaml", [("supports: none ", "supports: fixed_rear_end ")]),
        "straight, none": ("straight_plowing.yaml", []),
        "straight, fixed_rear_end": ("straight_plowing.yaml", [("supports: none ", "supports: fixed_rear_end ")]),
        "beta 11, steer 11, none": ("offset_plowing.yaml", [("steering_deg: 22", "steering_deg: 11"), ("blade_angle_deg: 22", "blade_angle_deg: 11")]),
        "beta 22, steer 0, none": ("offset_plowing.yaml", [("steering_deg: 22", "steering_deg: 0")]),
    }
    folders = {}
    for i, (key, (example, repl)) in enumerate(runs.items()):
        folders[key] = run_pipeline(framedyn, work, f"run{i}", example, repl)
    base = folders["offset, none"]
    parts_inp = os.path.join(base, "frame_parts.inp")
    loads = read_loads(os.path.join(base, "frame_loads.csv"))
    with open(os.path.join(base, "summary.json")) as f:
        cg = json.load(f)["frame"]["total_mass"]["cg"]["value"]

    # 2. The rails of each pipeline run through frame-response (history on) with its own loads and
    #    frame model; the pipeline's own envelope is compared with it as a check.
    say("== Rails' vertical bending |M_z| (dynamic part), lbf*in: peaks, where, and how far apart ==")
    say("run | left peak @X | right peak @X | peaks apart | largest station difference @X (stations above 10 % of the peak) | max|A|/max|S| | "
        "the rails' largest |M_z| at one instant, how far apart")
    rails = {}

    def report(key, r):
        m = r.measures()
        median, share = r.snapshots()
        say(f"{key} | {m['peak_left']:,.0f} @{m['x_left']:g} | {m['peak_right']:,.0f} @{m['x_right']:g} | {100 * m['peak_diff']:.2f} % | "
            f"{100 * m['station_diff']:.1f} % @{m['x_station_diff']:g} | {m['max_A'] / m['max_S']:.4f} (max|A| {m['max_A']:.3g}) | "
            f"instants t >= 0.5 s: median {100 * median:.1f} %, {100 * share:.0f} % of them above 25 %")

    for i, (key, folder) in enumerate(folders.items()):
        support = "fixed_rear_end" if "fixed_rear_end" in key else "none"   # axle_pins: the same stresses as none (P4.2)
        fr = frame_response(framedyn, work, f"fr{i}", read_loads(os.path.join(folder, "frame_loads.csv")),
                            os.path.join(folder, "frame_parts.inp"), support)
        rails[key] = Rails(fr)
        env = np.genfromtxt(os.path.join(folder, "frame_rails_envelope.csv"), delimiter=",", names=True)
        pipeline_mz = np.sort(env["max_abs_Mz_lbfin"])
        mine = np.sort(np.concatenate(rails[key].envelopes()))
        check = np.abs(pipeline_mz - mine).max() / mine.max()
        report(key, rails[key])
        if check > 1e-8:
            say(f"   (!) frame-response differs from the pipeline's envelope by {check:.1e}")

    # 3. Load groups, free-free and clamped, on the pipeline's frame model; and without the parts.
    say()
    say("== Offset plowing: each load group alone (mirror-symmetric part S, antisymmetric part A of M_z), lbf*in ==")
    say("resultant components about the frame model's c.g. "
        f"({cg[0]:.2f}, {cg[1]:.0f}, {cg[2]:.2f}) in: peak |FX|, |FZ| [lbf], |MY| [lbf*in] (symmetric); |FY| [lbf], |MX| roll, |MZ| yaw [lbf*in] (antisymmetric)")
    for name, pts in GROUPS:
        r = resultants(loads, pts, cg)
        say(f"  {name}: FX {r[0]:,.0f}  FZ {r[2]:,.0f}  MY {r[4]:,.0f} | FY {r[1]:,.0f}  MX {r[3]:,.0f}  MZ {r[5]:,.0f}")
    r = resultants(loads, [p for _, ps in GROUPS for p in ps], cg)
    say(f"  all: FX {r[0]:,.0f}  FZ {r[2]:,.0f}  MY {r[4]:,.0f} | FY {r[1]:,.0f}  MX {r[3]:,.0f}  MZ {r[5]:,.0f}")
    points, header, data = loads
    for label, parts, support in (("free-free, with the parts", parts_inp, "none"),
                                  ("rear end clamped, with the parts", parts_inp, "fixed_rear_end"),
                                  ("free-free, bare mesh (no parts)", None, "none")):
        say(f"-- {label}: group | max|S| | max|A| | A at the rails' peak station and time")
        whole = Rails(frame_response(framedyn, work, f"whole_{support}_{bool(parts)}", loads, parts, support))
        total_s, total_a = np.zeros_like(whole.s), np.zeros_like(whole.a)
        el, er = whole.envelopes()
        at = (el.argmax(), np.abs(whole.mzl[el.argmax()]).argmax()) if el.max() >= er.max() else (er.argmax(), np.abs(whole.mzr[er.argmax()]).argmax())
        for g, (name, pts) in enumerate(GROUPS):
            part = Rails(frame_response(framedyn, work, f"group{g}_{support}_{bool(parts)}", (points, header, keep_points(header, data, pts)), parts, support))
            total_s += part.s
            total_a += part.a
            say(f"  {name} | {np.abs(part.s).max():,.0f} | {np.abs(part.a).max():,.0f} | S {part.s[at]:,.0f}, A {part.a[at]:,.0f}")
        err = max(np.abs(total_s - whole.s).max(), np.abs(total_a - whole.a).max()) / np.abs(whole.s).max()
        say(f"  all | {np.abs(whole.s).max():,.0f} | {np.abs(whole.a).max():,.0f} | S {whole.s[at]:,.0f}, A {whole.a[at]:,.0f} at X = {whole.x[at[0]]:g} in, t = {whole.t[at[1]]:.3f} s")
        say(f"  superposition: sum of the groups - whole = {err:.1e} of max|S|")
        report(label, whole)
        rails[label] = whole

    # The clamped frame model with the parts has an antisymmetric mode near the shaker (frame_modes.csv of
    # the clamped run: 18.43 Hz, lateral, roll and yaw effective masses only): damped 10 % instead of 2 %.
    damped = Rails(frame_response(framedyn, work, "clamped_damped", loads, parts_inp, "fixed_rear_end", damping=0.10))
    report("rear end clamped, with the parts, modal damping 10 % (2 % elsewhere)", damped)
    with open(os.path.join(folders["offset, fixed_rear_end"], "frame_modes.csv")) as f:
        say("  clamped frame model's modes below 40 Hz: " + ", ".join(f"{float(r[1]):.2f}" for r in list(csv.reader(f))[1:] if float(r[1]) < 40) + " Hz")

    # 4. The thesis's SAPIV set-up: bare frame, rear end clamped, cab loads left out (point 19 goes into the clamp).
    say()
    say("== The thesis's set-up and what would have to be true for Figure 25 ==")
    thesis_pts = ["P24_REEL", "P25_FRONT_AXLE_PIN", "P26_REAR_AXLE_PIN", "P27_LEVELING_CYLINDER"]
    rails["thesis set-up"] = Rails(frame_response(framedyn, work, "thesis", (points, header, keep_points(header, data, thesis_pts)), None, "fixed_rear_end"))
    report("thesis set-up: bare frame clamped, points 24-27", rails["thesis set-up"])
    without19 = [p for _, ps in GROUPS[:4] for p in ps]
    rails["free-free without 19"] = Rails(frame_response(framedyn, work, "no19", (points, header, keep_points(header, data, without19)), parts_inp, "none"))
    report("free-free with the parts, without point 19", rails["free-free without 19"])
    for key in ("offset, none", "offset, fixed_rear_end", "thesis set-up"):
        for target in (0.10, 0.25):
            k, d = k_for(rails[key], target)
            if k is None:
                say(f"  {key}: peaks {100 * target:.0f} % apart not reached for antisymmetric loads x 1 to 100 (largest {100 * d[0]:.1f} % at x {d[1]:.1f})")
            else:
                say(f"  {key}: antisymmetric loads x {k:.2f} for peaks {100 * target:.0f} % apart")
    # The centreline loads (axle pins, reel) on the right rail, as a model with the pins' nodes on a rail would put them.
    new_place = {"P24_REEL": ("RIGHT_RAIL_P24", [-25, 15, 0]), "P25_FRONT_AXLE_PIN": ("RIGHT_RAIL_P25", [0, 15, 0]),
                 "P26_REAR_AXLE_PIN": ("RIGHT_RAIL_P26", [72, 15, 0])}
    moved = dict(new_place.get(name, (name, p)) for name, p in points.items())
    renamed_header = [h.replace("P24_REEL.", "RIGHT_RAIL_P24.").replace("P25_FRONT_AXLE_PIN.", "RIGHT_RAIL_P25.").replace("P26_REAR_AXLE_PIN.", "RIGHT_RAIL_P26.")
                      for h in header]
    for support in ("none", "fixed_rear_end"):
        key = f"pins on the right rail, {support}"
        rails[key] = Rails(frame_response(framedyn, work, f"moved_{support}", (moved, renamed_header, data), parts_inp if support == "none" else None,
                                          support, points=moved))
        report(key + ("" if support == "none" else " (bare frame, as the thesis)"), rails[key])

    # 5. The static state (gravity and the static loads) of the shipped run, from its envelope file.
    env = np.genfromtxt(os.path.join(base, "frame_rails_envelope.csv"), delimiter=",", names=True, dtype=None, encoding=None)
    left = env["rail"] == "left_rail"
    st_l, st_r = env["static_max_abs_normal_stress_psi"][left], env["static_max_abs_normal_stress_psi"][~left]
    say()
    say(f"static state (gravity, parts' weights, static loads at 24-31 and 19): peak |normal stress| left {st_l.max():,.0f} psi, right {st_r.max():,.0f} psi; "
        f"largest station difference {np.abs(st_l - st_r).max():,.0f} psi")

    # 6. The figure.
    panels = [("offset, none", "offset plowing, free-free (shipped)"), ("offset, fixed_rear_end", "offset plowing, rear end clamped"),
              ("thesis set-up", "thesis set-up: bare frame clamped, points 24-27"), ("pins on the right rail, fixed_rear_end", "what-if: pins and reel on the right rail (clamped, bare)"),
              ("straight, none", "straight plowing, free-free"), ("free-free, bare mesh (no parts)", "offset, free-free, bare mesh")]
    fig, axes = plt.subplots(2, 3, figsize=(15, 8), sharex=True)
    for ax, (key, title) in zip(axes.flat, panels):
        r = rails[key]
        el, er = r.envelopes()
        order = np.argsort(r.x, kind="stable")
        ax.plot(r.x[order], el[order] / 1e3, label="left rail (Y = -15 in)", linewidth=1.2)
        ax.plot(r.x[order], er[order] / 1e3, "--", label="right rail (Y = +15 in)", linewidth=1.2)
        ax.plot(r.x[order], np.abs(r.a).max(axis=1)[order] / 1e3, ":", label="antisymmetric part max|A|", linewidth=1.0, color="k")
        m = r.measures()
        ax.set_title(f"{title}\npeaks {100 * m['peak_diff']:.1f} % apart", fontsize=9)
        ax.grid(True, linewidth=0.3)
    for ax in axes[1]:
        ax.set_xlabel("X along the rail [in] (front axle 0, rear axle 72)")
    for ax in axes[:, 0]:
        ax.set_ylabel("envelope of |M_z| [1000 lbf*in]")
    axes[0, 0].legend(fontsize=7)
    fig.suptitle("Figure 25 revisited: vertical bending moment envelopes along the left and right rails (dynamic part)")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "fig25_left_right_envelopes.png"), dpi=90)
    plt.close(fig)
    with open(os.path.join(work, "fig25_numbers.txt"), "w") as f:
        f.write("\n".join(out) + "\n")
    if temporary:
        shutil.rmtree(work)


if __name__ == "__main__":
    main()
