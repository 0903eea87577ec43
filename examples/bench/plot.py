#!/usr/bin/env python3
"""Plots ns per vertex against the number of lights from run.py's CSV (a `lights` column,
then one column per line).

    plot.py LIGHTS_CSV OUT_PNG TITLE
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")  # no display: `make bench` may run headless
import matplotlib.pyplot as plt  # noqa: E402


def main(data, png, title):
    with open(data) as f:
        header, *rows = list(csv.reader(f))
    lights = [int(row[0]) for row in rows]
    fig, ax = plt.subplots(figsize=(8, 5))
    for column, label in enumerate(header[1:], start=1):
        ax.plot(lights, [float(row[column]) for row in rows], marker="o", label=label)
    ax.set_xlabel("spot lights (attenuated; local viewer, two-sided, GL_NORMALIZE)")
    ax.set_ylabel("ns per vertex (lower is better)")
    ax.set_title(title, fontsize=9)
    ax.set_xticks(lights)
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(png, dpi=120)


if __name__ == "__main__":
    main(*sys.argv[1:4])
