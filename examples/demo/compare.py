#!/usr/bin/env python3
"""Prints the demo's fflight and OSMesa outputs side by side with the largest difference."""
import sys

def rows(path):
    with open(path) as f:
        return [[float(v) for v in line.split()] for line in f if line.strip()]

fflight, osmesa = rows(sys.argv[1]), rows(sys.argv[2])
if len(fflight) != len(osmesa):
    sys.exit(f"fflight fed back {len(fflight)} points, OSMesa {len(osmesa)}")
print(f"{'window x, y':>16}  {'fflight r g b a':>36}  {'OSMesa r g b a':>36}")
largest = 0.0
for f, o in zip(fflight, osmesa):
    largest = max([largest] + [abs(a - b) for a, b in zip(f, o)])
    fmt = lambda row: " ".join(f"{v:8.6f}" for v in row[2:])
    print(f"{f[0]:7.2f} {f[1]:7.2f}  {fmt(f)}  {fmt(o)}")
print(f"{len(fflight)} lit vertices; largest difference fflight vs OSMesa: {largest:.3g}")
sys.exit(0 if largest <= 1e-5 else 1)
