#!/usr/bin/env python3
"""Writes data/components.csv, the seed of the component database, from
../shared/reference/domain.md (sections 1, 3-6). Run from the project root:

    python3 componentdb/tools/generate_seed.py > data/components.csv

Every number is tagged: P (published, source given), P-low (weak source), E (engineering
estimate, the derivation in the source column). Families of geared rotary actuators are E:
plausible parts spread over the ranges of domain.md section 6, built from one stated scaling law
so that fits over the database have data; they are not real parts.
"""
import csv
import math
import sys

rows = []
HEADER = ["type", "designation", "program", "supplier", "note", "parameter", "value", "min", "max",
          "unit", "tag", "source"]


def part(type_, designation, program, note, params, supplier=""):
    first = True
    for p in params:
        name, value, lo, hi, unit, tag, source = p
        rows.append([type_, designation, program if first else "", supplier if first else "",
                     note if first else "", name, fmt(value), fmt(lo), fmt(hi), unit, tag, source])
        first = False


def fmt(v):
    if v is None:
        return ""
    if isinstance(v, int):
        return str(v)
    return "%.4g" % v


def q(name, value, unit, tag, source, lo=None, hi=None):
    return (name, value, lo, hi, unit, tag, source)


S1, S3, S4, S5, S6 = ("domain.md s1", "domain.md s3", "domain.md s4", "domain.md s5", "domain.md s6")

# --- materials -----------------------------------------------------------------------------
part("material", "Ti-6Al-4V", "", "titanium torque tubes (A330, A340, A350, A380: ctgltd.com)", [
    q("shear_modulus", 44, "GPa", "P-low", "azom 1341 via " + S1 + "; domain [43, 51] GPa " + S6, 43, 51),
    q("density", 4420, "kg/m^3", "P", "azom 1341; princeton mae324 via " + S1),
    q("allowable_shear_stress", 550, "MPa", "E", S6 + ": ultimate shear about 550 MPa (0.6 x UTS 895 MPa)", 500, 600)])
part("material", "steel-300M", "", "high-strength steel shafts and gears", [
    q("shear_modulus", 80, "GPa", "E", S6 + ": steel G about 80 GPa", 77, 82),
    q("density", 7850, "kg/m^3", "E", "typical low-alloy steel"),
    q("allowable_shear_stress", 1000, "MPa", "E", "0.6 x UTS about 1900 MPa, rounded down", 900, 1100)])
part("material", "Al-7075-T6", "", "aluminium tubes", [
    q("shear_modulus", 27, "GPa", "E", S6 + ": aluminium G about 27 GPa", 26, 28),
    q("density", 2810, "kg/m^3", "E", "typical 7075 alloy"),
    q("allowable_shear_stress", 330, "MPa", "E", "0.6 x UTS about 570 MPa", 300, 350)])
part("material", "CFRP-tube", "", "filament-wound +-45 deg carbon tube; 0.28 kg/m per ctgltd.com (P)", [
    q("shear_modulus", 30, "GPa", "E", "+-45 deg laminate shear modulus 25-35 GPa", 25, 35),
    q("density", 1550, "kg/m^3", "E", "typical carbon/epoxy"),
    q("allowable_shear_stress", 300, "MPa", "E", "+-45 deg laminate, with knock-downs", 200, 400)])

# --- PDUs ----------------------------------------------------------------------------------
part("pdu", "PCU-A380C-FLAP", "A380-class flap", "scaled estimate, not A380 data (" + S3 + ")", [
    q("motor_count", 2, "1", "P", S1 + ": 2 motors summed by a differential (A320 FCOM)"),
    q("motor_inertia", 3e-4, "kg*m^2", "E", S3 + ": motor J [2, 4]e-4", 2e-4, 4e-4),
    q("ratio", 20, "1", "E", S3 + ": i_PCU = 20"),
    q("gear_inertia", 0.02, "kg*m^2", "E", S3 + ": 0.02 kg m2 gears"),
    q("efficiency", 0.90, "1", "E", S3 + ": PCU gearbox 0.90"),
    q("max_output_speed", 242, "rpm", "E", S3 + ": 25.3 rad/s, 1.15 x average"),
    q("power", 18, "kW", "E", S3 + ": about 18 kW for both wings"),
    q("supply_pressure", 345, "bar", "P-low", S1 + ": A380 5000 psi")])
part("pdu", "PCU-A320C-FLAP", "A320-class flap", "single-aisle estimate (" + S4 + ")", [
    q("motor_count", 2, "1", "P", S1 + ": A318-A321 FCOM DSC-27-30-10"),
    q("motor_inertia", 1.5e-4, "kg*m^2", "E", S4 + ": 2 x 1.5e-4 x 16^2 + 0.01"),
    q("ratio", 16, "1", "E", S4),
    q("gear_inertia", 0.01, "kg*m^2", "E", S4),
    q("efficiency", 0.90, "1", "E", S3 + ": PCU gearbox 0.90"),
    q("max_output_speed", 290, "rpm", "E", S4 + ": w_max 30.4 rad/s"),
    q("power", 6, "kW", "E", S4 + ": about 6 kW for both wings"),
    q("motor_displacement", 4.4, "cm^3/rev", "E", S4 + ": 13.4 N m at 207 bar"),
    q("supply_pressure", 207, "bar", "P-low", S1 + ": A320 3000 psi")])
part("pdu", "PCU-A320C-SLAT", "A320-class slat", "single-aisle estimate (" + S5 + ")", [
    q("motor_count", 2, "1", "P", S1),
    q("motor_inertia", 1.5e-4, "kg*m^2", "E", "as the A320-class flap PCU motor " + S4),
    q("ratio", 20, "1", "E", "4600 rpm motor / 21.6 rad/s output"),
    q("gear_inertia", 0.01, "kg*m^2", "E", "as " + S4),
    q("max_output_speed", 21.6, "rad/s", "E", S5),
    q("power", 7, "kW", "E", S5 + ": about 7 kW for both wings"),
    q("supply_pressure", 207, "bar", "P-low", S1)])
part("pdu", "PCU-A330C-FLAP", "A330-class flap", "two-speed PCU (" + S1 + "); sizes interpolated between s3 and s4", [
    q("motor_count", 2, "1", "P", S1 + ": airbusflightinstructor.com a330 ata-27"),
    q("motor_inertia", 2.5e-4, "kg*m^2", "E", "between s3 and s4", 2e-4, 3e-4),
    q("ratio", 18, "1", "E", "between s3 (20) and s4 (16)"),
    q("gear_inertia", 0.015, "kg*m^2", "E", "between s3 and s4"),
    q("max_output_speed", 260, "rpm", "E", "between s3 and s4"),
    q("power", 12, "kW", "E", "between s3 and s4")])

# --- system torque limiters ------------------------------------------------------------------
def wobble(k):
    """Deterministic +-12 % scatter, so fits over families are not exact."""
    return 1 + 0.12 * math.sin(2.1 * k + 0.7)


for k, (des, prog, tau, src) in enumerate([("STL-A380C", "A380-class flap", 470, S3 + ": 1.3 x 360 N m root torque"),
                            ("STL-A320C-FLAP", "A320-class flap", 125, S4 + ": STL about 125 N m"),
                            ("STL-A320C-SLAT", "A320-class slat", 210, S5 + ": 1.3 x 160 N m root torque"),
                            ("STL-A330C", "A330-class flap", 300, "E: 1.3 x about 230 N m, between s3 and s4")]):
    part("system_torque_limiter", des, prog, "ball-ramp lock-out coupling (EP0873937)", [
        q("lockout_torque_extend", tau, "N*m", "E", src + "; " + S6 + " 1.2-1.4 x", round(0.9 * tau), round(1.1 * tau)),
        q("lockout_torque_retract", tau, "N*m", "E", "symmetric STL"),
        q("inertia", 1e-3 * (tau / 470) ** 0.5 * wobble(k), "kg*m^2", "E",
          "J = 1e-3 (T/470 N m)^0.5 (friction-pack device, weak size dependence; catalogue 1e-3), x %.2f scatter" % wobble(k))])

# --- torque shafts (tube stock; length given per segment in a project) -----------------------
def tube(des, prog, D, t, material, G, rho, tau, tagG, note):
    d = D - 2 * t
    ip = math.pi / 32 * ((D / 1e3) ** 4 - (d / 1e3) ** 4)
    ml = rho * math.pi / 4 * ((D / 1e3) ** 2 - (d / 1e3) ** 2)
    part("torque_shaft", des, prog, note + "; material " + material, [
        q("outer_diameter", D, "mm", "E", prog + " tube, " + S3 + "/" + S4),
        q("wall_thickness", t, "mm", "E", S3 + ": +-0.1 mm", t - 0.1, t + 0.1),
        q("shear_modulus", G[0], "GPa", tagG, material + " " + S6, G[1], G[2]),
        q("density", rho, "kg/m^3", "P" if material == "Ti-6Al-4V" else "E", material + " " + S1),
        q("allowable_shear_stress", tau, "MPa", "E", material + " ultimate shear " + S6),
        q("linear_density", ml, "kg/m", "E", "rho pi/4 (D^2 - d^2); Ti tube 1.2 kg/m published (ctgltd.com)")])


tube("TS-TI-50x2.0", "A380-class flap", 50, 2.0, "Ti-6Al-4V", (44, 43, 51), 4420, 550, "P-low", "inboard tube, GJ 7657 N m2")
tube("TS-TI-45x1.8", "A380-class flap", 45, 1.8, "Ti-6Al-4V", (44, 43, 51), 4420, 550, "P-low", "outboard tube, GJ 5024 N m2")
tube("TS-TI-38x1.5", "A320-class flap", 38, 1.5, "Ti-6Al-4V", (44, 43, 51), 4420, 550, "P-low", "GJ 2525 N m2")
tube("TS-TI-32x1.2", "A320-class slat", 32, 1.2, "Ti-6Al-4V", (44, 43, 51), 4420, 550, "P-low", "slat tube, 160 N m root torque")
tube("TS-TI-55x2.2", "A350-class flap", 55, 2.2, "Ti-6Al-4V", (44, 43, 51), 4420, 550, "P-low", "E: between A330 and A380 class")
tube("TS-ST-30x1.5", "generic", 30, 1.5, "steel-300M", (80, 77, 82), 7850, 1000, "E", "steel tube for short stiff segments")
tube("TS-AL-60x2.5", "generic", 60, 2.5, "Al-7075-T6", (27, 26, 28), 2810, 330, "E", "aluminium tube")
part("torque_shaft", "TS-CFRP-50", "A350-class flap", "composite tube; mass per length published", [
    q("outer_diameter", 50, "mm", "E", "same envelope as the Ti 50 mm tube"),
    q("wall_thickness", 2.5, "mm", "E", "thicker wall for the lower shear modulus", 2.3, 2.7),
    q("shear_modulus", 30, "GPa", "E", "+-45 deg laminate", 25, 35),
    q("linear_density", 0.28, "kg/m", "P", "ctgltd.com high-lift transmission shafts via " + S1)])

# --- steady bearings -------------------------------------------------------------------------
for i, tc in enumerate([0.05, 0.1, 0.15, 0.2]):
    part("steady_bearing", "SB-%02d" % (i + 1), "generic", "sealed deep-groove bearing in a flexible mount", [
        q("coulomb_torque", tc, "N*m", "E", S6 + ": drag 0.05-0.2 N m each"),
        q("stribeck_torque", 0.35 * tc, "N*m", "E", S6 + ": T_brk 1.2-1.5 x T_C", 0.2 * tc, 0.5 * tc),
        q("inertia", 5e-5, "kg*m^2", "E", "small rotating parts")])

# --- universal joints ------------------------------------------------------------------------
for des, eta, J in [("UJ-S", 0.99, 1e-4), ("UJ-M", 0.985, 2e-4), ("UJ-L", 0.98, 3e-4)]:
    part("universal_joint", des, "generic", "Cardan joint", [
        q("efficiency", eta, "1", "E", S6 + ": eta 0.98-0.99"),
        q("inertia", J, "kg*m^2", "E", S6 + ": J 1e-4 to 3e-4 kg m2")])

# --- angle gearboxes -------------------------------------------------------------------------
part("angle_gearbox", "RGB-A380C", "A380-class flap", "root (kink) gearbox", [
    q("ratio", 1, "1", "E", S6 + ": 1:1 to 2:1"),
    q("eta_mesh", 0.97, "1", "E", S6 + ": 0.96-0.98 per mesh", 0.96, 0.98),
    q("inertia", 2e-3, "kg*m^2", "E", S3 + ": gearbox 2e-3 kg m2")])
part("angle_gearbox", "RGB-A320C-FLAP", "A320-class flap", "root gearbox", [
    q("ratio", 1, "1", "E", S6),
    q("eta_mesh", 0.97, "1", "E", S6, 0.96, 0.98),
    q("inertia", 7e-4, "kg*m^2", "E", S4 + ": RGB node 1.4e-3 incl. shaft halves")])
part("angle_gearbox", "BGB-19-A320C-SLAT", "A320-class slat", "19 deg bevel gearbox after the differential", [
    q("ratio", 1, "1", "E", S6),
    q("shaft_angle", 19, "deg", "P", "AMM 27-84-00 via " + S1),
    q("inertia", 5e-4, "kg*m^2", "E", "small bevel set")])
part("angle_gearbox", "BGB-63-A320C-SLAT", "A320-class slat", "63.5 deg gearbox", [
    q("ratio", 1, "1", "E", S6),
    q("shaft_angle", 63.5, "deg", "P", "AMM 27-84-00 via " + S1),
    q("inertia", 4e-4, "kg*m^2", "E", "small bevel set")])
part("angle_gearbox", "OGB-2-A320C-FLAP", "A320-class flap", "offset gearbox at a flap track", [
    q("ratio", 2, "1", "E", S6 + ": 1:1 to 2:1"),
    q("meshes", 2, "1", "E", "two spur meshes"),
    q("inertia", 3e-4, "kg*m^2", "E", "small offset gearbox")])

# --- branch gearboxes ------------------------------------------------------------------------
part("branch_gearbox", "SGB-2-A380C", "A380-class flap", "station gearbox (down-drive)", [
    q("ratio", 2, "1", "E", S3 + ": station gearbox 2:1"),
    q("eta_mesh", 0.97, "1", "E", S6, 0.96, 0.98),
    q("inertia", 6.25e-4, "kg*m^2", "E", S3 + ": station input 1e-3 kg m2 at the shaft = this 6.25e-4 + (limiter 5e-4 + "
      "GRA input 1e-3) / 2^2 behind the 2:1")])
part("branch_gearbox", "TGB-1-A320C-SLAT", "A320-class slat", "T-gearbox", [
    q("ratio", 1, "1", "P", "AMM 27-84-00 via " + S1 + ": T-gearbox 1:1"),
    q("inertia", 4e-4, "kg*m^2", "E", "small bevel set")])
part("branch_gearbox", "SGB-1-A320C-FLAP", "A320-class flap", "station down-drive", [
    q("ratio", 1, "1", "E", S6),
    q("inertia", 5e-4, "kg*m^2", "E", S4 + ": station nodes 2.0e-3 to 2.3e-3 incl. flap and shaft")])
part("branch_gearbox", "SGB-1.5-A330C", "A330-class flap", "station gearbox, torque limiter in the input (" + S1 + ")", [
    q("ratio", 1.5, "1", "E", S6 + ": 1:1 to 2:1"),
    q("inertia", 8e-4, "kg*m^2", "E", "between s3 and s4")])

# --- station torque limiters -----------------------------------------------------------------
# A station limiter sits between the station gearbox and the actuator: its settings and inertia
# count on the actuator input side, where a shaft-side torque of domain.md reads ratio x larger.
for k, (des, prog, tau, src) in enumerate([
        ("STTL-A380C", "A380-class flap", 180, S3 + ": 1.5 x 58.8 N m = 90 N m at the shaft, x 2 behind the 2:1 station gearbox"),
        ("STTL-A320C-FLAP", "A320-class flap", 52.5, S4 + ": about 35 N m input side (shaft), x 1.5 behind the 1.5:1 offset gearbox"),
        ("STTL-A320C-SLAT", "A320-class slat", 24, S5 + ": 1.5 x 15.7 N m, 1:1 with the shaft"),
        ("STTL-A330C", "A330-class flap", 60, "E: between s3 and s4")]):
    part("station_torque_limiter", des, prog, "bi-directional ball-ramp limiter with lock-out indicator (TTM 27-50-00, P)", [
        q("lockout_torque_extend", tau, "N*m", "E", src + "; actuator input side; " + S6 + " 1.3-1.6 x",
          round(0.9 * tau, 1), round(1.1 * tau, 1)),
        q("lockout_torque_retract", 0.7 * tau, "N*m", "E", S3 + ": retract 0.7 x extend; EP4265931 (P) asymmetric"),
        q("inertia", 5e-4 * (tau / 180) * wobble(k + 4), "kg*m^2", "E",
          "J = 5e-4 (T/180 N m) at the actuator input (friction-pack device), x %.2f scatter" % wobble(k + 4))])

# --- geared rotary actuators: named ones, then a family ---------------------------------------
T_IN_REF = 20e3 / 200 / 0.85  # N m: the s3 GRA (20 kN m, 200:1, eta 0.85) has J_in = 1e-3 (s6)


def gra_inertia(torque_nm, ratio):
    """J_in = 3e-4 + 7e-4 (T_in / T_in_ref)^(5/3): gear scaling above a floor for the input
    shaft, bearings and no-back brake (the same law as estimation/physics.h)."""
    return 3e-4 + 7e-4 * (torque_nm / ratio / 0.85 / T_IN_REF) ** (5 / 3)


def gra(des, prog, ratio, torque_knm, note, scatter=1.0, tag_src=""):
    J = gra_inertia(torque_knm * 1e3, ratio) * scatter
    part("geared_rotary_actuator", des, prog, note, [
        q("ratio", ratio, "1", "E", tag_src or (S6 + ": ratio 100-300:1")),
        q("output_torque_rating", torque_knm, "kN*m", "E", tag_src or (S6 + " family, 2-25 kN m")),
        q("eta_opposing", 0.85, "1", "E", S6 + ": 0.80-0.90", 0.80, 0.90),
        q("eta_aiding", 0.70, "1", "E", S6 + ": 0.60-0.80", 0.60, 0.80),
        q("input_inertia", J, "kg*m^2", "E",
          "J_in = 3e-4 + 7e-4 (T_out/ratio/0.85/117.6 N m)^(5/3) x %.2f scatter; 1e-3 at 20 kN m, 200:1 (%s)" % (scatter, S6))])


gra("GRA-200-A380C", "A380-class flap", 200, 20, "compound planetary (ASME IDETC 2011, P type)", 1.0,
    S3 + ": station output about 20 kN m, GRA 200:1")
gra("GRA-300-A320C-FLAP", "A320-class flap", 300, 6, "rotary actuator at a flap track (TTM 27-50-00, P)", 1.0,
    S4 + ": station output about 6 kN m, 300:1")
gra("GRA-150-A320C-SLAT", "A320-class slat", 150, 2, "slat rotary actuator (AMM 27-84-00, P)", 1.0,
    S5 + ": output 2 kN m, 150:1")
# A family over the section-6 ranges: torque 2-25 kN m log-spaced, ratio spread over 100-300
# independently of the torque (deterministic); scatter of the inertia +-15 %.
n = 19
for k in range(n):
    T = 2.0 * (25.0 / 2.0) ** (k / (n - 1))
    ratio = round((200 + 100 * math.sin(2.3 * k + 1.0)) / 5) * 5
    ratio = min(300, max(100, ratio))
    scatter = 1 + 0.15 * math.sin(1.7 * k + 0.5)
    gra("GRA-F%02d-%d" % (k + 1, ratio), "family (E)", ratio, round(T, 2), "plausible family member, not a real part", scatter)

# --- ballscrew actuators ---------------------------------------------------------------------
for des, lead, F, J in [("BSA-05", 5, 40, 2e-4), ("BSA-10", 10, 80, 5e-4), ("BSA-20", 20, 150, 1e-3)]:
    part("ballscrew_actuator", des, "generic", "ball-screw flap actuator", [
        q("lead", lead, "mm/rev", "E", "typical leads 5-20 mm"),
        q("output_force_rating", F, "kN", "E", "sized for 2-20 kN m equivalent"),
        q("eta_opposing", 0.90, "1", "E", "ball screw 0.85-0.95", 0.85, 0.95),
        q("input_inertia", J, "kg*m^2", "E", "screw and nut inertia")])

# --- wing-tip brakes -------------------------------------------------------------------------
for k, (des, prog, dyn, stat, src) in enumerate([("WTB-A380C", "A380-class flap", 550, 700, S3 + ": >= 1.5 x 360 N m"),
                                  ("WTB-A320C-FLAP", "A320-class flap", 150, 190, S4 + ": WTB at least 150 N m"),
                                  ("WTB-A320C-SLAT", "A320-class slat", 240, 300, S5 + ": 1.5 x 160 N m"),
                                  ("WTB-A330C", "A330-class flap", 350, 450, "E: between s3 and s4")]):
    part("wing_tip_brake", des, prog, "pressure-off friction brake; triggers asymmetry, runaway, overspeed (P, TTM 27-50-00)", [
        q("max_dynamic_torque", dyn, "N*m", "E", src),
        q("static_capacity", stat, "N*m", "E", src + "; static above dynamic"),
        q("engagement_latency", 100, "ms", "E", S6 + ": 50-150 ms", 50, 150),
        q("inertia", 5e-4 * (dyn / 550) ** 0.4 * (wobble(k + 8) if k else 1.0), "kg*m^2", "E",
          "rotor 5e-4 at 550 N m (s3) and about 3e-4 at 150 N m (s4 node 4.3e-4 less a shaft half): J ~ T^0.4" +
          (", x %.2f scatter" % wobble(k + 8) if k else ""))])

# --- position sensors ------------------------------------------------------------------------
part("position_sensor", "APPU-A320C", "A320-class flap", "asymmetry position pick-off at track 4 (TTM 27-50-00, P)", [
    q("asymmetry_threshold", 2, "rev", "E", S3 + ": 1-3 shaft revolutions", 1, 3),
    q("latency", 10, "ms", "E", "sensor and monitor chain")])
part("position_sensor", "FPPU-A320C", "A320-class flap", "feedback position pick-off at the PCU; APPU/FPPU agree within 1.3 deg (AMM 27-54-49, P)", [
    q("latency", 10, "ms", "E", "sensor and monitor chain"),
    q("overspeed_factor", 1.3, "1", "E", S3 + ": overspeed 1.3 x w_max")])
part("position_sensor", "APPU-A380C", "A380-class flap", "asymmetry pick-off at the shaft end", [
    q("asymmetry_threshold", 2, "rev", "E", S3 + ": 1-3 shaft revolutions", 1, 3),
    q("overspeed_factor", 1.3, "1", "E", S3),
    q("latency", 10, "ms", "E", "sensor and monitor chain", 5, 30)])

# --- failure elements --------------------------------------------------------------------------
part("disconnector", "DISC-SPLINE", "generic", "failure element: splined coupling that breaks in a rupture scenario", [
    q("stiffness", 5e4, "N*m/rad", "E", "stiff compared with 1.4-3.3 kN m/rad shaft segments (" + S3 + ")")])
part("disconnector", "DISC-FLEX", "generic", "failure element: flexible coupling", [
    q("stiffness", 1e4, "N*m/rad", "E", "a few times the shaft segment stiffness")])
part("jam", "JAM-GROUND", "generic", "failure element: jam grounded through the actuator mount", [
    q("stiffness", 1e5, "N*m/rad", "E", "stiff compared with the shaft (" + S3 + ")", 2e4, 5e5)])
part("jam", "JAM-TRACK", "generic", "failure element: jam in the flap track (softer load path)", [
    q("stiffness", 2e4, "N*m/rad", "E", "track and carriage compliance")])

w = csv.writer(sys.stdout, lineterminator="\n")
w.writerow(HEADER)
w.writerows(rows)
