#!/usr/bin/env python3
"""Offset plowing from Python (docs/user-guide.md, "Python"): runs examples/offset_plowing.yaml
in memory with the framedyn module, plots the bending-moment envelope along both rails
(thesis Figure 25) and the total von Mises stress history at the top hot spot, and writes
the figure (matplotlib, Agg backend: no display needed).

    PYTHONPATH=build/python /usr/bin/python3 examples/python/offset_plowing.py [--duration S] [--out FIG.png]
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import framedyn  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--study", default=os.path.join(HERE, "..", "offset_plowing.yaml"))
    parser.add_argument("--duration", type=float, help="seconds of plowing (default: the study's)")
    parser.add_argument("--out", default="offset_plowing.png", help="the figure (PNG)")
    args = parser.parse_args()

    study = framedyn.load_study(args.study)
    if args.duration:
        study.set("analysis.response.duration", args.duration)
    r = study.run()  # in memory: nothing is written but the figure
    u = r.units

    fig, (envelopes, history) = plt.subplots(2, 1, figsize=(8, 8))
    for rail, e in r.rail_envelopes.items():
        envelopes.plot(e["x"], e["bending_moment"], marker=".", label=rail)
    envelopes.set_xlabel("X [%s]" % u["rail_envelopes"]["x"])
    envelopes.set_ylabel("largest |M| over the run [%s]" % u["rail_envelopes"]["bending_moment"])
    envelopes.set_title("Rail bending-moment envelopes (Figure 25)")
    envelopes.legend()

    hot = r.hot_spots[0]
    history.plot(r.frame_time, hot["von_mises"], label=hot["name"])
    history.set_xlabel("time [%s]" % u["frame_time"])
    history.set_ylabel("total von Mises stress [%s]" % u["hot_spots"]["von_mises"])
    history.set_title("Stress history at the top hot spot")
    history.legend()
    fig.tight_layout()
    fig.savefig(args.out, dpi=100)
    peak = max(hot["von_mises"])
    print("%s: peak %.6g %s at %s; figure %s" % (r.summary["input"]["name"], peak, u["hot_spots"]["von_mises"], hot["name"], args.out))


if __name__ == "__main__":
    main()
