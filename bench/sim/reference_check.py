#!/usr/bin/env python3
"""Checks that a simulator change does not move the answers (issue 30): every A380-class case is
simulated by two highlift binaries at a tight tolerance and their element peaks, component peaks
and event times are compared; then the error of each binary's default-tolerance run against the
first binary's tight-tolerance run (the reference) is compared, which must not get worse.

    reference_check.py BASE_BINARY NEW_BINARY [PROJECT.json] [--rtol 1e-8] [--jobs 2]
                       [--cases GLOB] [--limit 1e-6] [--keep DIR] [--reuse DIR]
                       [--reference-interval DT [--reference-binary B] [--reference-rtol R]
                        [--steps-may-change [--chance K]]]

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

With --reference-interval DT (seconds) the peaks are judged against an independent reference
instead: BASE (or --reference-binary) at RTOL with every scenario's output interval set to DT
(at most 4 million rows), a binary that samples its peaks at the output points (main before the
peaks were located between step ends, 2026-12-05). That is for a change of how a peak is measured, which moves the
peaks by design. The errors against the reference are those of the element peaks relative to
the case's largest and of the component peaks relative to their own value (components above
1 % of the case's largest component peak). Exit 1 when NEW's steps or events at RTOL are not
BASE's (the event times within --limit), or, over all cases, when NEW's largest error or the
geometric mean of its errors (at RTOL and at the default tolerance, each floored at 1e-9)
exceeds BASE's by more than 10 %. A case where NEW's error exceeds BASE's is marked but does not
fail alone: a sampled peak falls below the solution's maximum by a sampling error that can
cancel the integration error by chance, which a located peak no longer does.

With --steps-may-change (a change that moves the steps: an integrator setting, a linear solver
with other roundoff) only the time events and the events that change a mode are compared (not
the actuators' reversals, which are counted, nor a root that fired without changing a mode:
both depend on roundoff), and a geometric mean fails only when it also grew by more than two
standard errors of the cases' log ratios. Each case's error moves by chance with its steps:
main's binary with its tolerances scaled by 1 +- 1e-6 moves the geometric means by 0.90 to
1.19 and the largest errors by up to 26 % (2026-12-05). Such a change is judged against a
reference at a tighter tolerance (--reference-rtol 1e-10): at RTOL itself the reference shares
BASE's steps, and BASE's tight error would be only its sampling error.

--chance K (with --steps-may-change) measures that chance instead of assuming it: BASE runs
every case K more times at the default tolerance and K more times at RTOL, each with its
relative tolerance scaled by 1 + 0.1 %, 1 - 0.1 %, 1 + 0.3 %, 1 - 0.3 %, 1 + 1 %, ... (K at
most 8): the same tolerance to an engineer, other steps. The largest errors and geometric means
of NEW at each tolerance are then judged against the largest of BASE's and of these runs': a
change fails only where it is worse than BASE by more than BASE's own steps move it. (At RTOL
the errors are those of the steps as well: measured 2026-12-05, BASE at 1e-8 x (1 +- 0.1 %,
+ 0.3 %) gave largest element errors of 2.58e-6 to 2.77e-6 against 2.21e-6 at 1e-8 itself.) (Measured 2026-12-05: BASE at rtol
scaled by 1 + 1e-6 judged as NEW fails the largest-error test, 6.7e-5 -> 8.7e-5; and the
largest component error, a gearbox peak of rupture_shaft_l1, moves from 3.24e-3 to 3.82e-3
between rtol 0.99e-5 and 1.01e-5, where 1 +- 1e-6 leaves it within 1 %.)

--reuse DIR reads the runs that a --keep DIR holds instead of running them again (the reference
files name their tolerance), so a change can be judged again, or against another BASE's runs,
without the reference runs.
"""
import argparse
import concurrent.futures
import fnmatch
import json
import math
import os
import subprocess
import sys


def run(binary, project, case, rtol, extra=()):
    cmd = [binary, "simulate", project, "--scenario", case, "--json", *extra]
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


def project_with_cases(project, cases, output_interval=None, tag=""):
    """A copy of the project with one scenario per sizing case (as model::SizingScenario); with
    `output_interval` (s) every scenario writes at that interval."""
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
    if output_interval is not None:
        p.setdefault("settings", {})["output_interval"] = f"{output_interval!r} s"
        for s in p["scenarios"]:  # at most 4 million rows per run (the extension's 40 s: 10 us)
            stop = float(str(s.get("stop_time", "3 s")).split()[0])
            s["output_interval"] = f"{max(output_interval, stop / 4e6)!r} s"
    # Relative "sources" paths stay valid next to the original.
    path = os.path.join(os.path.dirname(os.path.abspath(project)), f".reference_check_{os.getpid()}{tag}.json")
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


def result_file(args, binary, case, rtol):
    """The file of one run in a --keep directory (the reference's and the chance runs' name their
    tolerance)."""
    if binary == "reference":
        return f"{case}.reference.{rtol:g}.json"
    if binary == "chance":
        return f"{case}.chance.{rtol:.9g}.json"
    return f"{case}.{'base' if binary == args.base else 'new'}.{'tight' if rtol else 'default'}.json"


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
    ap.add_argument("--reference-interval", type=float,
                    help="judge the peaks against BASE at RTOL sampled at this output interval (s)")
    ap.add_argument("--reference-binary",
                    help="the binary of the sampled reference (default BASE); it must sample its peaks at the output "
                         "points (main before 2026-12-05)")
    ap.add_argument("--reference-rtol", type=float,
                    help="the relative tolerance of the sampled reference (default RTOL); below RTOL for a change "
                         "of the steps, whose tight run BASE's reference would otherwise share")
    ap.add_argument("--reuse", help="a --keep directory: runs found there are read instead of run again")
    ap.add_argument("--steps-may-change", action="store_true",
                    help="with --reference-interval: a change of the step sequence (an integrator setting); "
                         "the events that change a mode must be BASE's, the actuators' reversals may differ")
    ap.add_argument("--chance", type=int, default=0,
                    help="with --steps-may-change: K runs of BASE per case at the default tolerance and K at RTOL, "
                         "each scaled by 1 +- 0.1 %%, 0.3 %%, 1 %%, 3 %%; NEW is judged against the largest errors of "
                         "BASE and of these")
    args = ap.parse_args()
    args.reference_rtol = args.reference_rtol or args.rtol
    if args.chance and not (args.steps_may_change and args.reference_interval):
        ap.error("--chance needs --steps-may-change and --reference-interval")
    if args.chance > 8:
        ap.error("--chance takes at most 8 runs per case (rtol x 1 +- 0.1 %, 0.3 %, 1 %, 3 %)")
    args.chance_rtols = []  # the default tolerance's chance runs
    args.chance_tight = []  # RTOL's
    if args.chance:
        with open(args.project) as f:
            default_rtol = float(json.load(f).get("settings", {}).get("relative_tolerance", 1e-6))
        steps = (1e-3, 3e-3, 1e-2, 3e-2)
        for k in range(args.chance):
            d = steps[min(k // 2, len(steps) - 1)] * (1 if k % 2 == 0 else -1)
            args.chance_rtols.append(default_rtol * (1 + d))
            args.chance_tight.append(args.rtol * (1 + d))

    cases = cases_of(args.base, args.project)
    path, names = project_with_cases(args.project, cases)
    fine_path = None
    if args.reference_interval:
        fine_path, _ = project_with_cases(args.project, cases, args.reference_interval, "_fine")
    names = [n for n in names if any(fnmatch.fnmatch(n, g) for g in args.cases.split(","))]
    try:
        jobs = [(b, n, r) for n in names for b in (args.base, args.new) for r in (args.rtol, None)]
        if fine_path:
            jobs = [("reference", n, args.reference_rtol) for n in names] + jobs
        jobs += [("chance", n, r) for n in names for r in args.chance_rtols + args.chance_tight]

        def one(j):
            kept = os.path.join(args.reuse, result_file(args, *j)) if args.reuse else None
            if kept and os.path.exists(kept):
                with open(kept) as f:
                    return json.load(f)
            if j[0] == "reference":
                return run(args.reference_binary or args.base, fine_path, j[1], j[2], ("--max-rows", "1e8"))
            if j[0] == "chance":
                return run(args.base, path, j[1], j[2])
            return run(j[0], path, j[1], j[2])

        with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
            results = dict(zip(jobs, pool.map(one, jobs)))
    finally:
        os.remove(path)
        if fine_path:
            os.remove(fine_path)
    if args.keep:
        os.makedirs(args.keep, exist_ok=True)
        for j, v in results.items():
            with open(os.path.join(args.keep, result_file(args, *j)), "w") as f:
                json.dump(v, f)
    if fine_path:
        return judge_against_reference(args, names, results)

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


def errors(ref, run):
    """The largest error of run's peaks against ref's: (element peaks relative to the case's
    largest, component peaks relative to their own value where that is a sizing value, above
    1 % of the case's largest)."""
    pr, pn = peaks(ref), peaks(run)
    scale = max([abs(v[0]) for v in pr.values()] + [1e-300])
    component_scale = max([abs(v[0]) for k, v in pr.items() if k.startswith("component ")] + [1e-300])
    element = component = 0.0
    for k in pr.keys() & pn.keys():
        d = abs(abs(pr[k][0]) - abs(pn[k][0]))
        element = max(element, d / scale)
        if k.startswith("component ") and abs(pr[k][0]) > 0.01 * component_scale:
            component = max(component, d / abs(pr[k][0]))
    return element, component


def mode_events(run):
    """The run with only the time events and the state events that change a mode. Left out: the
    kinematic reversals ("<gra> contact"), whose number near zero speed depends on roundoff, and
    the roots that fired without changing a mode ("<brake> root 1": a root function that touches
    zero within roundoff fires in one run and not in another)."""
    r = dict(run)
    r["events"] = [e for e in run.get("events", []) if e.get("kind") != "state" or "->" in e["what"]]
    r["events_total"] = len(r["events"])
    r["peak_torques"], r["component_peaks"] = [], []
    return r


def reversal_counts(runs):
    n = [sum(1 for e in runs[k].get("events", []) if e["what"].endswith(" contact")) for k in ("tight base", "tight new")]
    return f"; reversals {n[0]} / {n[1]}"


def judge_against_reference(args, names, results):
    failed = False
    print(f"Reference: {args.reference_binary or args.base} at rtol {args.reference_rtol:g}, sampled every"
          f" {args.reference_interval:g} s.")
    print("Errors against it: element peaks relative to the case's largest / component peaks relative to their own.")
    print()
    print(f"| case | steps base / new (rtol {args.rtol:g}) | event-time change | error at rtol {args.rtol:g}: base | new |"
          " error at the default tolerance: base | new |")
    print("|---|---|---|---|---|---|---|")
    totals = {k: [0.0, 0.0] for k in ("tight base", "tight new", "default base", "default new")}
    logs = {k: [0.0, 0.0] for k in totals}
    ratios = {(tol, i): [] for tol in ("tight", "default") for i in (0, 1)}  # log(new / base) per case
    counted = 0
    worst_event = (0.0, "")
    chance_totals = {r: [0.0, 0.0] for r in args.chance_rtols + args.chance_tight}
    chance_logs = {r: [0.0, 0.0] for r in args.chance_rtols + args.chance_tight}
    for n in names:
        ref = results[("reference", n, args.reference_rtol)]
        runs = {"tight base": results[(args.base, n, args.rtol)], "tight new": results[(args.new, n, args.rtol)],
                "default base": results[(args.base, n, None)], "default new": results[(args.new, n, None)]}
        if not ref.get("ok") or not all(r.get("ok") for r in runs.values()):
            print(f"| {n} | failed: {[r.get('message') for r in [ref, *runs.values()]]} | | | | | |")
            failed = True
            continue
        # The events and steps do not move (the change measures the peaks, it does not integrate);
        # with --steps-may-change only the events that change a mode are compared.
        steps = (runs["tight base"]["statistics"]["steps"], runs["tight new"]["statistics"]["steps"])
        if args.steps_may_change:
            w = compare(mode_events(runs["tight base"]), mode_events(runs["tight new"]), ref["stop_time"])
            w["structure"] += reversal_counts(runs)
            bad = bool(w["structure"].split(";")[0].strip()) or w["event_time"][0] > args.limit
        else:
            w = compare(runs["tight base"], runs["tight new"], ref["stop_time"])
            bad = bool(w["structure"]) or w["event_time"][0] > args.limit or steps[0] != steps[1]
        if w["event_time"][0] >= worst_event[0]:
            worst_event = (w["event_time"][0], f"{n}: {w['event_time'][1]}")
        e = {k: errors(ref, r) for k, r in runs.items()}
        for r in args.chance_rtols + args.chance_tight:
            run_r = results[("chance", n, r)]
            if not run_r.get("ok"):
                print(f"| {n} | chance run at rtol {r:.9g} failed: {run_r.get('message')} | | | | | |")
                failed = True
                continue
            er = errors(ref, run_r)
            for i in (0, 1):
                chance_totals[r][i] = max(chance_totals[r][i], er[i])
                chance_logs[r][i] += math.log(max(er[i], 1e-9))
        counted += 1
        for k in totals:
            for i in (0, 1):
                totals[k][i] = max(totals[k][i], e[k][i])
                logs[k][i] += math.log(max(e[k][i], 1e-9))
        worse = []
        for tol in ("tight", "default"):
            for i, what in ((0, "element"), (1, "component")):
                ratios[(tol, i)].append(math.log(max(e[f"{tol} new"][i], 1e-9) / max(e[f"{tol} base"][i], 1e-9)))
                if e[f"{tol} new"][i] > 1.1 * e[f"{tol} base"][i] + 1e-9:
                    worse.append(f"{tol} {what}")
        failed = failed or bad
        cell = lambda k: f"{e[k][0]:.2e} / {e[k][1]:.2e}"
        print(f"| {n} | {steps[0]} / {steps[1]} | {w['event_time'][0]:.2e}{' ' + w['structure'] if w['structure'] else ''} |"
              f" {cell('tight base')} | {cell('tight new')} | {cell('default base')} | {cell('default new')}"
              f"{' WORSE: ' + ', '.join(worse) if worse else ''} |")
    print()
    print(f"largest event-time change at rtol {args.rtol:g}: {worst_event[0]:.3e} ({worst_event[1]})")
    for k, (el, co) in totals.items():
        g = [math.exp(v / max(counted, 1)) for v in logs[k]]
        print(f"{k}: largest error of the element peaks {el:.3e}, of the component peaks {co:.3e};"
              f" geometric means {g[0]:.3e}, {g[1]:.3e}")
    # The chance band of each tolerance: BASE's own errors with its steps moved.
    band = {tol: {"largest": list(totals[f"{tol} base"]), "mean": [0.0, 0.0]} for tol in ("tight", "default")}
    for tol, rtols in (("tight", args.chance_tight), ("default", args.chance_rtols)):
        for r in rtols:
            g = [math.exp(v / max(counted, 1)) for v in chance_logs[r]]
            print(f"chance (BASE at rtol {r:.9g}): largest error of the element peaks {chance_totals[r][0]:.3e},"
                  f" of the component peaks {chance_totals[r][1]:.3e}; geometric means {g[0]:.3e}, {g[1]:.3e}")
            for i in (0, 1):
                b = band[tol]
                b["largest"][i] = max(b["largest"][i], chance_totals[r][i])
                b["mean"][i] = max(b["mean"][i], math.log(g[i] / math.exp(logs[f"{tol} base"][i] / max(counted, 1))))
    for tol in ("tight", "default"):
        for i, what in ((0, "element"), (1, "component")):
            base, new = totals[f"{tol} base"][i], totals[f"{tol} new"][i]
            if args.chance_rtols:
                base = band[tol]["largest"][i]  # the largest of BASE and of its chance runs
            if new > 1.1 * base + 1e-9:
                against = " (the largest of BASE and its chance runs)" if args.chance_rtols else ""
                print(f"FAIL: the largest {what} error at the {tol} tolerance grew{against}: {base:.3e} -> {new:.3e}")
                failed = True
            r = ratios[(tol, i)]
            mean = sum(r) / len(r) if r else 0.0
            # With chance runs, the geometric mean may grow as far as the chance runs' did.
            allowed = band[tol]["mean"][i] if args.chance_rtols else 0.0
            grew = mean > allowed + math.log(1.1)  # the geometric means' ratio exceeds 1.1 (and the chance's)
            se = math.sqrt(sum((x - mean) ** 2 for x in r) / (len(r) - 1) / len(r)) if len(r) > 1 else 0.0
            print(f"{tol} {what} errors: geometric mean of new / base {math.exp(mean):.3f}, standard error x"
                  f"{math.exp(se):.3f}; new larger in {sum(1 for x in r if x > 0)} of {len(r)} cases")
            # With --steps-may-change each case's error moves by chance with its steps (a
            # perturbation of the base's rtol by 1e-6 moves the geometric means by up to 19 %,
            # about one standard error): the growth must also exceed two standard errors.
            significant = not args.steps_may_change or mean > 2 * se
            if grew and significant:
                beyond = " beyond the chance runs'" if allowed > 0 else ""
                print(f"FAIL: the geometric mean of the {what} errors at the {tol} tolerance grew by more than 10 %{beyond}")
                failed = True
            elif grew:
                print(f"note: the geometric mean of the {what} errors at the {tol} tolerance grew by more than 10 %,"
                      " within two standard errors of the steps' chance")
    print("result:", "FAIL" if failed else "ok")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
