within HighLift.Drives;
model PDU "Speed-controlled power drive unit: two motors on a speed-summing differential, torque limit, pressure-off brakes"
  import Modelica.Units.SI;

  parameter Integer n_m(min=1) = 2 "Number of motors summed by the differential";
  parameter SI.Inertia J_m(min=0) = 3e-4 "Rotor inertia of one motor";
  parameter Real ratio(min=Modelica.Constants.small) = 20 "PDU gear ratio, motor speed / output speed";
  parameter SI.Inertia J_g(min=0) = 0.02 "Inertia of the differential and gears, at the output";
  parameter SI.AngularVelocity w_max(min=Modelica.Constants.small) = 25.3
    "Maximum output speed with all motors";
  parameter SI.Torque tau_stall(min=0) = 1000 "Maximum output torque (stall torque)";
  parameter SI.Power P_max(min=Modelica.Constants.small) = 18000 "Maximum output power";
  parameter SI.Time t_ramp(min=Modelica.Constants.small) = 0.4
    "Time from 0 to the maximum output speed (speed ramp)";
  parameter SI.Time T_w(min=Modelica.Constants.small) = 0.02
    "Time constant of the closed speed loop";
  parameter SI.Time T_i(min=0) = 0.08
    "Integral time of the speed loop (PI); 0 = proportional only";
  parameter SI.Torque tauPOB(min=0) = 1100 "Holding torque of the pressure-off brakes at the output";
  parameter SI.Time t_POB(min=0) = 0.05 "Time for the pressure-off brakes to build up their torque";
  parameter SI.AngularVelocity w_hold(min=0) = 1e-3
    "Speed command below which the pressure-off brakes are applied";
  parameter SI.Time t_motor_lost = Modelica.Constants.inf "Time at which one motor is lost";
  parameter Boolean useStopInput = false
    "= true, if the shutdown command stop is used (the monitor's wing-tip brake command)"
    annotation (Evaluate=true, HideResult=true, choices(checkBox=true));
  final parameter SI.Inertia J = n_m*J_m*ratio^2 + J_g "Inertia at the output";
  final parameter Real k_w(unit="N.m.s/rad") = J/T_w "Gain of the speed loop";

  Modelica.Blocks.Interfaces.RealInput w_ref(unit="rad/s") "Commanded output speed"
    annotation (Placement(transformation(extent={{-140,-20},{-100,20}})));
  Modelica.Blocks.Interfaces.BooleanInput stop if useStopInput
    "Shutdown command (latched): the motors are depressurised and the pressure-off brakes applied"
    annotation (Placement(transformation(extent={{-140,-80},{-100,-40}})));
  Modelica.Mechanics.Rotational.Interfaces.Flange_b flange_left "Output to the left wing"
    annotation (Placement(transformation(extent={{-10,90},{10,110}})));
  Modelica.Mechanics.Rotational.Interfaces.Flange_b flange_right "Output to the right wing"
    annotation (Placement(transformation(extent={{90,-10},{110,10}})));
  Modelica.Blocks.Interfaces.RealOutput phi(unit="rad") "Output angle (FPPU)"
    annotation (Placement(transformation(extent={{100,-70},{120,-50}})));
  Modelica.Blocks.Interfaces.RealOutput w(unit="rad/s") "Output speed"
    annotation (Placement(transformation(extent={{100,-100},{120,-80}})));

  Modelica.Mechanics.Rotational.Sources.Torque motorTorque
    annotation (Placement(transformation(extent={{-60,-10},{-40,10}})));
  Modelica.Mechanics.Rotational.Components.Inertia inertia(J=J)
    annotation (Placement(transformation(extent={{-20,-10},{0,10}})));
  HighLift.Mechanical.ShaftBrake pob(tauB_max=tauPOB, tauB_lim=tauPOB)
    annotation (Placement(transformation(extent={{20,-10},{40,10}})));

  Integer n_active "Motors in operation";
  SI.AngularVelocity w_avail "Output speed available from the motors in operation";
  SI.AngularVelocity w_target "Speed command limited to the available speed";
  SI.AngularVelocity w_set(start=0, fixed=true) "Ramped speed set point";
  SI.AngularVelocity e_w "Speed error w_set - w";
  SI.Angle z(start=0, fixed=true) "Integral of the speed error (PI speed loop)";
  SI.Torque tau_raw "Torque of the speed loop before the limit";
  SI.Torque tau_lim "Torque limit at the current speed (stall torque and power)";
  SI.Torque tau_drive "Drive torque at the output";
  Boolean stopped(start=false, fixed=true) "= true after the shutdown command (latched)";
  Boolean brakeApplied "= true, if the pressure-off brakes are applied";
  Boolean driving "= true, while the motors deliver the drive torque";
  discrete SI.Time t_on(start=0) "Time at which the pressure-off brakes were applied";
  Real f_brake(min=0, max=1) "Normalized torque of the pressure-off brakes";

protected
  Modelica.Blocks.Interfaces.BooleanInput stop_internal "Shutdown command in use";

equation
  connect(stop, stop_internal);
  if not useStopInput then
    stop_internal = false;
  end if;

  // One motor lost: its pressure-off brake holds it, so the differential delivers the speed of
  // the remaining motors only (half speed with two motors) at full torque.
  n_active = if time >= t_motor_lost then n_m - 1 else n_m;
  w_avail = w_max*n_active/n_m;
  stopped = pre(stopped) or stop_internal;
  w_target = if stopped then 0 else max(-w_avail, min(w_avail, w_ref));
  der(w_set) = max(-w_max/t_ramp, min(w_max/t_ramp, (w_target - w_set)/T_w));
  tau_lim = min(tau_stall, P_max/max(abs(inertia.w), Modelica.Constants.small));

  // Pressure-off brakes: applied when command and set point are at rest, or at once by the
  // shutdown command. Applied at the start, they have held the parked drive: fully built up.
  brakeApplied = (abs(w_target) <= w_hold and abs(w_set) <= w_hold) or stopped;
  when {initial(), brakeApplied} then
    t_on = if initial() then time - t_POB else time;
  end when;
  f_brake = if not brakeApplied then 0 else if t_POB > 0 then min(1, max(0, (time - t_on)/t_POB)) else 1;
  // Engaged from the instant of application (a vanishing capacity that then rises).
  pob.u = if brakeApplied then max(f_brake, 1e-12) else 0;

  // PI speed loop with back-calculation anti-windup. The motors keep driving (holding the set
  // point) until the brakes are built up, t_POB after the application; depressurised at once
  // by the shutdown command.
  driving = not stopped and (not brakeApplied or time < t_on + t_POB);
  e_w = w_set - inertia.w;
  tau_raw = if T_i > 0 then k_w*(e_w + z/T_i) else k_w*e_w;
  tau_drive = if driving then max(-tau_lim, min(tau_lim, tau_raw)) else 0;
  der(z) = if T_i > 0 and driving then e_w + (tau_drive - tau_raw)/k_w else 0;
  // Bumpless release: the integral takes over the torque the stuck brakes held.
  when not brakeApplied then
    reinit(z, if pre(pob.locked) then -T_i*pre(pob.tau)/k_w else 0);
  end when;

  motorTorque.tau = tau_drive;
  phi = inertia.phi;
  w = inertia.w;

  connect(motorTorque.flange, inertia.flange_a)
    annotation (Line(points={{-40,0},{-20,0}}));
  connect(inertia.flange_b, pob.flange_a)
    annotation (Line(points={{0,0},{20,0}}));
  connect(pob.flange_b, flange_left)
    annotation (Line(points={{40,0},{60,0},{60,80},{0,80},{0,100}}));
  connect(pob.flange_b, flange_right)
    annotation (Line(points={{40,0},{100,0}}));

  annotation (
    Icon(coordinateSystem(preserveAspectRatio=true, extent={{-100,-100},{100,100}}),
      graphics={
        Rectangle(extent={{-100,100},{100,-100}}, lineColor={0,0,0},
          fillColor={215,215,215}, fillPattern=FillPattern.Solid),
        Text(extent={{-80,40},{80,-40}}, textString="PDU"),
        Text(extent={{-150,150},{150,110}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>
The power drive unit (PCU): <code>n_m</code> motors summed by a speed-summing differential,
each with a pressure-off brake (POB), drive the output shaft that goes to the left
(<code>flange_left</code>) and right (<code>flange_right</code>) transmission. The PDU is
speed-controlled (as a variable-displacement hydraulic motor in a closed speed loop), acting on
the output inertia <code>J = n_m*J_m*ratio^2 + J_g</code>:
</p>
<pre>
  w_avail  = w_max*n_active/n_m                       (one motor lost: half speed)
  w_target = limit(w_ref, -w_avail, w_avail)          (0 after the shutdown command)
  der(w_set) = limit((w_target - w_set)/T_w, -w_max/t_ramp, w_max/t_ramp)      (speed ramp)
  tau_lim  = min(tau_stall, P_max/|w|)                (torque limit, full torque with one motor)
  e        = w_set - w,   k_w = J/T_w
  tau_raw  = k_w*(e + z/T_i)                          (PI; T_i = 0: k_w*e)
  tau      = limit(tau_raw, -tau_lim, tau_lim)        (while the motors drive, else 0)
  der(z)   = e + (tau - tau_raw)/k_w                  (while the motors drive, else 0)
</pre>
<p>
The integral <code>z</code> has a back-calculation anti-windup: in the torque limit it relaxes
to the value that gives the limited torque.
</p>
<p>
<strong>Pressure-off brakes.</strong> When the command and the set point are at rest
(<code>|w_target| &le; w_hold</code> and <code>|w_set| &le; w_hold</code>) the POBs, a
<a href=\"modelica://HighLift.Mechanical.ShaftBrake\">ShaftBrake</a> with holding torque
<code>tauPOB</code>, are applied; their torque builds up linearly within <code>t_POB</code>.
The motors keep driving (holding the set point) until the brakes are fully built up, i.e. until
<code>t_POB</code> after the application; only then is the drive torque removed. Brakes applied
at the start (<code>w_ref = 0</code> at the start time) have held the parked drive: they are
fully built up from the start. When the brakes are released, the integral <code>z</code> is
set so that the drive takes over the torque the brakes held (bumpless release).
</p>
<p>
<strong>Shutdown.</strong> With <code>useStopInput = true</code> the Boolean input
<code>stop</code> (the monitor's wing-tip brake command, latched) depressurises the motors (drive
torque 0 at once), applies the brakes at once (building up over <code>t_POB</code>) and sets
<code>w_target = 0</code>, so that after a shaft rupture the healthy side is not driven into
its wing-tip brake.
</p>
<p>
From <code>t_motor_lost</code> on one motor is lost.
</p>
</html>"));
end PDU;
