#!/usr/bin/env python3
"""Thesis Tables IV and V: the tables of docs/validation.md P6, C1 and C4, generated.

Standard library only. Every number in the two tables comes from `framedyn run`
on a study written here from a shipped file; nothing is typed by hand but the
thesis's own values (Tables IV and V, CMW2D/CMW3D columns).

  examples/tools/thesis_tables.py predict [--framedyn PATH]
      P6 (prediction): every case of Tables IV and V on the shipped machine
      with nothing fitted. Each case is a shipped study (examples/r100_*.yaml,
      or a thesis case file already on the shipped machine, its `calibration`
      block removed) with only the case's configuration changed (held
      coordinates, attachment, the cab stiff in X): the edits are listed per
      case below and printed under the table. The table's values are paired
      with the model's modes by frequency order, as a calibration pairs them
      (among the modes symmetric about X-Z for a 3-D column of the planar
      cases 5 and 6: energy share of y, theta_x, theta_z, v, theta_u, theta_w,
      eta, alpha below 1e-6), and the model's dominant coordinate of that mode
      is compared with the table's label (match yes/no). Measure: undamped
      natural frequency (rigid_modes.csv), both sides.

  examples/tools/thesis_tables.py predict --check docs/validation.md
      The same, compared with P6's table and count line in the document: exit
      status 1 and the differing rows if they differ (ctest
      ValidationReport.P6TableIsWhatTheShippedMachineGives runs this).

  examples/tools/thesis_tables.py fits [--framedyn PATH] [--jobs N] CASE...
      C1 and C4 (calibration): the bounded fit of each named case file
      (examples/thesis/CASE.yaml): targets, parameters with their moves,
      bounds and at_bound, independent targets, singular values, the largest
      miss and the fit status, from summary.json `rigid.calibration`. The
      cases run as N separate `framedyn run` processes at a time (default:
      one per core); each is a run of its own file, so the table does not
      depend on N.

  examples/tools/thesis_tables.py fits --check docs/validation.md
      The same for the cases that C1's and C4's generating commands name
      (`examples/tools/thesis_tables.py fits CASE...` in the section), each
      compared with the table after its command: exit status 1 and the
      differing rows if they differ (ctest
      ValidationReport.FitTablesOfC1AndC4AreWhatTheFitsGive runs this).

The framedyn binary defaults to build/apps/framedyn under the source tree.
"""
import argparse
import concurrent.futures
import csv
import json
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ANTISYMMETRIC = ["y", "theta_x", "theta_z", "v", "theta_u", "theta_w", "eta", "alpha"]

# The cab made very stiff in X (Table V, cases 5 and 6 in 3-D), as the thesis's
# case files do it: each mount's X spring 1e7 lbf/in at the cab's c.g. height,
# so that the cab's X follows the frame's there (the 2-D cab has no X).
CAB_STIFF_IN_X = [(f"- {{name: {m}, position: [{x}, {y}, 0], x: {{stiffness: 245, damping: 1.5}}",
                   f"- {{name: {m}, position: [{x}, {y}, 32], x: {{stiffness: 1.0e7, damping: 1.5}}")
                  for m, x, y in (("FL", 20, -15), ("FR", 20, 15), ("RL", 52, -15), ("RR", 52, 15))]
ALL_3D = ["x", "y", "z", "theta_x", "theta_y", "theta_z", "u", "v", "w", "theta_u", "theta_v", "theta_w", "eta", "alpha", "psi"]


def held_but(free, coordinates):
    return "  fixed_coordinates: [" + ", ".join(c for c in coordinates if c != free) + "]\n"


# (case, table, thesis values [(Hz, label)], base file, edits [(from, to)], pairing, the edits in words)
# pairing: "all" (frequency order over every mode), "symmetric" (over the modes
# symmetric about X-Z). A case file "thesis/..." has its calibration block removed.
CASES = [
    ("1", "IV, 2-D", [(2.175, "x"), (2.792, "z"), (3.841, "theta_y"), (6.268, "theta_v"), (7.051, "w")],
     "r100_plow_2d.yaml",
     [("attachment: plow", "attachment: none"), (None, "plow"), (None, "soil")],
     "all", "no attachment (plow and soil blocks removed)"),
    ("2", "IV, 3-D (frame alone)", [(1.586, "y"), (2.351, "theta_z"), (2.690, "x"), (3.183, "z"), (3.267, "theta_x"), (3.808, "theta_y")],
     "thesis/case2.yaml", [], "all", ""),
    ("3", "IV, 3-D (cab alone)", [(4.757, "u"), (4.966, "v"), (6.737, "theta_w"), (8.693, "w"), (9.214, "theta_v"), (12.320, "theta_u")],
     "thesis/case3.yaml", [], "all", ""),
    ("4 eta", "V, 3-D", [(3.499, "eta")], "thesis/case4_eta.yaml", [], "all", ""),
    ("4 alpha", "V, 3-D", [(4.402, "alpha")], "thesis/case4_alpha.yaml", [], "all", ""),
    ("4 psi", "V, 2-D", [(8.321, "psi")], "r100_plow_2d.yaml",
     [("analysis:\n  modes: true\n", "analysis:\n  modes: true\n" + held_but("psi", ["x", "z", "theta_y", "w", "theta_v", "psi"]))],
     "all", "every coordinate but psi held"),
    ("4 psi", "V, 3-D", [(5.016, "psi")], "r100_plow_straight.yaml",
     [("analysis:\n  modes: true\n", "analysis:\n  modes: true\n" + held_but("psi", ALL_3D))],
     "all", "every coordinate but psi held"),
    ("5", "V, 2-D", [(2.129, "x"), (2.718, "z"), (3.890, "theta_v"), (5.533, "theta_y"), (7.777, "w"), (8.321, "psi")],
     "r100_plow_2d.yaml", [], "all", ""),
    ("5", "V, 3-D", [(2.162, "x"), (2.742, "z"), (3.888, "theta_v"), (5.472, "theta_y"), (7.765, "w"), (8.321, "psi")],
     "r100_plow_straight.yaml", CAB_STIFF_IN_X, "symmetric", "cab mounts' X springs 1e7 lbf/in at the cab's c.g. height (Z 32 in)"),
    ("6", "V, 2-D", [(1.650, "z"), (3.835, "x"), (5.766, "w"), (6.510, "theta_v"), (8.903, "theta_y")],
     "r100_chain_2d.yaml", [], "all", ""),
    ("6", "V, 3-D", [(1.655, "z"), (3.836, "x"), (5.664, "w"), (6.479, "theta_v"), (8.751, "theta_y")],
     "r100_chain_center.yaml", CAB_STIFF_IN_X, "symmetric", "cab mounts' X springs 1e7 lbf/in at the cab's c.g. height (Z 32 in)"),
]


def study_text(base, edits):
    with open(os.path.join(ROOT, "examples", base)) as f:
        s = f.read()
    if base.startswith("thesis/"):
        s = re.sub(r"\ncalibration:\n(?:[ #].*\n|\n)*", "\n", s)
        if "\ncalibration:" in s:
            raise SystemExit(f"{base}: calibration block not removed")
    for old, new in edits:
        if old is None:  # drop the top-level block `new`
            s, n = re.subn(r"\n" + new + r":.*\n(?:[ #].*\n|\n)*", "\n", s, count=1)
            if n != 1:
                raise SystemExit(f"{base}: no block '{new}' to drop")
            continue
        if old not in s:
            raise SystemExit(f"{base}: edit '{old.strip()}' does not apply (has the shipped file changed?)")
        s = s.replace(old, new, 1)
    # only the modes are compared: no forced response is run
    s = re.sub(r"^  response:.*\n", "", s, flags=re.M)
    return s


def run(framedyn, text, folder):
    study = folder + ".yaml"
    with open(study, "w") as f:
        f.write(text)
    subprocess.run([framedyn, "run", study, "-o", folder, "-q"], check=True, stdout=subprocess.DEVNULL)
    return folder


def read_modes(folder):
    with open(os.path.join(folder, "rigid_modes.csv"), newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    return rows


def symmetric(row):
    return sum(float(row.get("energy_share_" + c, 0.0) or 0.0) for c in ANTISYMMETRIC) < 1e-6


def predict(framedyn, work, out=print):
    print = out  # noqa: A001 (the table goes to `out`)
    print("| case | Table | thesis (Hz, label) | shipped machine, same order (Hz, label) | miss | label | mode led by the same coordinate (Hz, miss) |")
    print("|---|---|---|---|---|---|---|")
    misses, matches, total, notes = [], 0, 0, []
    for i, (case, table, values, base, edits, pairing, what) in enumerate(CASES):
        folder = run(framedyn, study_text(base, edits), os.path.join(work, f"p6_{i}"))
        modes = read_modes(folder)
        if pairing == "symmetric":
            modes = [m for m in modes if symmetric(m)]
        modes.sort(key=lambda m: float(m["frequency [Hz]"]))
        targets = sorted(values)
        if len(modes) < len(targets):
            raise SystemExit(f"case {case} ({table}): {len(modes)} modes for {len(targets)} values")
        for (hz, label), m in zip(targets, modes):
            same = [float(n["frequency [Hz]"]) for n in modes if n["dominant"] == label]
            same_text = f"{same[0]:.3f} ({100 * (same[0] - hz) / hz:+.1f} %)" if same else "none"
            f = float(m["frequency [Hz]"])
            miss = (f - hz) / hz
            ok = m["dominant"] == label
            misses.append((abs(miss), case, table, label))
            matches += ok
            total += 1
            print(f"| {case} | {table} | {hz:.3f} {label} | {f:.3f} {m['dominant']} | {100 * miss:+.1f} % | {'yes' if ok else 'no'} | {same_text} |")
        notes.append(f"case {case} ({table}): examples/{base}" + ("" if not what else "; " + what) +
                     (" (paired among the modes symmetric about X-Z)" if pairing == "symmetric" else ""))
    within = sum(1 for m in misses if m[0] <= 0.10)
    worst = max(misses)
    print()
    print(f"Values within 10 %: {within} of {total}; within 1 %: {sum(1 for m in misses if m[0] <= 0.01)}; "
          f"worst: case {worst[1]} ({worst[2]}) {worst[3]}, {100 * worst[0]:.1f} %; labels predicted right: {matches} of {total}.")
    print()
    print("Studies (shipped file; edits):")
    for n in notes:
        print("- " + n)


def run_fit(framedyn, work, case):
    """`framedyn run examples/thesis/CASE.yaml`: its summary.json `rigid.calibration`."""
    folder = os.path.join(work, "fit_" + case)
    subprocess.run([framedyn, "run", os.path.join(ROOT, "examples", "thesis", case + ".yaml"), "-o", folder, "-q"],
                   check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(folder, "summary.json")) as f:
        return json.load(f)["rigid"]["calibration"]


def fits(framedyn, work, cases, jobs=None, out=print):
    print = out  # noqa: A001 (the table goes to `out`)
    # One process per case, `jobs` at a time: the runs share nothing, and the
    # rows are printed in the order of `cases` whatever order they finish in.
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs or os.cpu_count() or 1) as pool:
        calibrations = list(pool.map(lambda case: run_fit(framedyn, work, case), cases))
    print("| case | t / i / p | targets: table -> model (label, miss) | parameters: nominal -> fitted (ratio, bounds, at bound) | largest miss | s | status, iterations | labels |")
    print("|---|---|---|---|---|---|---|---|")
    for case, c in zip(cases, calibrations):
        ts = "; ".join(f"{t['frequency']['value']:.3f} {t['dominant']} -> {t['achieved']['value']:.3f} {t['achieved_dominant']} "
                       f"({100 * (t['achieved']['value'] - t['frequency']['value']) / t['frequency']['value']:+.1f} %)"
                       for t in c["targets"])
        ps = "; ".join(f"{p['name']} {p['initial']:.6g} -> {p['fitted']:.6g} (x{p['ratio']:.3f}, {p['lower']:.6g}-{p['upper']:.6g}"
                       f"{', **at bound**' if p['at_bound'] else ''})" for p in c["parameters"])
        sv = ", ".join(f"{s:.2g}" for s in c["singular_values"])
        labels = sum(1 for t in c["targets"] if t["label_matches"])
        print(f"| {case} | {c['target_count']} / {c['independent_targets']} / {c['parameter_count']} | {ts} | {ps} | "
              f"{100 * c['residual_max']:.2f} % | {sv} | {c['fit_status']}, {c['iterations']}"
              f"{' (limit)' if c['iteration_limit_reached'] else ''} | {labels}/{len(c['targets'])} |")


def doc_section(doc, number):
    """The lines of section NUMBER (e.g. "P6") of DOC, up to the next heading of its level or above."""
    with open(doc) as f:
        text = f.read()
    start = text.index(f"\n## {number}.")
    end = min((i for i in (text.find("\n## ", start + 1), text.find("\n# ", start + 1)) if i >= 0), default=len(text))
    return text[start:end].split("\n")


def compare(doc, number, generated, documented, regenerate):
    if generated == documented:
        print(f"{number} table of {doc}: {len(generated) - 2} rows as generated")
        return 0
    print(f"{number} table of {doc} differs from what framedyn gives (regenerate with {regenerate}):")
    for g, d in zip(generated + [""] * len(documented), documented + [""] * len(generated)):
        if g != d:
            print(f"  document:  {d}\n  generated: {g}")
    return 1


def collect(fill):
    lines = []
    fill(lambda *args: lines.append(" ".join(str(x) for x in args)))
    return lines


def check_p6(framedyn, work, doc):
    lines = collect(lambda out: predict(framedyn, work, out))
    generated = [l for l in lines if l.startswith("| ") or l.startswith("Values within")]
    section = doc_section(doc, "P6")
    documented = [l.strip("*") for l in section if l.startswith("| ") or l.startswith("**Values within")]
    return compare(doc, "P6", generated, documented, "examples/tools/thesis_tables.py predict")


FITS_COMMAND = re.compile(r"`examples/tools/thesis_tables\.py fits ([a-z0-9_ ]+)`")
FIT_SECTIONS = ("C1", "C4")


def check_fits(framedyn, work, doc, jobs):
    """In each of FIT_SECTIONS, the table that follows the section's generating command
    (`examples/tools/thesis_tables.py fits CASE...`), against the fits of those cases. Other
    tables of the sections (C1's hand-written one, C4's before-and-after) are not generated."""
    wanted = []  # (section, cases, documented rows)
    for number in FIT_SECTIONS:
        section = doc_section(doc, number)
        at = next((i for i, l in enumerate(section) if FITS_COMMAND.search(l)), None)
        if at is None:
            raise SystemExit(f"{doc}, {number}: no `examples/tools/thesis_tables.py fits CASE...` command names the table's cases")
        cases = FITS_COMMAND.search(section[at]).group(1).split()
        first = next(i for i in range(at, len(section)) if section[i].startswith("|"))
        documented = []
        for l in section[first:]:
            if not l.startswith("|"):
                break
            documented.append(l)
        wanted.append((number, cases, documented))
    # Every case of every section at once (jobs at a time), then each section's rows.
    all_cases = [c for _, cases, _ in wanted for c in cases]
    rows = [l for l in collect(lambda out: fits(framedyn, work, all_cases, jobs, out)) if l.startswith("|")]
    head, body = rows[:2], dict(zip(all_cases, rows[2:]))
    status = 0
    for number, cases, documented in wanted:
        generated = head + [body[c] for c in cases]
        status |= compare(doc, number, generated, documented, "examples/tools/thesis_tables.py fits " + " ".join(cases))
    return status


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("command", choices=["predict", "fits"])
    ap.add_argument("cases", nargs="*")
    ap.add_argument("--framedyn", default=os.path.join(ROOT, "build", "apps", "framedyn"))
    ap.add_argument("--check", metavar="DOC", help="compare with DOC's P6 (predict) or C4 (fits) table")
    ap.add_argument("--jobs", type=int, default=None, help="fits: cases run at a time (default: one per core)")
    a = ap.parse_args()
    if a.command == "fits" and not a.check and not a.cases:
        ap.error("fits: name the cases (examples/thesis/CASE.yaml), or --check DOC")
    with tempfile.TemporaryDirectory(prefix="thesis_tables_") as work:
        if a.command == "predict" and a.check:
            return check_p6(a.framedyn, work, a.check)
        if a.command == "predict":
            predict(a.framedyn, work)
        elif a.check:
            return check_fits(a.framedyn, work, a.check, a.jobs)
        else:
            fits(a.framedyn, work, a.cases, a.jobs)


if __name__ == "__main__":
    sys.exit(main())
