#!/usr/bin/env python3
"""Compares the design-load envelopes of campaigns of one project at two tolerances (issue 26
item 6) and prints Markdown tables: per component class the largest relative difference of the
envelope (|torque| at the tolerance against |torque| at the reference tolerance), the runs with
negative dissipation, the failed runs, and the largest factor by which a rupture's simulated
load-path peak exceeded its capped single-DOF estimate.

    compare_envelopes.py PROJECT.json REFERENCE_DIR OTHER_DIR [OTHER_DIR...]

Each DIR is a campaign's --out directory (campaign.sqlite); the reference is the converged one
(e.g. --rtol 1e-8). The envelopes are taken over the runs that succeeded in every campaign given
(a run failing at one tolerance leaves the comparison; the table of campaigns counts them). A file DIR/time.txt ("<wall> wall <user> user <sys> sys", as
/usr/bin/time -f writes it) adds the cost. Exit 1 when an envelope differs by more than 1 %.
"""
import json
import os
import sqlite3
import sys

LIMIT = 0.01


def ok_runs(directory):
    db = sqlite3.connect(os.path.join(directory, "campaign.sqlite"))
    return {r[0] for r in db.execute("SELECT run FROM runs WHERE status = 'ok'")}


def load(directory, runs=None):
    """The campaign's numbers; its envelope over `runs` only (None: every successful run)."""
    db = sqlite3.connect(os.path.join(directory, "campaign.sqlite"))
    meta = dict(db.execute("SELECT key, value FROM campaign"))
    envelope = {}
    for run, component, torque, case, sample in db.execute(
            "SELECT p.run, p.component, p.torque, c.name, r.sample FROM component_peaks p JOIN runs r ON r.run = p.run "
            "JOIN cases c ON c.case_index = r.case_index WHERE r.status = 'ok' ORDER BY p.run"):
        if runs is not None and run not in runs:
            continue
        if component not in envelope or abs(torque) > abs(envelope[component][0]):
            envelope[component] = (torque, case, sample)
    runs = db.execute("SELECT count(*) FROM runs").fetchone()[0]
    failed = db.execute("SELECT count(*) FROM runs WHERE status != 'ok'").fetchone()[0]
    not_passive = db.execute("SELECT count(*) FROM passivity WHERE violations > 0").fetchone()[0]
    elements = [r[0] for r in db.execute("SELECT report FROM passivity WHERE violations > 0 LIMIT 5")]
    cap = max(((peak / sdof, name, sample, comp) for peak, sdof, name, sample, comp in db.execute(
        "SELECT r.peak, r.single_dof, c.name, r.sample, r.peak_component FROM runs r JOIN cases c "
        "ON c.case_index = r.case_index WHERE r.status = 'ok' AND c.kind = 'rupture' AND r.single_dof > 0")),
        default=None)
    over = db.execute("SELECT count(*) FROM runs r JOIN cases c ON c.case_index = r.case_index WHERE r.status = 'ok' "
                      "AND c.kind = 'rupture' AND r.single_dof > 0 AND r.peak > r.single_dof").fetchone()[0]
    ruptures = db.execute("SELECT count(*) FROM runs r JOIN cases c ON c.case_index = r.case_index WHERE "
                          "r.status = 'ok' AND c.kind = 'rupture' AND r.single_dof > 0").fetchone()[0]
    cost = None
    try:
        words = open(os.path.join(directory, "time.txt")).read().split()
        cost = (float(words[0]), float(words[2]) + float(words[4]))
    except (OSError, IndexError, ValueError):
        pass
    return dict(meta=meta, envelope=envelope, runs=runs, failed=failed, not_passive=not_passive, elements=elements,
                cap=cap, over=over, ruptures=ruptures, cost=cost)


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    project = json.load(open(sys.argv[1]))
    kind = {c["id"]: c["type"] for c in project["components"]}
    # The envelopes are compared over the runs that succeeded in every campaign (the same points).
    common = ok_runs(sys.argv[2])
    for d in sys.argv[3:]:
        common &= ok_runs(d)
    reference = load(sys.argv[2], common)
    others = [load(d, common) for d in sys.argv[3:]]
    ok = True
    print("| campaign | model | rtol | runs | failed | negative dissipation | wall [s] | CPU [s] |")
    print("|---|---|---|---|---|---|---|---|")
    for c in [reference] + others:
        m = c["meta"]
        cost = c["cost"] or ("-", "-")
        print(f"| {m['campaign_id']} | {m['model']} | {m.get('relative_tolerance', '?')} | {c['runs']} | {c['failed']} | "
              f"{c['not_passive']} | {cost[0]} | {cost[1]:.0f} |" if c["cost"] else
              f"| {m['campaign_id']} | {m['model']} | {m.get('relative_tolerance', '?')} | {c['runs']} | {c['failed']} | "
              f"{c['not_passive']} | - | - |")
        for e in c["elements"]:
            print(f"|   | negative dissipation: {e} | | | | | | |")
    print()
    print(f"Envelopes over the {len(common)} runs that succeeded in every campaign compared.")
    print()
    for c in others:
        rt, rr = c["meta"].get("relative_tolerance"), reference["meta"].get("relative_tolerance")
        print(f"Envelope at rtol {rt} against rtol {rr} ({c['meta']['model']} model): per component class, the largest "
              f"| |torque(rtol {rt})| / |torque(rtol {rr})| - 1 |:")
        print()
        print("| class | components | largest difference | component | at rtol " + rt + " [N*m] | at rtol " + rr +
              " [N*m] | case, sample (" + rt + ") |")
        print("|---|---|---|---|---|---|---|")
        classes = {}
        for component, (torque, case, sample) in c["envelope"].items():
            ref = reference["envelope"].get(component)
            if ref is None:
                print(f"| {kind.get(component, '?')} | missing in the reference: {component} | | | | | |")
                ok = False
                continue
            # Components that carry no torque in either (a joint whose torque is not resolved) agree.
            d = 0.0 if torque == 0 and ref[0] == 0 else abs(abs(torque) / abs(ref[0]) - 1) if ref[0] != 0 else float("inf")
            k = kind.get(component, "?")
            n, worst = classes.get(k, (0, None))
            if worst is None or d > worst[0]:
                worst = (d, component, abs(torque), abs(ref[0]), f"{case}, {sample}")
            classes[k] = (n + 1, worst)
            ok = ok and d <= LIMIT
        for k in sorted(classes):
            n, (d, component, a, b, where) = classes[k]
            print(f"| {k} | {n} | {100 * d:.3f} % | {component} | {a:.1f} | {b:.1f} | {where} |")
        print()
    for c in [reference] + others:
        if c["cap"]:
            f, name, sample, comp = c["cap"]
            print(f"Rupture cap ({c['meta']['model']}, rtol {c['meta'].get('relative_tolerance')}): {c['over']} of "
                  f"{c['ruptures']} rupture runs above their capped single-DOF estimate; largest factor {f:.4f} "
                  f"({name}, sample {sample}, at {comp})")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
