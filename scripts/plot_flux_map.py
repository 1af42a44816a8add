#!/usr/bin/env python3
"""Draw the figure of `mhbench identify --flux-map ... --out DIR` from its CSVs.

Usage: plot_flux_map.py DIR [TITLE]

Reads DIR/points.csv (the measured map) and DIR/curves.csv (the fitted model's psi_d(i_d) curves at
a few levels of i_q and psi_q(i_q) curves at a few levels of i_d) and writes DIR/flux-map.pdf (fonts
embedded as TrueType, for a paper) and DIR/flux-map.png: two panels as drive papers show a flux map,
the measured points as markers and the fitted curves as lines, one colour per level. A measured
point is shown on a curve when its current equals the curve's level (a map taken on a current grid);
the curves of a map not taken on a grid are drawn without points. Sizes, fonts and colours are
plot_study.py's (scripts/figure_style.py): two columns wide, 8-9 pt serif. Each file is written
under a temporary name and renamed, so a stop leaves whole figures only. Needs matplotlib (Debian:
apt install python3-matplotlib); Agg backend.
"""
import csv
import math
import os
import sys


def rows(path):
    with open(path, newline="") as f:
        return [{k: float(v) if k != "curve" else v for k, v in r.items()} for r in csv.DictReader(f)]


def panel(ax, colours, curves, points, curve, swept, level_key, flux, level_name):
    levels = sorted({c["level"] for c in curves if c["curve"] == curve})
    for index, level in enumerate(levels):
        line = [c for c in curves if c["curve"] == curve and c["level"] == level and math.isfinite(c[flux])]
        colour = colours[index % len(colours)]
        ax.plot([c[swept] for c in line], [c[flux] for c in line], color=colour,
                label="$%s_%s$ = %g A" % (level_name[0], level_name[2], level))
        measured = [p for p in points if abs(p[level_key] - level) <= 1e-9 * max(1.0, abs(level))]
        ax.plot([p[swept] for p in measured], [p[flux] for p in measured], linestyle="none", marker="o",
                markerfacecolor="none", color=colour)
    ax.legend()


def main():
    if len(sys.argv) < 2:
        sys.stderr.write("usage: plot_flux_map.py DIR [TITLE]\n")
        return 2
    out_dir = sys.argv[1]
    title = sys.argv[2] if len(sys.argv) > 2 else "flux map"
    import matplotlib

    import figure_style

    figure_style.use_style(matplotlib)
    from matplotlib.figure import Figure

    points = rows(os.path.join(out_dir, "points.csv"))
    curves = rows(os.path.join(out_dir, "curves.csv"))
    # Fixed margins in inches, as plot_study.py's figures (no tight bounding box: one draw per format).
    width, height = figure_style.TWO_COLUMNS, 3.0
    fig = Figure(figsize=(width, height))
    fig.subplots_adjust(left=0.6 / width, right=1 - 0.12 / width, top=1 - 0.32 / height, bottom=0.45 / height,
                        wspace=0.3)
    left, right = fig.subplots(1, 2)
    colours = figure_style.PALETTE
    panel(left, colours, curves, points, "psi_d(i_d)", "i_d", "i_q", "psi_d", "i_q")
    left.set_xlabel("$i_d$ (A)")
    left.set_ylabel(r"$\psi_d$ (V s)")
    panel(right, colours, curves, points, "psi_q(i_q)", "i_q", "i_d", "psi_q", "i_d")
    right.set_xlabel("$i_q$ (A)")
    right.set_ylabel(r"$\psi_q$ (V s)")
    fig.suptitle(title + ": measured (markers), fitted (lines)", y=1 - 0.04 / height, va="top")
    figure_style.save_figure(fig, out_dir, "flux-map")
    return 0


if __name__ == "__main__":
    sys.exit(main())
