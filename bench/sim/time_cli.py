#!/usr/bin/env python3
"""Times whole `highlift simulate` processes of two binaries in one run (issue 30): rounds that
alternate base and new, per run the wall time, the CPU time (user + sys) and the peak resident
set; prints the medians and the ratios new / base as a Markdown table, and the load average.

    time_cli.py BASE_BINARY NEW_BINARY [--rounds 5] [--project P] [--scenarios extension,rupture_wtb]
                [--out]   (also write the CSV, to a temporary file)
"""
import argparse
import os
import resource
import statistics
import subprocess
import tempfile
import time


def once(binary, project, scenario, out):
    cmd = [binary, "simulate", project, "--scenario", scenario]
    if out:
        cmd += ["--out", out]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("base")
    ap.add_argument("new")
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--project",
                    default=os.path.join(os.path.dirname(__file__), "..", "..", "examples", "a380_class_flaps.json"))
    ap.add_argument("--scenarios", default="extension,rupture_wtb,jam_l3")
    ap.add_argument("--out", action="store_true", help="write the CSV too")
    args = ap.parse_args()
    scenarios = args.scenarios.split(",")
    out = os.path.join(tempfile.gettempdir(), f"time_cli_{os.getpid()}.csv") if args.out else None
    load_before = os.getloadavg()
    t = {(b, s): [] for b in ("base", "new") for s in scenarios}
    rss = {}
    for r in range(args.rounds):
        for s in scenarios:
            order = ("base", "new") if r % 2 == 0 else ("new", "base")
            for b in order:
                # RUSAGE_CHILDREN's maxrss is the largest child so far: measured in a fresh child.
                code = ("import resource,subprocess,sys;subprocess.run(sys.argv[1:],stdout=subprocess.DEVNULL,"
                        "stderr=subprocess.DEVNULL);print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)")
                w, c = once(args.base if b == "base" else args.new, args.project, s, out)
                t[(b, s)].append((w, c))
                if r == 0:
                    cmd = [args.base if b == "base" else args.new, "simulate", args.project, "--scenario", s]
                    if out:
                        cmd += ["--out", out]
                    rss[(b, s)] = int(subprocess.run(["python3", "-c", code] + cmd, capture_output=True,
                                                     text=True).stdout) / 1024.0
    if out and os.path.exists(out):
        os.remove(out)
    load_after = os.getloadavg()
    print(f"load average {load_before[0]:.2f} before, {load_after[0]:.2f} after; {args.rounds} alternating rounds"
          f"{', with --out' if args.out else ''}")
    print()
    print("| scenario | base wall | new wall | base CPU | new CPU | new / base (CPU) | new / base (wall) |"
          " peak RSS base / new |")
    print("|---|---|---|---|---|---|---|---|")
    for s in scenarios:
        bw = statistics.median(x[0] for x in t[("base", s)])
        nw = statistics.median(x[0] for x in t[("new", s)])
        bc = statistics.median(x[1] for x in t[("base", s)])
        nc = statistics.median(x[1] for x in t[("new", s)])
        print(f"| {s} | {bw * 1e3:.0f} ms | {nw * 1e3:.0f} ms | {bc * 1e3:.0f} ms | {nc * 1e3:.0f} ms | {nc / bc:.2f} |"
              f" {nw / bw:.2f} | {rss[('base', s)]:.1f} / {rss[('new', s)]:.1f} MiB |")


if __name__ == "__main__":
    main()
