#!/usr/bin/env python3
"""The `make bench` driver: runs bench.c built against OSMesa and against fflight on the same
scenes, prints one table (ns per vertex, speed ratio = OSMesa time / fflight time, target,
PASS/FAIL), writes it to BENCH_DIR/results.md, and plots ns per vertex against the number of
lights (BENCH_DIR/lights.png, copied to docs/bench-lights.png).

    run.py BENCH_DIR [--vertices N]

BENCH_DIR holds bench_osmesa and bench_fflight. --vertices sets the size of the timed scenes
(default 1000000; the memory scenes use 10 times as many) for a quick run. A missed target is
reported, not an error; the exit status is 1 when a program fails (crash, GL error, wrong
feedback count) or the plot cannot be made.
"""
import argparse
import csv
import os
import shutil
import statistics
import subprocess
import sys
from pathlib import Path

RUNS = 7  # timed runs per scene and process, after the program's own warm-up run
# Processes per library and scene, the two libraries alternating: the reported time is the
# median of the processes' medians. The machine is shared, and one process of either library
# can land in a slow minute (OSMesa's own median moved by 1.7x between two processes; a
# scene's ratio by 2.4x between rounds of one run at stop 26, hence five rather than three).
ROUNDS = 5
PLOT_RUNS = 5
TIMEOUT = 600  # seconds per program: a hang is a failure, not a stalled `make bench`
# Memory bound: 1 MiB per fflight thread (a worker's stack and buffers) plus this allowance
# for page tables, allocator slack and the main thread's stack.
ALLOWANCE_KIB = 256

# Scene, minimum speed ratio. bench.c runs OSMesa's same draw for both bulk rows.
TIMED = [
    ("arrays_1light", 4.0),
    ("arrays_8spot", 4.0),
    ("immediate_1light", 3.0),
    ("immediate_8spot", 3.0),
    ("mesh_8light", 4.0),
    ("bulk_8spot_1thread", 3.0),
    ("bulk_8spot_threads", 5.5),
]
MEMORY = ["memory_bulk_10M", "memory_arrays_10M"]

failures = []
# CPU time the hypervisor gave other guests while each library's programs ran, in ticks
# of /proc/stat (steal, and every state together): a virtual machine's second core can be
# taken away, and a library that uses both cores loses more then.
stolen = {}


def cpu_ticks():
    """(steal, total) ticks of all CPUs so far, from /proc/stat; (0, 0) where unreadable."""
    try:
        with open("/proc/stat") as f:
            fields = [int(v) for v in f.readline().split()[1:]]
    except (OSError, ValueError):
        return 0, 0
    return (fields[7] if len(fields) > 7 else 0), sum(fields)


def run(binary, scene, vertices, runs=RUNS, threads=None):
    """Runs one scene in its own process and returns its `key=value` line as a dict, or None
    (recorded in failures). threads=None leaves fflight its default, all cores."""
    env = {k: v for k, v in os.environ.items() if k != "FFLIGHT_THREADS"}
    if threads is not None:
        env["FFLIGHT_THREADS"] = str(threads)
    cmd = [str(binary), scene, str(vertices), str(runs)]
    print(f"bench: {' '.join(cmd[1:])} ({binary.name})", file=sys.stderr, flush=True)
    before = cpu_ticks()
    try:
        done = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=TIMEOUT)
        after = cpu_ticks()
        total = stolen.setdefault(binary.name, [0, 0])
        total[0] += after[0] - before[0]
        total[1] += after[1] - before[1]
    except subprocess.TimeoutExpired:
        failures.append(f"{binary.name} {scene}: no result after {TIMEOUT} s")
        return None
    fields = done.stdout.split()
    if done.returncode != 0 or not fields or fields[0] != scene:
        failures.append(f"{binary.name} {scene}: exit status {done.returncode}\n"
                        f"{done.stdout}{done.stderr}".rstrip())
        return None
    return {k: float(v) for k, v in (f.split("=") for f in fields[1:])}


def cpu_line():
    model, flags = "unknown", set()
    with open("/proc/cpuinfo") as f:
        for line in f:
            key, _, value = line.partition(":")
            if key.strip() == "model name" and model == "unknown":
                model = value.strip()
            elif key.strip() == "flags":
                flags = set(value.split())
    has = lambda flag: "yes" if flag in flags else "no"
    return f"CPU: {model}, {os.cpu_count()} cores, avx512f: {has('avx512f')}, avx2: {has('avx2')}"


def fmt(value, spec):
    return "error" if value is None else format(value, spec)


def rounds(osmesa, fflight, scene, vertices):
    """ROUNDS processes of each library on `scene`, alternating; each library's last result
    line with the median of the processes' ns_per_vertex in it, and the ratio of each round,
    or None for a library that failed."""
    results = {osmesa: [], fflight: []}
    for _ in range(ROUNDS):
        for binary in (osmesa, fflight):
            results[binary].append(run(binary, scene, vertices))
    medians = []
    for binary in (osmesa, fflight):
        if None in results[binary]:
            medians.append(None)
            continue
        line = dict(results[binary][-1])
        for key in ("ns_per_vertex", "ns_per_triangle"):
            if key in line:
                line[key] = statistics.median(r[key] for r in results[binary])
        medians.append(line)
    each = [o["ns_per_vertex"] / f["ns_per_vertex"]
            for o, f in zip(results[osmesa], results[fflight]) if o and f]
    return medians[0], medians[1], each


def timed_rows(osmesa, fflight, vertices):
    rows, notes, threads, spreads = [], [], [], []
    for scene, target in TIMED:
        o, f, each = rounds(osmesa, fflight, scene, vertices)
        o_ns = o and o["ns_per_vertex"]
        f_ns = f and f["ns_per_vertex"]
        ratio = o_ns / f_ns if o and f else None
        if each:
            spreads.append(f"{scene} {min(each):.2f}-{max(each):.2f}")
        result = "error" if ratio is None else "PASS" if ratio >= target else "FAIL"
        rows.append([scene, fmt(o_ns, ".1f"), fmt(f_ns, ".1f"), fmt(ratio, ".2f"),
                     f">= {target}", result])
        if f:
            threads.append(f"{scene} {int(f['threads'])}")
        if scene == "mesh_8light" and o and f:
            notes.append(f"mesh_8light: {int(f['triangles'])} triangles, ns per triangle: "
                         f"OSMesa {o['ns_per_triangle']:.1f}, fflight {f['ns_per_triangle']:.1f}")
    notes.append("fflight threads: " + ", ".join(threads))
    notes.append(f"ratio of each of the {ROUNDS} rounds, lowest-highest: " + ", ".join(spreads))
    return rows, notes


def memory_rows(fflight, vertices):
    rows = []
    for scene in MEMORY:
        m = run(fflight, scene, vertices)
        if m is None:
            rows.append([scene, "n/a", "error", "n/a", "", "error"])
            continue
        bound = int(m["threads"]) * 1024 + ALLOWANCE_KIB
        increase = int(m["increase_kib"])
        rows.append([scene, "n/a", f"+{increase} KiB", "n/a",
                     f"<= {bound} KiB ({int(m['threads'])} x 1 MiB + {ALLOWANCE_KIB} KiB)",
                     "PASS" if increase <= bound else "FAIL"])
    return rows


def plot(osmesa, fflight, vertices, out_dir, title):
    """ns per vertex for scene 1's draw with the first k of the 8 spot lights, k = 1..8."""
    lines = [(osmesa, None), (fflight, 1), (fflight, None)]
    table, threads = [], 0
    for k in range(1, 9):
        row = [k]
        for binary, count in lines:
            r = run(binary, f"lights_{k}", vertices, PLOT_RUNS, count)
            if r is None:
                return None
            row.append(f"{r['ns_per_vertex']:.3f}")
            if binary is fflight and count is None:
                threads = int(r["threads"])
        table.append(row)
    table.insert(0, ["lights", "OSMesa", "fflight, 1 thread",
                     f"fflight, all threads ({threads})"])
    data, png = out_dir / "lights.csv", out_dir / "lights.png"
    with open(data, "w", newline="") as f:
        csv.writer(f).writerows(table)
    script = Path(__file__).with_name("plot.py")
    if subprocess.run([sys.executable, str(script), str(data), str(png), title]).returncode:
        failures.append("plot.py failed")
        return None
    docs = Path(__file__).resolve().parents[2] / "docs" / "bench-lights.png"
    shutil.copyfile(png, docs)
    return png, docs


def text_table(rows):
    widths = [max(len(row[i]) for row in rows) for i in range(len(rows[0]))]
    return "\n".join("  ".join(cell.ljust(w) if i in (0, 4, 5) else cell.rjust(w)
                               for i, (cell, w) in enumerate(zip(row, widths))).rstrip()
                     for row in rows)


def markdown_table(rows):
    lines = ["| " + " | ".join(rows[0]) + " |", "|---|--:|--:|--:|---|---|"]
    return "\n".join(lines + ["| " + " | ".join(row) + " |" for row in rows[1:]])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("bench_dir", type=Path)
    parser.add_argument("--vertices", type=int, default=1000000)
    args = parser.parse_args()
    osmesa, fflight = args.bench_dir / "bench_osmesa", args.bench_dir / "bench_fflight"

    cpu = cpu_line()
    with open("/proc/loadavg") as f:  # other work on the machine skews the timings
        load = f.read().split()[0]
    rows, notes = timed_rows(osmesa, fflight, args.vertices)
    shares = [f"{name} {100 * steal / total:.1f}%"
              for name, (steal, total) in stolen.items() if total > 0]
    notes.append("CPU time (both cores) stolen by the hypervisor during each library's runs: "
                 + ", ".join(shares))
    rows += memory_rows(fflight, 10 * args.vertices)
    plotted = plot(osmesa, fflight, args.vertices, args.bench_dir,
                   f"glDrawArrays(GL_POINTS) + GL_3D_COLOR feedback, {args.vertices} points\n{cpu}")
    rows.insert(0, ["scene", "OSMesa ns/vertex", "fflight ns/vertex",
                    "ratio (OSMesa/fflight)", "target", "result"])
    notes += [f"median of {ROUNDS} processes per library (alternating), each the median of "
              f"{RUNS} runs after a warm-up; {args.vertices} vertices per scene "
              f"(mesh: a square grid), memory scenes {10 * args.vertices}; "
              f"load average at the start {load}",
              "memory: growth of the peak RSS (VmHWM) over one call, 1 light, after a "
              f"1000-vertex warm-up call; allowance {ALLOWANCE_KIB} KiB beyond 1 MiB per thread"]
    if plotted:
        notes.append(f"plot: {plotted[0]} (copied to {plotted[1]})")

    print(cpu)
    print(text_table(rows))
    for note in notes:
        print(f"  {note}")
    results = args.bench_dir / "results.md"
    results.write_text(f"{cpu}\n\n{markdown_table(rows)}\n\n"
                       + "".join(f"- {note}\n" for note in notes))
    print(f"table written to {results}")
    for failure in failures:
        print(f"FAILED: {failure}", file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
