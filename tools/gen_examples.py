#!/usr/bin/env python3
"""Generates the bundled example projects examples/*.json from the estimates of
../shared/reference/domain.md (sections 3, 4 and 5), the infeasible variant included.

The examples are committed; this script documents how they were built and regenerates them:

    python3 tools/gen_examples.py            # writes examples/a380_class_flaps.json, ...
    python3 tools/gen_examples.py --check    # exits 1 when a committed example differs

Every parameter value carries its domain.md tag in its note (P published, P-low weak source,
E engineering estimate). Both wings are built from one description of the left wing, mirrored
about the PDU: ids end in _left/_right or carry l/r (shaft_l1, gra_r3, ...).
"""

import argparse
import json
import math
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
EXAMPLES = ROOT / "examples"


LIMIT_NOTE = ("estimate (E), the catalogue rule: actuator output side, 2.5 x the rated output torque; a jam "
              "passes the station limiter's end stop, up to 1.6 x 1.25 x 1.1 = 2.2 x the operating torque "
              "(domain.md s6)")


def q(value, note, lo=None, hi=None):
    """A quantity in the object form with its provenance note (domain.md tag)."""
    out = {}
    if value is not None:
        out["value"] = value
    if lo is not None:
        out["min"] = lo
    if hi is not None:
        out["max"] = hi
    out["note"] = note
    return out


def fmt(x, digits=4):
    """A number with `digits` significant digits, without trailing noise."""
    return float(f"{x:.{digits}g}")


class Builder:
    """Collects components and connections of one project."""

    def __init__(self):
        self.components = []
        self.connections = []
        self.ids = set()

    def add(self, cid, ctype, description, parameters=None, labels=None):
        assert cid not in self.ids, cid
        self.ids.add(cid)
        c = {"id": cid, "type": ctype, "description": description}
        if labels:
            c["labels"] = labels
        if parameters:
            c["parameters"] = parameters
        self.components.append(c)
        return cid

    def connect(self, a, b):
        self.connections.append([a, b])


# ----------------------------------------------------------------------------------------------
# Speed profile: 0 -> w_max in t_ramp, hold, 0.25 x w_max for the last 3 % of travel, stop.

def speed_profile(w_max, travel, t_ramp=0.4, t_slow_down=0.2, t_stop=0.1, slow_fraction=0.03,
                  slow_factor=0.25):
    """Points [t, w] (s, rad/s) of the PDU speed that covers `travel` rad of shaft rotation."""
    w_slow = slow_factor * w_max
    slow_angle = slow_fraction * travel
    ramp_angle = 0.5 * w_max * t_ramp
    down_angle = 0.5 * (w_max + w_slow) * t_slow_down
    stop_angle = 0.5 * w_slow * t_stop
    hold_angle = travel - slow_angle - ramp_angle - down_angle
    assert hold_angle > 0
    t1 = t_ramp
    t2 = t1 + hold_angle / w_max
    t3 = t2 + t_slow_down
    t4 = t3 + (slow_angle - stop_angle) / w_slow
    t5 = t4 + t_stop
    pts = [[0.0, 0.0], [t1, w_max], [t2, w_max], [t3, w_slow], [t4, w_slow], [t5, 0.0]]
    return [[fmt(t, 6), fmt(w, 5)] for t, w in pts], t5


def table_time(points, unit):
    return {"against": "time", "unit": unit, "points": points}


def table_position(points, unit):
    return {"against": "position", "unit": unit, "points": points}


# ----------------------------------------------------------------------------------------------
# Tubes

def tube_capacity_expression(shaft):
    """Ultimate torque of a tube, min(tau_allow, tau_cr) * Ip / (D/2) with tau_cr its torsional
    buckling stress: the network's derived <shaft>.torque_capacity (docs/optimize.md)."""
    return f"{shaft}.torque_capacity"


def shaft_parameters(length, D_mm, t_mm, geometry_note, material, x):
    p = {
        "length": q(f"{fmt(length)} m", geometry_note),
        "outer_diameter": q(f"{D_mm} mm", geometry_note),
        "wall_thickness": q(f"{t_mm} mm", geometry_note + "; +-0.1 mm (domain.md s3 suggested domain)",
                            f"{fmt(t_mm - 0.1)} mm", f"{fmt(t_mm + 0.1)} mm"),
    }
    p.update(material)
    p["span_position"] = q(f"{fmt(x)} m", geometry_note + ": mid-span of the segment")
    return p


TITANIUM = {
    "shear_modulus": q("44 GPa", "Ti-6Al-4V, domain.md s1/s6 (P-low): G 43-51 GPa", "43 GPa", "51 GPa"),
    "density": q("4420 kg/m^3", "Ti-6Al-4V, domain.md s1 (P)"),
    "allowable_shear_stress": q("550 MPa", "Ti-6Al-4V ultimate shear, domain.md s6 (E)", "500 MPa",
                                "600 MPa"),
}


def titanium(drag_per_metre, wing_length, component_drag, tag, why):
    """The tube material with the drag of the bearings and joints along the shaft.

    domain.md s3 books every no-load loss along a wing as one drag per metre of shaft (0.2-0.3 N m
    per metre, domain [0.1, 0.5]); the examples give the steady bearings, the gearboxes and the
    actuators their own Stribeck drag, so the tubes carry the rest: the wing's total stays
    `drag_per_metre` x `wing_length` (N m, referred to the shaft). `component_drag` is the sum of
    the components' Coulomb torques referred to the shaft."""
    own = component_drag / wing_length
    out = dict(TITANIUM)
    out["drag_per_length"] = q(
        f"{fmt(drag_per_metre - own, 3)} N*m/m",
        f"{tag}: {why}: {fmt(drag_per_metre)} N m per metre over the {fmt(wing_length)} m wing = "
        f"{fmt(drag_per_metre * wing_length, 3)} N m at the shaft, less the {fmt(component_drag, 3)} N m "
        "of the bearings, gearboxes and actuators given as components; domain [0.1, 0.5] N m/m in all "
        "(the shaft's share at least 0)",
        f"{fmt(max(0.0, 0.1 - own), 3)} N*m/m", f"{fmt(0.5 - own, 3)} N*m/m")
    return out


def sci(x):
    """A small inertia as domain.md writes it: 6.25e-4, 1e-3, 0.0388."""
    if abs(x) >= 1e-2:
        return f"{x:.3g}"
    mantissa, exponent = f"{x:.3e}".split("e")
    return f"{mantissa.rstrip('0').rstrip('.')}e{int(exponent)}"


def station_inertias(tag, ratio, station_input, flap, limiter, actuator):
    """Inertias of a station (branch gearbox + limiter + actuator) from domain.md's values at the
    shaft: `station_input` (gearbox, limiter and actuator input together) and `flap` (the surface
    reflected to the shaft), both kg m2 at shaft speed. The gearbox's inertia counts at its input
    (the shaft); the limiter's and the actuator's behind the station gearbox of `ratio`, where an
    inertia reads ratio^2 times its shaft-side value. `limiter` and `actuator` are given on their
    own side (actuator input); the gearbox takes the rest of `station_input`."""
    r2 = ratio * ratio
    gearbox_J = station_input - (limiter + actuator) / r2
    assert gearbox_J > 0, (station_input, limiter, actuator, ratio)
    split = (f"station input {sci(station_input)} kg m2 at the shaft = gearbox "
             f"{sci(gearbox_J)} + (limiter {sci(limiter)} + actuator input {sci(actuator)}) "
             f"/ {fmt(ratio, 3):g}^2")
    return {
        "gearbox": q(f"{sci(gearbox_J)} kg*m^2", f"{tag}: shaft side; {split}"),
        "limiter": q(f"{sci(limiter)} kg*m^2", f"{tag}: actuator input side; {split}"),
        "actuator": actuator,
        "flap": q(f"{sci(flap * r2)} kg*m^2",
                  f"{tag}: flap {sci(flap)} kg m2 at the shaft = {sci(flap * r2)} at the actuator "
                  f"input (x {fmt(ratio, 3):g}^2 behind the {fmt(ratio, 3):g}:1 station gearbox)"),
    }


# domain.md s3: "efficiencies GRA+station eta_opposing 0.85, eta_aiding 0.70": the station gearbox's
# losses are inside the actuator's efficiency, and the wing's root torque (360 N m = 6 x 58.8 N m +
# drag) carries no further mesh or joint loss: the other no-load losses are the drag per metre.
def lossless(tag, what):
    return q(1, f"{tag}: {what}; its losses are counted elsewhere (GRA + station efficiency 0.85/0.70 "
             "and the bearings-and-joints drag per metre of domain.md s3), so not twice here")


def shaft_gearbox(tag, what, ratio, inertia, **more):
    """A root or station gearbox on the shaft: lossless (see lossless), its inertia and its 0.1 N m
    no-load drag on the shaft side."""
    out = {"ratio": ratio}
    out.update(more)
    out["eta_mesh"] = lossless(tag, what)
    out["inertia"] = inertia
    out["coulomb_torque"] = q("0.1 N*m", f"{tag}: shaft side, part of the drag budget of the wing")
    return out


def with_x(parameters, x, note):
    out = dict(parameters)
    out["span_position"] = q(f"{fmt(x)} m", note)
    return out


# ----------------------------------------------------------------------------------------------
# A drive wing: the stations along one wing, mirrored for both wings.

def build_wing(b, side, spec):
    """Adds one wing (side 'left' or 'right') from `spec` and returns a dict of useful ids.

    The span position is negative on the left wing (body axis y points to starboard).

    spec keys:
      tag            note for values of this data set (e.g. 'domain.md s3 (E)')
      root_x         span position of the root gearbox [m]
      stations       span positions of the stations [m]
      wtb_x          span position of the wing-tip brake [m]
      tube(x0, x1)   -> (D_mm, t_mm) of the segment between x0 and x1
      split_length   segments at least this long get a steady bearing at mid-span
      joint_at_root  add a universal joint between the STL and the first shaft
      stl, joint, bearing, rgb, station_gearbox, limiter, gra, wtb, appu, material: parameters
    """
    s = side[0]  # 'l' or 'r'
    sign = -1.0 if side == "left" else 1.0
    tag = spec["tag"]
    xnote = f"{tag}: x along the span, negative on the left wing"
    ids = {"stations": [], "gras": [], "shafts": [], "segments": []}
    stl = b.add(f"stl_{side}", "system_torque_limiter",
                f"system torque limiter at the {side} PDU output",
                with_x(spec["stl"], sign * 0.3, xnote), {"side": side})
    ids["stl"] = stl
    previous = f"{stl}.output"
    if spec.get("joint_at_root"):
        uj = b.add(f"ujoint_{side}", "universal_joint",
                   f"universal joint at the {side} wing root (fuselage to wing)",
                   with_x(spec["joint"], sign * 0.5, xnote), {"side": side})
        b.connect(previous, f"{uj}.a")
        previous = f"{uj}.b"

    nodes = [("rgb", spec["root_x"])] + [(f"s{i + 1}", x) for i, x in enumerate(spec["stations"])] \
        + [("wtb", spec["wtb_x"])]
    x_previous = 0.0
    for segment, (node, x) in enumerate(nodes):
        length = x - x_previous
        D, t = spec["tube"](x_previous, x)
        inboard = "PDU" if segment == 0 else nodes[segment - 1][0].upper()
        where = f"{inboard}-{node.upper()}"
        geometry_note = f"{tag}: segment {where}, {fmt(length)} m, tube {D} x {t} mm"
        pieces = 2 if length >= spec["split_length"] - 1e-9 else 1
        names = [f"shaft_{s}{segment}"] if pieces == 1 else \
            [f"shaft_{s}{segment}a", f"shaft_{s}{segment}b"]
        ids["segments"].append(names)
        for k, name in enumerate(names):
            part = "" if pieces == 1 else (" (inboard half)" if k == 0 else " (outboard half)")
            x_mid = x_previous + (k + 0.5) * length / pieces
            b.add(name, "torque_shaft",
                  f"{side} wing torque shaft {where}{part}: titanium tube {D} x {t} mm",
                  shaft_parameters(length / pieces, D, t, geometry_note, spec["material"],
                                   sign * x_mid),
                  {"side": side, "segment": str(segment)})
            ids["shafts"].append(name)
            b.connect(previous, f"{name}.a")
            previous = f"{name}.b"
            if k == 0 and pieces == 2:
                brg = b.add(f"brg_{s}{segment}", "steady_bearing",
                            f"steady bearing at mid-span of segment {where}",
                            with_x(spec["bearing"], sign * (x_previous + length / 2), xnote),
                            {"side": side, "segment": str(segment)})
                b.connect(previous, f"{brg}.a")
                previous = f"{brg}.b"
        if node == "rgb":
            rgb = b.add(f"rgb_{side}", "angle_gearbox", f"{side} {spec['rgb_name']}",
                        with_x(spec["rgb"], sign * x, xnote), {"side": side})
            ids["rgb"] = rgb
            b.connect(previous, f"{rgb}.input")
            previous = f"{rgb}.output"
        elif node == "wtb":
            wtb = b.add(f"wtb_{side}", "wing_tip_brake",
                        f"{side} wing-tip brake, outboard of the last station",
                        with_x(spec["wtb"], sign * x, xnote), {"side": side})
            ids["wtb"] = wtb
            b.connect(previous, f"{wtb}.a")
            appu = b.add(f"appu_{side}", "position_sensor",
                         f"{side} asymmetry position pick-off unit (APPU) at the shaft end",
                         with_x(spec["appu"], sign * (x + 0.1), xnote), {"side": side})
            ids["appu"] = appu
            b.connect(f"{wtb}.b", f"{appu}.a")
        else:
            i = int(node[1:])
            station = f"{s}{i}"
            labels = {"side": side, "station": str(i)}
            tgb = b.add(f"tgb_{station}", "branch_gearbox",
                        f"station {station} gearbox (down-drive) at |x| = {fmt(x)} m",
                        with_x(spec["station_gearbox"], sign * x, xnote), labels)
            lim = b.add(f"stl_{station}", "station_torque_limiter",
                        f"station {station} torque limiter",
                        with_x(spec["limiter"], sign * x, xnote), labels)
            gra = b.add(f"gra_{station}", "geared_rotary_actuator",
                        f"station {station} geared rotary actuator",
                        with_x(spec["gra"], sign * x, xnote), labels)
            b.connect(previous, f"{tgb}.input")
            b.connect(f"{tgb}.branch", f"{lim}.input")
            b.connect(f"{lim}.output", f"{gra}.input")
            previous = f"{tgb}.through"
            ids["stations"].append(station)
            ids["gras"].append(gra)
        x_previous = x
    return ids


# ----------------------------------------------------------------------------------------------
# Load cases, scenarios and requirements shared by the examples

def load_cases(d, gras):
    w_max = d["w_max"]
    travel = d["revolutions"] * 2 * math.pi
    points, duration = speed_profile(w_max, travel)
    extend_loads = {g: table_position(d["extend_load"], ["1", "kN*m"]) for g in gras}
    retract_loads = {g: table_position([[x, -y] for x, y in d["extend_load"]], ["1", "kN*m"])
                     for g in gras}
    tag = d["tag"]
    values = {"travel": f"{fmt(travel, 5)} rad", "max_shaft_speed": f"{fmt(w_max)} rad/s"}
    cases = [
        {"name": "extend_opposing",
         "description": (
             f"Full extension (0 -> 1 of travel) against the opposing airload. PDU output speed: "
             f"0 -> w_max = {fmt(w_max)} rad/s in 0.4 s, hold, 0.25 x w_max for the last 3 % of "
             f"the {d['revolutions']} shaft revolutions of full travel, stop in 0.1 s on the "
             f"pressure-off brakes; {fmt(duration, 3)} s in all. Airload per actuator (output "
             f"torque, positive opposing the motion) rising with position to "
             f"{fmt(d['extend_load'][-1][1])} kN*m at full travel. {tag}."),
         "direction": "extend",
         "pdu_speed": table_time(points, ["s", "rad/s"]),
         "actuator_loads": extend_loads,
         "values": values},
        {"name": "retract_aiding",
         "description": (
             "Full retraction (1 -> 0 of travel) with the airload aiding the motion (negative = "
             "aiding), the same magnitude as extend_opposing at each position. Same speed "
             f"profile (speeds are magnitudes in the commanded direction). {tag}."),
         "direction": "retract",
         "pdu_speed": table_time(points, ["s", "rad/s"]),
         "actuator_loads": retract_loads,
         "values": values},
    ]
    return cases, duration


def scenarios(stations, duration, rupture_component, rgb, first_left_station):
    out = [{"name": "extension", "kind": "extension",
            "description": "Normal extension cycle against the opposing airload.",
            "load_case": "extend_opposing", "stop_time": f"{math.ceil(duration + 1)} s",
            "output_interval": "10 ms"}]
    for st in stations:
        out.append({"name": f"jam_{st}", "kind": "jam",
                    "description": (f"Jam of the actuator at station {st} at 1 s, at full speed "
                                    "while extending against the opposing load (CS 25.701(d), "
                                    "domain.md s2): the drive's kinetic energy goes into shaft "
                                    "twist until the station limiter, the STL and the PDU stop it."),
                    "load_case": "extend_opposing", "stop_time": "2 s",
                    "jam": {"component": f"gra_{st}", "time": "1 s"}})
    out.append({"name": "rupture_wtb", "kind": "rupture",
                "description": (f"Rupture of {rupture_component} (between the left root gearbox "
                                f"{rgb} and station {first_left_station}) at 1 s while extending "
                                "against the opposing load; the outboard shaft is back-driven by "
                                "the airload until the monitor (asymmetry/overspeed) fires the "
                                "wing-tip brakes (domain.md s2)."),
                "load_case": "extend_opposing", "stop_time": "3 s",
                "rupture": {"component": rupture_component, "time": "1 s"},
                "wtb": {"trigger": "monitor"}})
    return out


def requirement(rid, expression, description):
    return {"id": rid, "expression": expression, "description": description}


def requirements(wings, stations, d):
    n = d["numbers"]
    tag = d["tag"]
    reqs = []
    for side in ("left", "right"):
        w = wings[side]
        wtb_torque = max(n["root"], n["backdrive"])
        reqs.append(requirement(
            f"wtb_capacity_{side}", f"{w['wtb']}.static_capacity >= 1.5 * {wtb_torque} N*m",
            f"WTB static capacity at least 1.5 x the larger of the wing's opposing operating torque "
            f"({n['root']} N*m) and its back-drive torque (about {n['backdrive']} N*m), {tag}; "
            "domain.md s6"))
    for side in ("left", "right"):
        w = wings[side]
        reqs.append(requirement(
            f"stl_setting_min_{side}",
            f"{w['stl']}.lockout_torque_extend >= 1.2 * {n['root']} N*m",
            f"STL trips above 1.2 x the maximum operating wing torque ({n['root']} N*m); "
            "domain.md s6 (E) 1.2-1.4"))
        reqs.append(requirement(
            f"stl_setting_max_{side}",
            f"{w['stl']}.lockout_torque_extend <= 1.4 * {n['root']} N*m",
            f"STL trips below 1.4 x the maximum operating wing torque ({n['root']} N*m); "
            "domain.md s6 (E) 1.2-1.4"))
    for st in stations:
        reqs.append(requirement(
            f"station_limiter_{st}",
            f"stl_{st}.lockout_torque_extend >= 1.3 * {n['station']} N*m * {n.get('limiter_ratio', 1)}",
            f"station limiter trips above 1.3 x the maximum operating station input torque "
            f"({n['station']} N*m at the shaft, x {n.get('limiter_ratio', 1)} for the gearbox "
            "ahead of the limiter); domain.md s6 (E) 1.3-1.6"))
    reqs.append(requirement(
        "extension_time", f"travel_time.extension <= {n['time']} s",
        f"full extension within {n['time']} s ({tag})"))
    for st in stations:
        side = "left" if st[0] == "l" else "right"
        segment = wings[side]["segments"][wings[side]["stations"].index(st) + 1][-1]
        reqs.append(requirement(
            f"jam_{st}_shaft", f"1.5 * peak.jam_{st}.{segment} <= {tube_capacity_expression(segment)}",
            f"peak torque in the shaft inboard of station {st} during a jam there, times the "
            "factor of safety 1.5 (CS 25.303), stays below the tube's torque capacity "
            "min(tau_allow, tau_cr) * Ip / (D/2), tau_cr its torsional buckling stress"))
    last = wings["left"]["shafts"][-1]
    reqs.append(requirement(
        "rupture_wtb_shaft", f"1.5 * peak.rupture_wtb.{last} <= {tube_capacity_expression(last)}",
        "peak torque in the outboard shaft when the left WTB stops the back-driven shaft after "
        "the rupture, times 1.5, stays below the tube's torque capacity (shear or torsional buckling)"))
    # No requirement compares the rupture's peak with the WTB's static capacity: the peak at the
    # brake is its own friction torque (the single-DOF estimate is capped there, where the brake
    # slips), and holding the wing afterwards is the static requirement wtb_capacity_<side> above.
    return reqs


def build_project(d):
    b = Builder()
    b.add("pdu", "pdu", d["pdu_description"], d["pdu"])
    wings = {side: build_wing(b, side, d["wing"]) for side in ("left", "right")}
    fppu = b.add("fppu", "position_sensor",
                 "feedback position pick-off unit (FPPU) at the PDU, on its left output",
                 d["fppu"])
    b.connect("pdu.left", f"{fppu}.a")
    b.connect(f"{fppu}.b", f"{wings['left']['stl']}.input")
    b.connect("pdu.right", f"{wings['right']['stl']}.input")

    stations = wings["left"]["stations"] + wings["right"]["stations"]
    gras = wings["left"]["gras"] + wings["right"]["gras"]
    cases, duration = load_cases(d, gras)
    rupture = wings["left"]["segments"][1][0]
    scen = scenarios(stations, duration, rupture, wings["left"]["rgb"], wings["left"]["stations"][0])
    return {
        "format": "highlift-project/1",
        "name": d["name"],
        "description": d["description"],
        "sources": d["sources"],
        # 1e-5: the transient peaks of all 36 sizing cases agree with 1e-6 to 4e-4 (docs/performance.md).
        "settings": {"shaft_elements": 4, "relative_tolerance": 1e-5, "output_interval": "1 ms"},
        "components": b.components,
        "connections": b.connections,
        "requirements": requirements(wings, stations, d),
        "load_cases": cases,
        "scenarios": scen,
    }


def pm10(value, unit, note):
    """value +- 10 % (limiter trips, domain.md s3)."""
    return q(f"{fmt(value)} {unit}", note + "; +-10 %", f"{fmt(0.9 * value)} {unit}",
             f"{fmt(1.1 * value)} {unit}")


def stl_end_stop_and_brake(lockout, E):
    """The end stop (1.25 x, +-10 %) and friction brake (2 x) of a system torque limiter of
    lock-out `lockout` N m, by the catalogue's rules: its defaults are those of the 470 N m
    A380-class limiter, and every analysis passes the end-stop torque on to a jam
    (docs/reduced_models.md, "The system torque limiter in a jam")."""
    return {
        "end_stop_torque": pm10(1.25 * lockout, "N*m", f"{E}: 1.25 x the {fmt(lockout)} N m lock-out "
                                "torque (catalogue rule for the end stop of figure 4 in the paper)"),
        "max_brake_torque": q(f"{fmt(2 * lockout)} N*m", f"{E}: 2 x the {fmt(lockout)} N m lock-out "
                              "torque (catalogue rule)"),
    }


def station_limiter(extend, tag, derivation):
    """The trip, end-stop and brake torques of a station limiter on its own side (the actuator
    input): lock-out `extend` N m (+-10 %), retract 0.7 x extend (domain.md s3, asymmetric limiter
    s1 P), end stop 1.25 x and friction brake 2 x the lock-out torque (the catalogue's rules)."""
    return {
        "lockout_torque_extend": pm10(extend, "N*m", f"{tag}: actuator input side, {derivation}"),
        "lockout_torque_retract": pm10(0.7 * extend, "N*m", "domain.md s3 (E) rule: 0.7 x extend "
                                       "(asymmetric limiter, domain.md s1 P)"),
        "end_stop_torque": pm10(1.25 * extend, "N*m", f"{tag}: 1.25 x the {fmt(extend)} N m lock-out "
                                "torque (catalogue rule for the end stop of figure 4 in the paper)"),
        "max_brake_torque": q(f"{fmt(2 * extend)} N*m", f"{tag}: 2 x the {fmt(extend)} N m lock-out "
                              "torque (catalogue rule)"),
    }


def sensors(tag, role):
    return {
        "role": role,
        "asymmetry_threshold": q("2 rev", f"{tag}: asymmetry trigger 1-3 shaft revolutions", "1 rev",
                                 "3 rev"),
        "overspeed_factor": q(1.3, f"{tag}: overspeed trigger 1.3 x w_max"),
    }


COMMON_SOURCES = [
    "domain.md s1 (P): published architecture facts of A318-A321 and A330 high-lift systems",
    "domain.md s1 (P-low): Ti-6Al-4V shear modulus 43-51 GPa; hydraulic pressures",
    "domain.md s2 (P): certification cases (CS 25.701, 25.303) behind the scenarios and the "
    "factor of safety 1.5",
    "domain.md s6 (P/E): seed ranges for components",
]


# ----------------------------------------------------------------------------------------------
# A380-class flaps, domain.md section 3

def a380_flaps():
    E = "domain.md s3 (E)"
    station_gearbox_ratio = 2.0
    gra_ratio = 200.0
    inboard, outboard = (50, 2.0), (45, 1.8)
    # Station node of domain.md s3 at shaft speed: station input 1e-3 + reflected flap 9.7e-3 (+ the
    # shaft halves, which the tubes carry). The GRA input J about 1e-3 of s6 is on the actuator side.
    station = station_inertias(E, station_gearbox_ratio, 1e-3, 9.7e-3, 5e-4, 1e-3)
    # No-load drags referred to the shaft, per wing: 5 steady bearings x 0.1, 6 station gearboxes
    # x 0.1, 6 GRAs x 0.2 / 2, the root gearbox 0.1.
    component_drag = 5 * 0.1 + 6 * 0.1 + 6 * 0.2 / station_gearbox_ratio + 0.1
    wing = {
        "tag": E,
        "root_x": 4.0,
        "stations": [7.0, 10.5, 14.0, 17.5, 21.0, 24.0],
        "wtb_x": 25.5,
        "tube": lambda x0, x1: inboard if x1 <= 14.0 + 1e-9 else outboard,
        "split_length": 3.5,
        "joint_at_root": True,
        "material": titanium(0.25, 25.5, component_drag, E,
                             "bearings and joints 0.2-0.3 N m per metre, root torque about 360 N m = 6 x 58.8 "
                             "N m + drag"),
        "rgb_name": "root (kink) gearbox",
        "stl": {
            "lockout_torque_extend": pm10(470, "N*m", f"{E}: shaft side, 1.3 x 360 N m root torque"),
            "lockout_torque_retract": pm10(470, "N*m", f"{E}: symmetric STL"),
        },
        "joint": {
            "efficiency": lossless(E, "universal joint at the wing root"),
            "inertia": q("2e-4 kg*m^2", "domain.md s6 (E): 1e-4 to 3e-4 kg m2", "1e-4 kg*m^2",
                         "3e-4 kg*m^2"),
        },
        "bearing": {
            "coulomb_torque": q("0.1 N*m", "domain.md s6 (E): steady bearing drag 0.05-0.2 N m",
                                "0.05 N*m", "0.2 N*m"),
        },
        "rgb": shaft_gearbox(E, "kink gearbox", q(1, f"{E}: kink gearbox 1:1"),
                             q("2e-3 kg*m^2", f"{E}: shaft side; RGB node 4.7e-3 = gearbox 2e-3 + shaft halves")),
        "station_gearbox": shaft_gearbox(
            E, "station gearbox",
            q(station_gearbox_ratio, f"{E}: station ratio 400:1 = station gearbox 2:1 x GRA 200:1"),
            station["gearbox"]),
        # domain.md s3 sets the limiter at 1.5 x 58.8 = 90 N m on the shaft side; it sits behind
        # the 2:1 station gearbox, where the same setting reads 2 x 90 = 180 N m.
        "limiter": dict(station_limiter(180, E, "1.5 x 58.8 N m station input torque (90 N m at the "
                                        "shaft), x 2 behind the 2:1 station gearbox"),
                        inertia=station["limiter"]),
        "gra": {
            "ratio": q(gra_ratio, f"{E}: GRA 200:1 (s6: 100-300:1)"),
            "eta_opposing": q(0.85, f"{E}: GRA + station 0.85, domain [0.80, 0.90]", 0.80, 0.90),
            "eta_aiding": q(0.70, f"{E}: GRA + station 0.70, domain [0.60, 0.80]", 0.60, 0.80),
            "input_inertia": q("1e-3 kg*m^2", "domain.md s6 (E): actuator input side, GRA input J about "
                               "1e-3 kg m2", "5e-4 kg*m^2", "2e-3 kg*m^2"),
            "load_inertia": station["flap"],
            "coulomb_torque": q("0.2 N*m", f"{E}: actuator input side, part of the drag budget of the wing"),
            "output_torque_rating": q("20 kN*m", f"{E}: actuator output side, station output torque about "
                                      "20 kN m"),
            "limit_output_torque": q("50 kN*m", LIMIT_NOTE),
            "travel_angle": q("2.2 rad", f"{E}: 2.5 m stroke over 2.2 rad GRA output rotation"),
        },
        "wtb": {
            "static_capacity": q("600 N*m", f"{E}: at least 1.5 x 360 N m = 550 N m", "550 N*m",
                                 "700 N*m"),
            "max_dynamic_torque": q("550 N*m", f"{E}: 1.5 x 360 N m opposing wing torque, the larger of it "
                                    "and the back-drive torque",
                                    "500 N*m", "700 N*m"),
            "engagement_latency": q("100 ms", f"{E}: engagement 50-150 ms after the trigger",
                                    "50 ms", "150 ms"),
            "inertia": q("5e-4 kg*m^2", f"{E}: brake rotor 5e-4 kg m2"),
        },
        "appu": sensors(E, "appu"),
    }
    d = {
        "tag": E,
        "name": "A380-class flap transmission (both wings)",
        "description": (
            "The flap drive of a very large four-engine transport, both wings mirrored about the "
            "power drive unit on the centre line: a PDU with two hydraulic motors summed by a "
            "speed-summing differential, each held by a pressure-off brake; a system torque "
            "limiter (STL) at each PDU output; a root (kink) gearbox; 6 drive stations per wing "
            "(3 flap panels x 2), each a station gearbox (down-drive) + station torque limiter + "
            "geared rotary actuator (GRA); titanium torque tubes (50 x 2.0 mm inboard, 45 x 1.8 mm "
            "outboard, 51 m in all) with steady bearings at mid-span of the long segments; a "
            "wing-tip brake (WTB) outboard of station 6 and an APPU at each shaft end; an FPPU "
            "at the PDU. This is NOT A380 data: none is public. Every number is the engineering "
            "estimate (tag E) of ../shared/reference/domain.md section 3, scaled from published "
            "A320/A330 architecture facts (tag P, section 1) and first-principles sizing; the "
            "note of each value gives its tag and derivation, and values not given take the "
            "catalogue defaults (docs/components.md). Load cases: extension against an opposing "
            "airload and retraction with an aiding airload; scenarios: the normal extension, a "
            "jam at each of the 12 stations, and a shaft rupture inboard of station l1 followed "
            "by WTB application. Generated by tools/gen_examples.py."),
        "sources": COMMON_SOURCES + [
            "domain.md s3 (E): A380-class flap transmission, one wing (mirrored for both); the "
            "station, segment and load numbers"],
        "pdu_description": ("power drive unit on the centre line: two hydraulic motors summed by a "
                            "speed-summing differential, pressure-off brakes (domain.md s1 P, s3 E)"),
        "pdu": {
            "motor_count": {"value": 2, "note": "domain.md s1 (P): two motors summed by a differential"},
            "motor_inertia": q("3e-4 kg*m^2", f"{E}: per motor, domain [2, 4]e-4", "2e-4 kg*m^2",
                               "4e-4 kg*m^2"),
            "ratio": q(20, f"{E}: i_PCU = 20, motor speed / output speed"),
            "gear_inertia": q("0.02 kg*m^2", f"{E}: gears 0.02 kg m2 (PCU node 0.26 = 2 x 3e-4 x "
                              "20^2 + 0.02)"),
            "efficiency": q(0.90, f"{E}: PCU gearbox 0.90", 0.85, 0.95),
            "max_output_speed": q("25.3 rad/s", f"{E}: 242 rpm = 1.15 x the average speed"),
            "power": q("18 kW", f"{E}: about 18 kW for both wings"),
            "speed_ramp_time": q("0.4 s", f"{E}: 0 -> w_max in 0.3-0.5 s", "0.3 s", "0.5 s"),
            "brake_stop_time": q("0.1 s", f"{E}: stop with the POBs in about 0.1 s"),
            "supply_pressure": q("5000 psi", "domain.md s1 (P-low): A380 345 bar (5000 psi)"),
            "span_position": q("0 m", f"{E}: on the centre line"),
        },
        "fppu": with_x(sensors(E, "fppu"), -0.2, f"{E}: at the PDU"),
        "w_max": 25.3,
        "revolutions": 140,
        "extend_load": [[0, 5], [0.25, 8], [0.5, 12], [0.75, 16], [1, 20]],
        "wing": wing,
        "numbers": {"root": 360, "backdrive": 210, "station": 58.8, "time": 40, "limiter_ratio": 2},
    }
    return build_project(d)


# ----------------------------------------------------------------------------------------------
# The infeasible variant of the A380-class flaps: a design question without a solution

INFEASIBLE_FITTING = 868  # N*m, the station-1 shaft fittings of the requirement jam_l1_fitting


def a380_flaps_infeasible():
    project = a380_flaps()
    # The numbers of the description are what `highlift check` derives (tests/icsp pin them).
    project["name"] = "A380-class flap transmission, infeasible variant"
    project["description"] = (
        "The A380-class flap transmission of a380_class_flaps.json with two requirements that cannot "
        "be met together: full extension in 32 s, with the speed ramps of the load case, needs a PDU "
        "output speed of at least 30.3 rad/s, while a jam at station 1 must load the station-1 shaft "
        f"with at most {INFEASIBLE_FITTING} N*m, which (equation (1), tau = w sqrt(c* J*) = w w1 J*, "
        "plus at least 540.5 N*m of static drive torque through the system torque limiter, the low end of its end-stop torque) caps the PDU "
        "speed near 25.4 rad/s. `highlift check` exits 1 and names both requirements. The PDU speed is left "
        "open as a design domain of 20 to 32 rad/s. Generated by tools/gen_examples.py.")
    project["settings"] = dict(project["settings"], relative_tolerance=1e-6)
    pdu = next(c for c in project["components"] if c["id"] == "pdu")
    pdu["parameters"]["max_output_speed"] = q(
        "25.3 rad/s", "design domain for the trade-off: domain.md s3 (E) gives 25.3 rad/s (242 rpm)",
        "20 rad/s", "32 rad/s")
    for scenario in project["scenarios"]:
        if scenario["name"] == "extension":
            scenario.pop("output_interval", None)
    for r in project["requirements"]:
        if r["id"] == "extension_time":
            r["expression"] = "travel_time.extension <= 32 s"
            r["description"] = ("full extension within 32 s, speed ramps of the load case included (a "
                                "faster variant than the 40 s of the base project)")
    project["requirements"].append(requirement(
        "jam_l1_fitting", f"peak.jam_l1.shaft_l1 <= {INFEASIBLE_FITTING} N*m",
        f"the station-1 shaft fittings take at most {INFEASIBLE_FITTING} N*m in a jam at station 1 "
        "(dynamic peak of equation (1) plus the static drive torque through the system torque limiter)"))
    return project


# ----------------------------------------------------------------------------------------------
# A380-class flaps driven by the hydraulic PDU (issue 8, docs/hydraulics.md)

def hydraulic_pdu_flaps():
    E = "domain.md s3 (E)"
    project = a380_flaps()
    project["name"] = "A380-class flap transmission with a hydraulic PDU (both wings)"
    project["description"] = (
        "The A380-class flap transmission of a380_class_flaps.json driven by the hydraulic power "
        "drive unit: the 345 bar aircraft supply feeds, per motor, a servo valve that strokes a "
        "differential cylinder setting the displacement of a variable-displacement hydraulic "
        "motor (secondary control: the speed loop commands the displacement); the two motors "
        "are summed by the speed-summing differential and drive both wings through the PDU "
        "gearbox. The question it answers: does the hydraulic drive follow the speed profile "
        "against the opposing airload, and what does the shaft see when the left shaft ruptures "
        "and the WTB stops the back-driven outboard part? This is NOT A380 data; every number is "
        "the engineering estimate of ../shared/reference/domain.md (tags in the notes) and the "
        "hydraulic values not given take the catalogue defaults of the pdu (docs/components.md, "
        "docs/hydraulics.md). Scenarios: the normal extension and the rupture inboard of station "
        "l1 with WTB application. Generated by tools/gen_examples.py.")
    project["sources"] = project["sources"] + [
        "domain.md s1 (P-low): A380 hydraulic pressure 345 bar (5000 psi)",
        "domain.md s6 (P/E): hydraulic motors 4-13 cm3/rev, 207 or 345 bar, 4500-5000 rpm"]
    pdu = next(c for c in project["components"] if c["id"] == "pdu")
    pdu["description"] = ("hydraulic power drive unit on the centre line: two variable-displacement "
                          "motors on the 345 bar supply, each with servo valve and displacement "
                          "cylinder, summed by a speed-summing differential (docs/hydraulics.md)")
    pdu["parameters"]["drive"] = "hydraulic"
    pdu["parameters"]["supply_pressure"] = q("345 bar", "domain.md s1 (P-low): A380 345 bar (5000 psi)")
    pdu["parameters"]["motor_displacement"] = q(
        "5.4 cm^3/rev", f"{E}: two motors give the 1000 N m stall torque at the output through "
        "i = 20 and eta = 0.90 x 0.95 at 340 bar; within domain.md s6 4-13 cm3/rev, 4830 rpm at "
        "25.3 rad/s; the domain is the sized motor's +-9 % (the stall torque follows the "
        "displacement in every analysis: a 13 cm3/rev motor stalls the drive at 2.4 x)",
        "4.9 cm^3/rev", "5.9 cm^3/rev")
    keep = {"extension", "rupture_wtb"}
    project["scenarios"] = [s for s in project["scenarios"] if s["name"] in keep]
    project["requirements"] = [r for r in project["requirements"]
                               if "peak." not in r["expression"]
                               or any(f"peak.{k}." in r["expression"] for k in keep)]
    return project


# ----------------------------------------------------------------------------------------------
# Single-aisle (A320-class) flaps, domain.md section 4

def a320_flaps():
    E = "domain.md s4 (E)"
    tube = (38, 1.5)
    ratio = 1.5
    # Station nodes of domain.md s4 at shaft speed: 2.0-2.3e-3 kg m2 each, of which the shaft halves
    # (38 x 1.5 mm tube, 2.54e-4 kg m2 per metre) are 5.1-8.9e-4: the station's own 1.45e-3, taken
    # here as station input 6.1e-4 (gearbox 3e-4 + limiter and actuator behind 1.5:1) + flap 8.4e-4.
    station = station_inertias(E, ratio, 6.1e-4, 8.4e-4, 2e-4, 5e-4)
    flap = dict(station["flap"], min="1.2e-3 kg*m^2", max="2.6e-3 kg*m^2")
    # No-load drags referred to the shaft, per wing: 2 steady bearings x 0.05, 4 station gearboxes
    # x 0.1, 4 GRAs x 0.2 / 1.5, the root gearbox 0.1.
    component_drag = 2 * 0.05 + 4 * 0.1 + 4 * 0.2 / ratio + 0.1
    wing = {
        "tag": E,
        "root_x": 2.0,
        "stations": [3.0, 6.5, 10.0, 13.0],
        "wtb_x": 14.0,
        "tube": lambda x0, x1: tube,
        "split_length": 3.5,
        "joint_at_root": True,
        "material": titanium(0.2, 14.0, component_drag, E,
                             "root about 97 N m = 4 x 23.5 N m + drag (0.2 N m per metre, domain.md s3 "
                             "0.2-0.3)"),
        "rgb_name": "root gearbox",
        "stl": {
            "lockout_torque_extend": pm10(125, "N*m", f"{E}: shaft side, STL about 125 N m (1.3 x 97 N m)"),
            "lockout_torque_retract": pm10(125, "N*m", f"{E}: symmetric STL"),
            **stl_end_stop_and_brake(125, E),
            "inertia": q("5e-4 kg*m^2", f"{E}: scaled from the A380-class estimate"),
        },
        "joint": {
            "efficiency": lossless(E, "universal joint at the wing root"),
            "inertia": q("1e-4 kg*m^2", "domain.md s6 (E): 1e-4 to 3e-4 kg m2, small end",
                         "1e-4 kg*m^2", "3e-4 kg*m^2"),
        },
        "bearing": {
            "coulomb_torque": q("0.05 N*m", "domain.md s6 (E): steady bearing drag 0.05-0.2 N m, "
                                "small end for the smaller shaft", "0.05 N*m", "0.1 N*m"),
        },
        "rgb": shaft_gearbox(E, "root gearbox", q(1, f"{E}: root gearbox 1:1"),
                             q("1e-3 kg*m^2", f"{E}: shaft side; RGB node 1.4e-3 = gearbox 1e-3 + shaft halves")),
        "station_gearbox": shaft_gearbox(
            E, "station gearbox", q(ratio, f"{E}: station ratio 300:1 = offset gearbox 1.5:1 x GRA 200:1"),
            station["gearbox"]),
        # domain.md s4: "station limiter about 35 N m (input side)", i.e. 1.5 x 23.5 N m at the
        # station input on the shaft; behind the 1.5:1 offset gearbox it reads 1.5 x 35 = 52.5 N m.
        "limiter": dict(station_limiter(52.5, E, "about 35 N m at the station input (shaft side, 1.5 x "
                                        "23.5 N m), x 1.5 behind the 1.5:1 offset gearbox"),
                        inertia=station["limiter"]),
        "gra": {
            "ratio": q(200, f"{E}: station ratio 300:1 = 1.5:1 x GRA 200:1"),
            "eta_opposing": q(0.85, "domain.md s3/s6 (E): 0.85, domain [0.80, 0.90]", 0.80, 0.90),
            "eta_aiding": q(0.70, "domain.md s3/s6 (E): 0.70, domain [0.60, 0.80]", 0.60, 0.80),
            "input_inertia": q("5e-4 kg*m^2", f"{E}: actuator input side; station node 2.0-2.3e-3 kg m2 "
                               "at the shaft in all", "3e-4 kg*m^2", "1e-3 kg*m^2"),
            "load_inertia": flap,
            "coulomb_torque": q("0.2 N*m", f"{E}: actuator input side, part of the drag budget of the wing"),
            "output_torque_rating": q("6 kN*m", f"{E}: actuator output side, station output torque about "
                                      "6 kN m"),
            "limit_output_torque": q("15 kN*m", LIMIT_NOTE),
            "travel_angle": q("2.2 rad", f"{E}: 105 shaft revolutions / 300"),
        },
        "wtb": {
            "static_capacity": q("180 N*m", f"{E}: WTB at least 150 N m (1.5 x 97 N m opposing, larger "
                                 "than the back-drive torque)", "150 N*m", "220 N*m"),
            "max_dynamic_torque": q("150 N*m", f"{E}: WTB at least 150 N m", "130 N*m", "200 N*m"),
            "engagement_latency": q("100 ms", "domain.md s3/s6 (E): 50-150 ms", "50 ms", "150 ms"),
            "inertia": q("3e-4 kg*m^2", f"{E}: WTB node 4.3e-4 = rotor 3e-4 + shaft half"),
        },
        "appu": sensors("domain.md s1 (P) APPU at track 4; s3 (E)", "appu"),
    }
    d = {
        "tag": E,
        "name": "A320-class flap transmission (both wings)",
        "description": (
            "The flap drive of a single-aisle transport, both wings mirrored about the power "
            "control unit (PCU) on the centre line: two hydraulic motors summed by a differential "
            "with pressure-off brakes, a system torque limiter at each output, a root gearbox, "
            "4 drive stations per wing (2 flaps, 4 tracks), each an offset gearbox + "
            "bi-directional station torque limiter + rotary actuator, titanium tube 38 x 1.5 mm "
            "(28 m in all), a wing-tip brake outboard of track 4 with the APPU, an FPPU at the "
            "PCU. The architecture is published (domain.md section 1, tag P: A318-A321 FCOM and "
            "TTM); the numbers are NOT A320 data but the engineering estimates (tag E) of "
            "../shared/reference/domain.md section 4; the note of each value gives its tag. "
            "Values not given take the catalogue defaults. Generated by tools/gen_examples.py."),
        "sources": COMMON_SOURCES + [
            "domain.md s4 (E unless marked): single-aisle flap, one wing (mirrored for both)"],
        "pdu_description": ("power control unit: two hydraulic motors summed by a differential, "
                            "pressure-off brakes; one motor lost: half speed, full torque "
                            "(domain.md s1 P)"),
        "pdu": {
            "motor_count": {"value": 2, "note": "domain.md s1 (P): two motors summed by a differential"},
            "motor_inertia": q("1.5e-4 kg*m^2", f"{E}: per motor (PCU node 0.087 = 2 x 1.5e-4 x "
                               "16^2 + 0.01)", "1e-4 kg*m^2", "2e-4 kg*m^2"),
            "ratio": q(16, f"{E}: motor speed / output speed"),
            "gear_inertia": q("0.01 kg*m^2", f"{E}: gears"),
            "efficiency": q(0.90, "domain.md s3 (E): PCU gearbox 0.90", 0.85, 0.95),
            "max_output_speed": q("30.4 rad/s", f"{E}: 290 rpm"),
            "power": q("6 kW", f"{E}: about 6 kW for both wings"),
            "stall_torque": q("270 N*m", f"{E}: 1.4 x the 190 N m operating torque for both wings "
                              "(the catalogue's rule)", "230 N*m", "320 N*m"),
            "brake_torque": q("300 N*m", f"{E}: above the stall torque so the POBs hold the drive",
                              "250 N*m", "380 N*m"),
            "speed_ramp_time": q("0.4 s", "domain.md s3 (E): 0.3-0.5 s", "0.3 s", "0.5 s"),
            "brake_stop_time": q("0.1 s", "domain.md s3 (E): about 0.1 s"),
            "motor_displacement": q("4.4 cm^3/rev", f"{E}: 13.4 N m at 207 bar"),
            "supply_pressure": q("207 bar", "domain.md s1 (P-low): A320 207 bar (3000 psi)"),
            "span_position": q("0 m", f"{E}: on the centre line"),
        },
        "fppu": with_x(sensors("domain.md s1 (P) FPPU at the PCU; s3 (E)", "fppu"), -0.2,
                       f"{E}: at the PCU"),
        "w_max": 30.4,
        "revolutions": 105,
        "extend_load": [[0, 1.5], [0.25, 2.4], [0.5, 3.6], [0.75, 4.8], [1, 6]],
        "wing": wing,
        "numbers": {"root": 97, "backdrive": 56, "station": 23.5, "time": 25, "limiter_ratio": ratio},
    }
    return build_project(d)


# ----------------------------------------------------------------------------------------------
# Single-aisle (A320-class) slats, domain.md section 5

def a320_slats():
    E = "domain.md s5 (E)"
    tube = (38, 1.5)
    stations = [3.0, 4.4, 5.8, 7.2, 8.6, 10.0, 11.4, 12.8, 14.2, 15.6]
    # No-load drags referred to the shaft, per wing: 10 station gearboxes x 0.1, 10 actuators x 0.1
    # (1:1), the root gearbox 0.1.
    component_drag = 10 * 0.1 + 10 * 0.1 + 0.1
    wing = {
        "tag": E,
        "root_x": 1.5,
        "stations": stations,
        "wtb_x": 16.4,
        "tube": lambda x0, x1: tube,
        "split_length": 3.5,
        "joint_at_root": True,
        "material": titanium(0.2, 16.4, component_drag, E,
                             "root about 160 N m = 10 x 15.7 N m + drag (0.2 N m per metre, domain.md s3 "
                             "0.2-0.3)"),
        "rgb_name": "19 deg bevel gearbox at the wing root (the published T-gearbox 1:1 is lumped in)",
        "stl": {
            "lockout_torque_extend": pm10(210, "N*m", f"{E}: shaft side, 1.3 x 160 N m root torque"),
            "lockout_torque_retract": pm10(210, "N*m", f"{E}: symmetric STL"),
            **stl_end_stop_and_brake(210, E),
            "inertia": q("5e-4 kg*m^2", f"{E}: scaled from the A380-class estimate"),
        },
        "joint": {
            "efficiency": lossless(E, "universal joint at the wing root"),
            "inertia": q("1e-4 kg*m^2", "domain.md s6 (E): 1e-4 to 3e-4 kg m2, small end",
                         "1e-4 kg*m^2", "3e-4 kg*m^2"),
        },
        "bearing": {},
        "rgb": shaft_gearbox(
            E, "root bevel gearbox", q(1, "domain.md s1 (P): 19 deg bevel gearbox; 1:1 (E)"),
            q("1e-3 kg*m^2", f"{E}: shaft side, like the single-aisle flap root gearbox (s4)"),
            shaft_angle=q("19 deg", "domain.md s1 (P): A320 AMM 27-84-00")),
        "station_gearbox": shaft_gearbox(
            E, "63.5 deg station gearbox",
            q(1, "domain.md s1 (P): 63.5 deg gearbox to each actuator (AMM 27-84-00); 1:1 (E: s5 gives "
              "15.7 N m at the shaft for 2 kN m at the actuator = 1:1 x 150:1 / 0.85)"),
            q("3e-4 kg*m^2", f"{E}: shaft side, like a single-aisle flap station gearbox (s4)")),
        "limiter": dict(station_limiter(23.5, E, "1.5 x 15.7 N m actuator input torque (1:1 with the "
                                        "shaft)"),
                        inertia=q("1e-4 kg*m^2", f"{E}: actuator input side, small limiter")),
        "gra": {
            "ratio": q(150, f"{E}: rotary actuator 150:1"),
            "eta_opposing": q(0.85, f"{E}: 2 kN m -> 15.7 N m at the shaft over 150:1", 0.80, 0.90),
            "eta_aiding": q(0.70, "domain.md s6 (E): 0.60-0.80", 0.60, 0.80),
            "input_inertia": q("3e-4 kg*m^2", f"{E}: actuator input side, smaller than a flap GRA",
                               "2e-4 kg*m^2", "5e-4 kg*m^2"),
            "load_inertia": q(None, f"{E}: actuator input side (1:1 with the shaft); no data for the slat "
                              "inertia; an interval only", "1e-4 kg*m^2", "2e-3 kg*m^2"),
            "coulomb_torque": q("0.1 N*m", f"{E}: actuator input side; a 2 kN m slat actuator drags less "
                                "than the catalogue's 20 kN m flap GRA (0.2 N m); part of the drag budget"),
            "output_torque_rating": q("2 kN*m", f"{E}: actuator output side, actuator output 2 kN m"),
            "limit_output_torque": q("5 kN*m", LIMIT_NOTE),
            "travel_angle": q("2.5 rad", f"{E}: 2.5 rad pinion rotation, 60 shaft revolutions"),
        },
        "wtb": {
            "static_capacity": q("280 N*m", f"{E}: at least 1.5 x 160 N m = 240 N m (opposing, larger "
                                 "than the back-drive torque)", "240 N*m", "330 N*m"),
            "max_dynamic_torque": q("240 N*m", f"{E}: 1.5 x 160 N m", "220 N*m", "300 N*m"),
            "engagement_latency": q("100 ms", "domain.md s3/s6 (E): 50-150 ms", "50 ms", "150 ms"),
            "inertia": q("3e-4 kg*m^2", "domain.md s4 (E): like the single-aisle flap WTB"),
        },
        "appu": sensors("domain.md s1 (P) APPU at the tip; s3 (E)", "appu"),
    }
    d = {
        "tag": E,
        "name": "A320-class slat transmission (both wings)",
        "description": (
            "The slat drive of a single-aisle transport, both wings mirrored about the power "
            "control unit on the centre line: two hydraulic motors summed by a differential with "
            "pressure-off brakes, a system torque limiter at each output, a 19 deg bevel gearbox "
            "at the wing root, 10 rotary actuators per wing on 5 slats, each driven from the "
            "shaft through a 63.5 deg gearbox and a station torque limiter, titanium tube "
            "38 x 1.5 mm (about 33 m in all), a wing-tip brake and the APPU at the tip, an FPPU "
            "at the PCU. The architecture is published (domain.md section 1, tag P: A320 AMM "
            "27-84-00); the numbers are NOT A320 data but the engineering estimates (tag E) of "
            "../shared/reference/domain.md section 5, with the tube, the station positions, the "
            "limiter settings and the inertias estimated here (E) from sections 3, 4 and 6; the "
            "note of each value gives its tag. The slat inertia is unknown (an interval only). "
            "Values not given take the catalogue defaults. Generated by tools/gen_examples.py."),
        "sources": COMMON_SOURCES + [
            "domain.md s5 (E): single-aisle slats, one wing (mirrored for both)",
            "domain.md s4 (E): single-aisle flap values reused where s5 gives none (tube, PCU motors)"],
        "pdu_description": ("power control unit: two hydraulic motors summed by a differential, "
                            "pressure-off brakes (domain.md s1 P)"),
        "pdu": {
            "motor_count": {"value": 2, "note": "domain.md s1 (P): two motors summed by a differential"},
            "motor_inertia": q("1.5e-4 kg*m^2", "domain.md s4 (E): like the flap PCU motors",
                               "1e-4 kg*m^2", "2e-4 kg*m^2"),
            "ratio": q(22, f"{E}: about 4600 rpm motor speed (s4) / 206 rpm output speed"),
            "gear_inertia": q("0.01 kg*m^2", "domain.md s4 (E): like the flap PCU"),
            "efficiency": q(0.90, "domain.md s3 (E): PCU gearbox 0.90", 0.85, 0.95),
            "max_output_speed": q("21.6 rad/s", f"{E}: w_max 21.6 rad/s"),
            "power": q("7 kW", f"{E}: about 7 kW for both wings"),
            "stall_torque": q("450 N*m", f"{E}: 1.4 x the 320 N m operating torque for both wings "
                              "(the catalogue's rule)", "380 N*m", "540 N*m"),
            "brake_torque": q("500 N*m", f"{E}: above the stall torque so the POBs hold the drive",
                              "420 N*m", "620 N*m"),
            "speed_ramp_time": q("0.4 s", "domain.md s3 (E): 0.3-0.5 s", "0.3 s", "0.5 s"),
            "brake_stop_time": q("0.1 s", "domain.md s3 (E): about 0.1 s"),
            "supply_pressure": q("207 bar", "domain.md s1 (P-low): A320 207 bar (3000 psi)"),
            "span_position": q("0 m", f"{E}: on the centre line"),
        },
        "fppu": with_x(sensors("domain.md s1 (P) FPPU at the PCU; s3 (E)", "fppu"), -0.2,
                       f"{E}: at the PCU"),
        "w_max": 21.6,
        "revolutions": 60,
        "extend_load": [[0, 0.8], [0.5, 1.4], [1, 2]],
        "wing": wing,
        "numbers": {"root": 160, "backdrive": 93, "station": 15.7, "time": 20},
    }
    return build_project(d)


# ----------------------------------------------------------------------------------------------

def dump(value, indent=0, width=120):
    """JSON with every object or array on one line when it fits in `width` columns."""
    compact = json.dumps(value, ensure_ascii=False, separators=(", ", ": "))
    one_line = isinstance(value, dict) and "note" in value  # a quantity with its note
    if one_line or indent + len(compact) <= width or not isinstance(value, (dict, list)) or not value:
        return compact
    pad = " " * (indent + 2)
    if isinstance(value, dict):
        items = [f"{pad}{json.dumps(k)}: {dump(v, indent + 2, width)}"
                 for k, v in value.items()]
        return "{\n" + ",\n".join(items) + "\n" + " " * indent + "}"
    items = [pad + dump(v, indent + 2, width) for v in value]
    return "[\n" + ",\n".join(items) + "\n" + " " * indent + "]"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true",
                        help="compare with the committed files instead of writing them")
    args = parser.parse_args()
    projects = {"a380_class_flaps.json": a380_flaps(), "a320_class_flaps.json": a320_flaps(),
                "a320_class_slats.json": a320_slats(),
                "hydraulic_pdu_flaps.json": hydraulic_pdu_flaps(),
                "a380_class_flaps_infeasible.json": a380_flaps_infeasible()}
    status = 0
    for name, project in projects.items():
        text = dump(project) + "\n"
        path = EXAMPLES / name
        if args.check:
            if not path.exists() or path.read_text() != text:
                print(f"{path} differs from tools/gen_examples.py output", file=sys.stderr)
                status = 1
        else:
            path.write_text(text)
            print(f"wrote {path.relative_to(ROOT)}")
    return status


if __name__ == "__main__":
    sys.exit(main())
