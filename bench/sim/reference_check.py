#!/usr/bin/env python3
"""Checks that a simulator change does not move the answers (issue 30): every A380-class case is
simulated by two highlift binaries at a tight tolerance and their element peaks, component peaks
and event times are compared; then the error of each binary's default-tolerance run against the
first binary's tight-tolerance run (the reference) is compared, which must not get worse.

    reference_check.py BASE_BINARY NEW_BINARY [PROJECT.json] [--rtol 1e-8] [--jobs 2]
                       [--cases GLOB] [--limit 1e-6] [--keep DIR]

The cases are the 36 sizing cases of `highlift peak` (12 jams, 24 ruptures), simulated as
model::SizingScenario builds them (a jam while extending, a rupture while retracting with the
airload aiding, the failure at 1 s, stop at 2 s or 3 s), plus the project's own scenarios
(`extension`, `rupture_wtb`): a copy of the project gets one scenario per case, and each run is
`simulate --scenario CASE --rtol RTOL --json`.

Compared per case at RTOL: |tau| of every element's peak and of every component's peak
(relative to the case's largest peak torque; the component peaks also relative to their own
value), the peak times, and the times of every event
(same number and kinds of events; the time difference relative to the stop time). Exit 1 when a
relative change exceeds --limit (default 1e-6: the tight tolerance's own noise is far below)
or the default-tolerance error of NEW exceeds BASE's by more than 10 % plus 1e-9.
"""
import argparse
import concurrent.futures
import fnmatch
import json
import os
import subprocess
import sys


def run(binary, project, case, rtol):
    cmd = [binary, "simulate", project, "--scenario", case, "--json"]
    if rtol is not None:
        cmd += ["--rtol", repr(rtol)]
    out = subprocess.run(cmd, capture_output=True, text=True, check=False)
    try:
        return json.loads(out.stdout)
    except json.JSONDecodeError:
        sys.exit(f"{binary} {case}: no JSON ({out.stderr.strip()[:300]})")


def cases_of(binary, project):
    # (peak exits 1 when a case exceeds its capacity; the case list is there all the same)
    out = subprocess.run([binary, "peak", project, "--no-intervals", "--json"], capture_output=True, text=True,
                         check=False)
    return [(c["name"], c["kind"], c["component"]) for c in json.loads(out.stdout)["cases"]]


def project_with_cases(project, cases):
    """A copy of the project with one scenario per sizing case (as model::SizingScenario)."""
    with open(project) as f:
        p = json.load(f)
    directions = {lc["name"]: lc.get("direction") for lc in p["load_cases"]}
    first = {}
    for lc in p["load_cases"]:
        first.setdefault(lc.get("direction"), lc["name"])
    names = {s["name"] for s in p["scenarios"]}
    run_names = []
    for name, kind, component in cases:
        preferred = "retract" if kind == "rupture" else "extend"
        found = None
        for s in p["scenarios"]:
            target = s.get(kind, {}).get("component") if kind in s else None
            if s.get("kind") == kind and target == component and directions.get(s["load_case"]) == preferred:
                found = s["name"]
                break
        if found is None:
            found = f"{kind}_{component}"
            if found not in names:
                p["scenarios"].append({
                    "name": found, "kind": kind, "description": "sizing case (reference_check.py)",
                    "load_case": first.get(preferred, p["load_cases"][0]["name"]),
                    "stop_time": "2 s" if kind == "jam" else "3 s", kind: {"component": component, "time": "1 s"}})
                names.add(found)
        run_names.append(found)
    for s in ("extension", "rupture_wtb"):
        if s in names and s not in run_names:
            run_names.append(s)
    # Relative "sources" paths stay valid next to the original.
    path = os.path.join(os.path.dirname(os.path.abspath(project)), f".reference_check_{os.getpid()}.json")
    with open(path, "w") as f:
        json.dump(p, f, indent=1)
    return path, run_names


def peaks(result):
    out = {}
    for p in result.get("peak_torques", []):
        out["element " + p["element"]] = (p["tau"], p["time"])
    for p in result.get("component_peaks", []):
        out["component " + p["component"]] = (p["tau"], p["time"])
    return out


def compare(a, b, stop_time):
    """Largest relative changes (peak, peak time, event time) of b against a, with what."""
    pa, pb = peaks(a), peaks(b)
    scale = max([abs(v[0]) for v in pa.values()] + [1e-300])
    worst = {"peak": (0.0, ""), "component_peak": (0.0, ""), "peak_time": (0.0, ""), "event_time": (0.0, ""),
             "structure": ""}
    if set(pa) != set(pb):
        worst["structure"] = "different elements"
    for k in pa.keys() & pb.keys():
        d = abs(abs(pa[k][0]) - abs(pb[k][0])) / scale
        if d > worst["peak"][0]:
            worst["peak"] = (d, k)
        if k.startswith("component ") and pa[k][0] != 0.0:
            d = abs(abs(pa[k][0]) - abs(pb[k][0])) / abs(pa[k][0])
            if d > worst["component_peak"][0]:
                worst["component_peak"] = (d, k)
        # A peak time matters where the peak is a sizing value (above 1 % of the case's largest).
        if abs(pa[k][0]) > 0.01 * scale:
            d = abs(pa[k][1] - pb[k][1]) / stop_time
            if d > worst["peak_time"][0]:
                worst["peak_time"] = (d, k)
    ea, eb = a.get("events", []), b.get("events", [])
    if len(ea) != len(eb) or a.get("events_total") != b.get("events_total"):
        worst["structure"] += f" events {a.get('events_total')} vs {b.get('events_total')}"
    for x, y in zip(ea, eb):
        if (x["element"], x["kind"], x["what"]) != (y["element"], y["kind"], y["what"]):
            worst["structure"] += f" event {x['element']} {x['what']} vs {y['element']} {y['what']} at {x['time']}"
            break
        d = abs(x["time"] - y["time"]) / stop_time
        if d > worst["event_time"][0]:
            worst["event_time"] = (d, f"{x['element']} {x['what']} at {x['time']:.9g} s")
    return worst


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("base")
    ap.add_argument("new")
    ap.add_argument("project", nargs="?",
                    default=os.path.join(os.path.dirname(__file__), "..", "..", "examples", "a380_class_flaps.json"))
    ap.add_argument("--rtol", type=float, default=1e-8)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--cases", default="*")
    ap.add_argument("--limit", type=float, default=1e-6)
    ap.add_argument("--keep", help="directory for the JSON results")
    args = ap.parse_args()

    cases = cases_of(args.base, args.project)
    path, names = project_with_cases(args.project, cases)
    names = [n for n in names if any(fnmatch.fnmatch(n, g) for g in args.cases.split(","))]
    try:
        jobs = [(b, n, r) for n in names for b in (args.base, args.new) for r in (args.rtol, None)]
        with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
            results = dict(zip(jobs, pool.map(lambda j: run(j[0], path, j[1], j[2]), jobs)))
    finally:
        os.remove(path)
    if args.keep:
        os.makedirs(args.keep, exist_ok=True)
        for (b, n, r), v in results.items():
            tag = "base" if b == args.base else "new"
            with open(os.path.join(args.keep, f"{n}.{tag}.{'tight' if r else 'default'}.json"), "w") as f:
                json.dump(v, f)

    failed = False
    print(f"| case | steps base / new (rtol {args.rtol:g}) | peak change | component peak change |"
          " peak-time change | event-time change | default-tol. error base | new |")
    print("|---|---|---|---|---|---|---|---|")
    overall = {"peak": (0.0, ""), "component_peak": (0.0, ""), "peak_time": (0.0, ""), "event_time": (0.0, "")}
    for n in names:
        ref, new = results[(args.base, n, args.rtol)], results[(args.new, n, args.rtol)]
        if not ref.get("ok") or not new.get("ok"):
            print(f"| {n} | failed: {ref.get('message')} / {new.get('message')} | | | | | | |")
            failed = True
            continue
        stop = ref["stop_time"]
        w = compare(ref, new, stop)
        eb = compare(ref, results[(args.base, n, None)], stop)["peak"][0]
        en = compare(ref, results[(args.new, n, None)], stop)["peak"][0]
        for key in overall:
            if w[key][0] >= overall[key][0]:
                overall[key] = (w[key][0], f"{n}: {w[key][1]}")
        bad = w["structure"] or max(w[k][0] for k in overall) > args.limit
        worse = en > 1.1 * eb + 1e-9
        failed = failed or bool(bad) or worse
        print(f"| {n} | {ref['statistics']['steps']} / {new['statistics']['steps']} | {w['peak'][0]:.2e} |"
              f" {w['component_peak'][0]:.2e} |"
              f" {w['peak_time'][0]:.2e} | {w['event_time'][0]:.2e}{' ' + w['structure'] if w['structure'] else ''} |"
              f" {eb:.2e} | {en:.2e}{' WORSE' if worse else ''} |")
    print()
    for key, (v, what) in overall.items():
        print(f"largest {key.replace('_', ' ')} change at rtol {args.rtol:g}: {v:.3e} ({what})")
    print("result:", "FAIL" if failed else "ok")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
