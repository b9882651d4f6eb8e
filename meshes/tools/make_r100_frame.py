#!/usr/bin/env python3
"""Generate meshes/r100_frame.inp, the R-100-like trencher frame beam model.

Usage (from the repository root):

    python3 meshes/tools/make_r100_frame.py            # writes meshes/r100_frame.inp
    python3 meshes/tools/make_r100_frame.py --check    # only checks and prints the summary

The geometry, the sections and every assumption behind them are described in
docs/meshes/r100_frame.md; the tables in that page are the summary this script
prints. This script is a convenience for editing the mesh and is not used by the
build: the .inp file in meshes/ is the data. Plain Python 3, no third-party
modules.

Axes (framedyn's vehicle axes, as in the thesis's 3-D model): X along the rails,
positive rearward, X = 0 at the front axle; Y to the right; Z up; origin on the
rail tubes' neutral axis height, on the machine centreline. Units: inch,
pound-force, second (mass in lbf*s^2/in).
"""

import math
import sys
from pathlib import Path

# --------------------------------------------------------------------------
# Data
# --------------------------------------------------------------------------

RAIL_Y = 15.0  # rail centrelines at Y = -15 (left) and +15 (right), in

# Rail stations, front to rear, in. Station k (1-based) gives left-rail node k
# and right-rail node k + len(STATIONS).
STATIONS = [-25.0, -20.0, -15.0, -10.0, -5.0, 0.0, 5.0, 10.0, 15.0, 20.0, 26.0,
            31.0, 36.0, 41.0, 46.0, 52.0, 57.0, 62.0, 68.0, 72.0, 76.0, 80.0]

# Cross members, front to rear: (X, section group, has a centreline node, what it carries)
CROSS_MEMBERS = [
    (-25.0, "HEAVY_CROSS_MEMBERS", True, "front end plate; reel carrier attachment"),
    (-15.0, "LIGHT_CROSS_MEMBERS", True, "front bulkhead (reel carrier braces, front ballast)"),
    (0.0, "HEAVY_CROSS_MEMBERS", True, "front axle pivot cross member"),
    (10.0, "LIGHT_CROSS_MEMBERS", False, "bulkhead behind the front axle"),
    (20.0, "LIGHT_CROSS_MEMBERS", False, "front cab-mount cross member"),
    (31.0, "LIGHT_CROSS_MEMBERS", True, "front engine/pump mount cross member"),
    (41.0, "LIGHT_CROSS_MEMBERS", True, "rear engine/pump mount cross member"),
    (52.0, "LIGHT_CROSS_MEMBERS", False, "rear cab-mount cross member"),
    (62.0, "LIGHT_CROSS_MEMBERS", False, "bulkhead ahead of the rear axle"),
    (72.0, "HEAVY_CROSS_MEMBERS", True, "rear axle pivot cross member"),
    (76.0, "LIGHT_CROSS_MEMBERS", False, "rear hitch box bulkhead"),
    (80.0, "HEAVY_CROSS_MEMBERS", True, "rear end plate; plow/trencher hitch"),
]

# Sections: name -> (a along local 1 = vertical, b along local 2 = horizontal,
# wall thickness), in. n1 = (0, 0, 1) for every section.
SECTIONS = {
    "RAILS": (6.0, 3.0, 0.25),
    "HEAVY_CROSS_MEMBERS": (6.0, 3.0, 0.25),
    "LIGHT_CROSS_MEMBERS": (4.0, 3.0, 0.1875),
}
N1 = (0.0, 0.0, 1.0)

E_PSI, NU = 30.0e6, 0.3
RHO = 7.33e-4      # lbf*s^2/in^4 (0.283 lb/in^3 / 386.09 in/s^2)
G_IN_S2 = 386.09   # in/s^2, to convert lbf*s^2/in to lbm

# Load points: name -> (X, side) with side "L", "R" (rail node) or "C" (centreline node).
LOAD_POINTS = [
    ("P24_REEL", -25.0, "C"),
    ("P25_FRONT_AXLE_PIN", 0.0, "C"),
    ("P26_REAR_AXLE_PIN", 72.0, "C"),
    ("P27_LEVELING_CYLINDER", 68.0, "R"),
    ("P28_CAB_MOUNT_FL", 20.0, "L"),
    ("P29_CAB_MOUNT_FR", 20.0, "R"),
    ("P30_CAB_MOUNT_RL", 52.0, "L"),
    ("P31_CAB_MOUNT_RR", 52.0, "R"),
]
# The attachment's load points (thesis point 19 and the chain boom's soil load), by
# the names the 3-D vehicle model gives them (coupling/frame_loads_3d.h).
HITCH_LOAD_POINTS = ["P19_PLOW_SWING_PIN", "P19_CHAIN_PIN", "BOOM_SOIL"]

# --------------------------------------------------------------------------
# Build
# --------------------------------------------------------------------------


def build():
    ns = len(STATIONS)
    nodes = {}  # id -> (x, y, z)
    left = {}
    right = {}
    centre = {}
    for k, x in enumerate(STATIONS, start=1):
        nodes[k] = (x, -RAIL_Y, 0.0)
        left[x] = k
        nodes[ns + k] = (x, RAIL_Y, 0.0)
        right[x] = ns + k
    nid = 2 * ns
    for x, _, has_centre, _ in CROSS_MEMBERS:
        if has_centre:
            nid += 1
            nodes[nid] = (x, 0.0, 0.0)
            centre[x] = nid

    elements = {}  # id -> (n1, n2)
    elsets = {"LEFT_RAIL": [], "RIGHT_RAIL": [], "CROSS_MEMBERS": [],
              "RAILS": [], "HEAVY_CROSS_MEMBERS": [], "LIGHT_CROSS_MEMBERS": []}
    eid = 0
    for side, name in ((left, "LEFT_RAIL"), (right, "RIGHT_RAIL")):
        for x0, x1 in zip(STATIONS[:-1], STATIONS[1:]):
            eid += 1
            elements[eid] = (side[x0], side[x1])
            elsets[name].append(eid)
            elsets["RAILS"].append(eid)
    cm_elements = []  # (X, group, [element ids]) for the documentation
    for x, group, has_centre, _ in CROSS_MEMBERS:
        chain = [left[x], centre[x], right[x]] if has_centre else [left[x], right[x]]
        ids = []
        for a, b in zip(chain[:-1], chain[1:]):
            eid += 1
            elements[eid] = (a, b)
            ids.append(eid)
            elsets["CROSS_MEMBERS"].append(eid)
            elsets[group].append(eid)
        cm_elements.append((x, group, ids))

    nsets = {}
    for name, x, where in LOAD_POINTS:
        nsets[name] = [{"L": left, "R": right, "C": centre}[where][x]]
    nsets["REAR_END"] = [left[80.0], centre[80.0], right[80.0]]
    # The attachment's loads at point 19 (plow swing pin, chain pin, soil on the
    # chain boom) reach the frame through the hitch box, bolted across the rear end
    # plate: a rigid spider to the plate's three nodes.
    for name in HITCH_LOAD_POINTS:
        nsets[name] = list(nsets["REAR_END"])
    nsets["LEFT_RAIL_NODES"] = [left[x] for x in STATIONS]
    nsets["RIGHT_RAIL_NODES"] = [right[x] for x in STATIONS]
    return nodes, elements, elsets, nsets, left, right, centre, cm_elements


def box_properties(a, b, t):
    """Hand formulas for a uniform-wall rectangular tube (a along 1, b along 2)."""
    area = a * b - (a - 2 * t) * (b - 2 * t)
    i11 = (a * b**3 - (a - 2 * t) * (b - 2 * t) ** 3) / 12.0  # about local 1 (vertical axis)
    i22 = (b * a**3 - (b - 2 * t) * (a - 2 * t) ** 3) / 12.0  # about local 2 (horizontal axis)
    am = (a - t) * (b - t)                                    # area inside the wall midline
    j = 4.0 * am**2 / (2.0 * ((a - t) + (b - t)) / t)         # Bredt
    return area, i11, i22, j, am


def length(nodes, e):
    p, q = nodes[e[0]], nodes[e[1]]
    return math.dist(p, q)


# --------------------------------------------------------------------------
# Checks
# --------------------------------------------------------------------------


def check(nodes, elements, elsets, nsets):
    errors = []
    for eid, (a, b) in elements.items():
        if a not in nodes or b not in nodes:
            errors.append(f"element {eid} references an undefined node")
            continue
        L = length(nodes, (a, b))
        if L < 1e-9:
            errors.append(f"element {eid} has zero length")
            continue
        t = [(nodes[b][i] - nodes[a][i]) / L for i in range(3)]
        cross = (t[1] * N1[2] - t[2] * N1[1], t[2] * N1[0] - t[0] * N1[2], t[0] * N1[1] - t[1] * N1[0])
        if math.sqrt(sum(c * c for c in cross)) < 0.1:
            errors.append(f"element {eid}: n1 nearly parallel to the element axis")
    for name, members in elsets.items():
        for m in members:
            if m not in elements:
                errors.append(f"elset {name}: element {m} undefined")
        if len(set(members)) != len(members):
            errors.append(f"elset {name} lists an element twice")
    for name, members in nsets.items():
        for m in members:
            if m not in nodes:
                errors.append(f"nset {name}: node {m} undefined")
    count = {e: 0 for e in elements}
    for name in SECTIONS:
        for m in elsets[name]:
            count[m] += 1
    bad = [e for e, c in count.items() if c != 1]
    if bad:
        errors.append(f"elements not in exactly one section: {bad}")
    used = {n for e in elements.values() for n in e}
    if used != set(nodes):
        errors.append(f"nodes not used by any element: {sorted(set(nodes) - used)}")
    coords = {}
    for nid, p in nodes.items():
        key = tuple(round(c, 6) for c in p)
        if key in coords:
            errors.append(f"nodes {coords[key]} and {nid} coincide")
        coords[key] = nid
    # Connectivity (one piece).
    adj = {n: set() for n in nodes}
    for a, b in elements.values():
        adj[a].add(b)
        adj[b].add(a)
    seen, stack = set(), [next(iter(nodes))]
    while stack:
        n = stack.pop()
        if n not in seen:
            seen.add(n)
            stack.extend(adj[n] - seen)
    if seen != set(nodes):
        errors.append("mesh is not connected")
    return errors


# --------------------------------------------------------------------------
# Mass properties (line masses; each tube's own section inertia included)
# --------------------------------------------------------------------------


def mass_properties(nodes, elements, elsets):
    sec_of = {}
    for name in SECTIONS:
        for e in elsets[name]:
            sec_of[e] = name
    props = {name: box_properties(*dims) for name, dims in SECTIONS.items()}
    m_tot, first = 0.0, [0.0, 0.0, 0.0]
    parts = []
    for eid, (a, b) in elements.items():
        area, i11, i22, j, _ = props[sec_of[eid]]
        L = length(nodes, (a, b))
        m = RHO * area * L
        mid = [(nodes[a][i] + nodes[b][i]) / 2 for i in range(3)]
        t = [(nodes[b][i] - nodes[a][i]) / L for i in range(3)]
        parts.append((m, mid, t, L, i11, i22, area))
        m_tot += m
        for i in range(3):
            first[i] += m * mid[i]
    cg = [f / m_tot for f in first]
    inertia = [[0.0] * 3 for _ in range(3)]
    for m, mid, t, L, i11, i22, area in parts:
        r = [mid[i] - cg[i] for i in range(3)]
        # Slender rod along t: m L^2/12 (I - t t^T); section: rho*L*(polar) about t,
        # rho*L*I about the transverse axes (both sections have n1 = Z).
        for i in range(3):
            for k in range(3):
                delta = 1.0 if i == k else 0.0
                inertia[i][k] += m * L * L / 12.0 * (delta - t[i] * t[k])
                inertia[i][k] += m * ((sum(c * c for c in r)) * delta - r[i] * r[k])
        lin = RHO * L
        # section rotary inertia in global axes: about t -> (i11 + i22); about Z -> i11
        # (local 1 = Z, I11 is about the 1 axis); about the remaining horizontal axis -> i22.
        horiz = [-t[1], t[0], 0.0]  # horizontal axis normal to t (t lies in the XY plane)
        for axis, val in ((t, i11 + i22), ((0.0, 0.0, 1.0), i11), (horiz, i22)):
            for i in range(3):
                for k in range(3):
                    inertia[i][k] += lin * val * axis[i] * axis[k]
    return m_tot, cg, inertia


# --------------------------------------------------------------------------
# Output
# --------------------------------------------------------------------------


def fmt(v):
    s = f"{v:.4f}".rstrip("0")
    return s + "0" if s.endswith(".") else s


def write_inp(path, nodes, elements, elsets, nsets, left, right, centre, cm_elements):
    ns = len(STATIONS)
    L = []
    w = L.append
    w("** units: in-lbf-s")
    w("*HEADING")
    w("R-100-like trencher frame: 2 rails and 12 cross members, 51 nodes, 61 B31 elements (framedyn)")
    w("** Generated by meshes/tools/make_r100_frame.py; geometry, sections and assumptions:")
    w("** docs/meshes/r100_frame.md. Not the real R-100 frame (thesis Reference 21 is lost).")
    w("** Axes: X along the rails, positive REARWARD, X = 0 at the front axle; Y to the")
    w("** right; Z up; origin on the rails' neutral axis height on the machine centreline.")
    w("** Rails from X = -25 (front end) to X = 80 (rear end); axles at X = 0 and 72.")
    w("** Model data only: no supports, loads or steps. Include it from a study.")
    w("**")
    w(f"** Nodes 1-{ns}: left rail (Y = -{fmt(RAIL_Y)}), front to rear.")
    w(f"** Nodes {ns + 1}-{2 * ns}: right rail (Y = +{fmt(RAIL_Y)}), front to rear;"
      f" right node = left node + {ns} at the same X.")
    w(f"** Nodes {2 * ns + 1}-{len(nodes)}: centreline nodes of cross members, front to rear.")
    w("*NODE")
    for nid in sorted(nodes):
        x, y, z = nodes[nid]
        w(f"{nid}, {fmt(x)}, {fmt(y)}, {fmt(z)}")
    w("**")
    w(f"** Rail elements, front to rear: element k joins node k to k+1 (left rail),")
    w(f"** element {ns - 1}+k joins node {ns}+k to {ns + 1}+k (right rail).")
    w("*ELEMENT, TYPE=B31, ELSET=LEFT_RAIL")
    for e in elsets["LEFT_RAIL"]:
        w(f"{e}, {elements[e][0]}, {elements[e][1]}")
    w("*ELEMENT, TYPE=B31, ELSET=RIGHT_RAIL")
    for e in elsets["RIGHT_RAIL"]:
        w(f"{e}, {elements[e][0]}, {elements[e][1]}")
    w("** Cross members, front to rear, each from the left rail to the right rail")
    w("** (through its centreline node where it has one).")
    w("*ELEMENT, TYPE=B31, ELSET=CROSS_MEMBERS")
    for (x, group, ids), (_, _, _, what) in zip(cm_elements, CROSS_MEMBERS):
        w(f"** X = {fmt(x)}: {what} ({group})")
        for e in ids:
            w(f"{e}, {elements[e][0]}, {elements[e][1]}")
    w("**")
    w("** Section groups: every element is in exactly one of RAILS,")
    w("** HEAVY_CROSS_MEMBERS, LIGHT_CROSS_MEMBERS.")
    w("*ELSET, ELSET=RAILS, GENERATE")
    w(f"{elsets['RAILS'][0]}, {elsets['RAILS'][-1]}, 1")
    for name in ("HEAVY_CROSS_MEMBERS", "LIGHT_CROSS_MEMBERS"):
        w(f"*ELSET, ELSET={name}")
        ids = elsets[name]
        for i in range(0, len(ids), 8):
            w(", ".join(str(e) for e in ids[i:i + 8]))
    w("**")
    w("** Frame load points of the 3-D vehicle model (thesis points 24-31), one node each.")
    for name, x, where in LOAD_POINTS:
        nid = nsets[name][0]
        p = nodes[nid]
        w(f"** {name}: X = {fmt(p[0])}, Y = {fmt(p[1])}")
        w(f"*NSET, NSET={name}")
        w(f"{nid}")
    w("** Rear end nodes (X = 80): the thesis's SAPIV model clamped the frame here.")
    w("*NSET, NSET=REAR_END")
    w(", ".join(str(n) for n in nsets["REAR_END"]))
    w("** The attachment's loads (thesis point 19: plow swing pin, chain pin, soil on the chain")
    w("** boom) reach the frame through the hitch box on the rear end plate: a rigid spider")
    w("** to the plate's three nodes (docs/meshes/r100_frame.md, \"Load points\").")
    for name in HITCH_LOAD_POINTS:
        w(f"*NSET, NSET={name}")
        w(", ".join(str(n) for n in nsets[name]))
    w("*NSET, NSET=LEFT_RAIL_NODES, GENERATE")
    w(f"1, {ns}, 1")
    w("*NSET, NSET=RIGHT_RAIL_NODES, GENERATE")
    w(f"{ns + 1}, {2 * ns}, 1")
    w("**")
    w("** Steel: E = 30e6 psi, nu = 0.3, density 0.283 lb/in^3 / 386.09 in/s^2.")
    w("*MATERIAL, NAME=STEEL")
    w("*ELASTIC")
    w("30.0E6, 0.3")
    w("*DENSITY")
    w("7.33E-4")
    w("**")
    w("** Rectangular tubes, data line a, b, t1, t2, t3, t4: a = outer size along local 1,")
    w("** b = outer size along local 2, uniform walls. Local 1 (n1) = +Z for every element,")
    w("** so a is the VERTICAL depth and b the horizontal width of each tube.")
    for name, (a, b, t) in SECTIONS.items():
        w(f"** {name}: {fmt(b)} in wide x {fmt(a)} in deep x {fmt(t)} in wall")
        w(f"*BEAM SECTION, ELSET={name}, MATERIAL=STEEL, SECTION=BOX")
        w(f"{fmt(a)}, {fmt(b)}, {fmt(t)}, {fmt(t)}, {fmt(t)}, {fmt(t)}")
        w(", ".join(fmt(c) for c in N1))
    Path(path).write_text("\n".join(L) + "\n")


def summary(nodes, elements, elsets, nsets, left, right, centre, cm_elements):
    print(f"nodes {len(nodes)}, elements {len(elements)}")
    print("\nsections (in, in^2, in^4):")
    for name, (a, b, t) in SECTIONS.items():
        area, i11, i22, j, am = box_properties(a, b, t)
        print(f"  {name}: a={a} b={b} t={t}  A={area:.4f}  I11(about vertical)={i11:.4f}  "
              f"I22(about horizontal)={i22:.4f}  Am={am:.4f}  J={j:.4f}")
    print("\ntube length and mass by group:")
    total_len = total_m = 0.0
    for name in SECTIONS:
        area = box_properties(*SECTIONS[name])[0]
        ln = sum(length(nodes, elements[e]) for e in elsets[name])
        m = RHO * area * ln
        total_len += ln
        total_m += m
        print(f"  {name}: {len(elsets[name])} elements, {ln:.2f} in, volume {area * ln:.2f} in^3, "
              f"mass {m:.6f} lbf*s^2/in = {m * G_IN_S2:.2f} lbm")
    print(f"  total: {total_len:.2f} in, mass {total_m:.6f} lbf*s^2/in = {total_m * G_IN_S2:.2f} lbm")
    # Each cross member runs to the rail centrelines: half a rail width inside each
    # rail, one rail width in all, is counted twice.
    rail_width = SECTIONS["RAILS"][1]
    overlap = sum(box_properties(*SECTIONS[group])[0] * rail_width for _, group, _ in cm_elements)
    print(f"  volume counted twice at the rail/cross-member joints: {overlap:.2f} in^3 = "
          f"{overlap * RHO * G_IN_S2:.2f} lbm")
    m_tot, cg, I = mass_properties(nodes, elements, elsets)
    print(f"\nc.g. (in): X={cg[0]:.3f} Y={cg[1]:.3f} Z={cg[2]:.3f}")
    print("inertia about the c.g. (lbf*s^2*in):")
    for row in I:
        print("  " + "  ".join(f"{v:12.4f}" for v in row))
    print(f"FLT = {STATIONS[-1] - STATIONS[0]} in, rho (per unit frame length) = "
          f"{m_tot / (STATIONS[-1] - STATIONS[0]):.6e} lbf*s^2/in^2")
    print("\nload points:")
    for name, x, where in LOAD_POINTS:
        nid = nsets[name][0]
        print(f"  {name}: node {nid} at {nodes[nid]}")
    print("\nstations:")
    for x in STATIONS:
        cm = [c for c in CROSS_MEMBERS if c[0] == x]
        print(f"  X={x:6.1f}  L={left[x]:3d}  R={right[x]:3d}  C={centre.get(x, '-')!s:>3}  "
              f"{cm[0][3] + ' (' + cm[0][1] + ')' if cm else ''}")
    print("\nelement lengths (rails):", [fmt(b - a) for a, b in zip(STATIONS[:-1], STATIONS[1:])])
    for x, group, ids in cm_elements:
        print(f"  cross member X={x}: elements {ids} ({group})")


def main():
    model = build()
    errors = check(*model[:4])
    if errors:
        for e in errors:
            print("ERROR:", e, file=sys.stderr)
        return 1
    summary(*model)
    if "--check" not in sys.argv:
        out = Path(__file__).resolve().parent.parent / "r100_frame.inp"
        write_inp(out, *model)
        print(f"\nwrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
