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
  parameter SI.Torque tauPOB(min=0) = 1100 "Holding torque of the pressure-off brakes at the output";
  parameter SI.Time t_POB(min=0) = 0.05 "Time for the pressure-off brakes to build up their torque";
  parameter SI.AngularVelocity w_hold(min=0) = 1e-3
    "Speed command below which the pressure-off brakes are applied";
  parameter SI.Time t_motor_lost = Modelica.Constants.inf "Time at which one motor is lost";
  final parameter SI.Inertia J = n_m*J_m*ratio^2 + J_g "Inertia at the output";
  final parameter Real k_w(unit="N.m.s/rad") = J/T_w "Gain of the speed loop";

  Modelica.Blocks.Interfaces.RealInput w_ref(unit="rad/s") "Commanded output speed"
    annotation (Placement(transformation(extent={{-140,-20},{-100,20}})));
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
  HighLift.Control.BrakeActuation pobActuation(t_rise=t_POB)
    annotation (Placement(transformation(extent={{0,40},{20,60}})));

  Integer n_active "Motors in operation";
  SI.AngularVelocity w_avail "Output speed available from the motors in operation";
  SI.AngularVelocity w_target "Speed command limited to the available speed";
  SI.AngularVelocity w_set(start=0, fixed=true) "Ramped speed set point";
  SI.Torque tau_lim "Torque limit at the current speed (stall torque and power)";
  SI.Torque tau_drive "Drive torque at the output";
  Boolean brakeApplied "= true, if the pressure-off brakes are applied";

equation
  // One motor lost: its pressure-off brake holds it, so the differential delivers the speed of
  // the remaining motors only (half speed with two motors) at full torque.
  n_active = if time >= t_motor_lost then n_m - 1 else n_m;
  w_avail = w_max*n_active/n_m;
  w_target = max(-w_avail, min(w_avail, w_ref));
  der(w_set) = max(-w_max/t_ramp, min(w_max/t_ramp, (w_target - w_set)/T_w));
  tau_lim = min(tau_stall, P_max/max(abs(inertia.w), Modelica.Constants.small));
  brakeApplied = abs(w_target) <= w_hold and abs(w_set) <= w_hold;
  tau_drive = if brakeApplied then 0 else max(-tau_lim, min(tau_lim, k_w*(w_set - inertia.w)));
  motorTorque.tau = tau_drive;
  pobActuation.trigger = brakeApplied;
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
  connect(pobActuation.y, pob.u)
    annotation (Line(points={{21,50},{30,50},{30,11}}, color={0,0,127}));

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
speed-controlled (as a variable-displacement hydraulic motor in a closed speed loop):
</p>
<pre>
  w_avail  = w_max*n_active/n_m                       (one motor lost: half speed)
  w_target = limit(w_ref, -w_avail, w_avail)
  der(w_set) = limit((w_target - w_set)/T_w, -w_max/t_ramp, w_max/t_ramp)      (speed ramp)
  tau_lim  = min(tau_stall, P_max/|w|)                (torque limit, full torque with one motor)
  tau      = limit(J/T_w*(w_set - w), -tau_lim, tau_lim)
</pre>
<p>
acting on the output inertia <code>J = n_m*J_m*ratio^2 + J_g</code>. When the command and the
set point are at rest (<code>|w| &le; w_hold</code>) the drive torque is removed and the POBs,
a <a href=\"modelica://HighLift.Mechanical.ShaftBrake\">ShaftBrake</a> with holding torque
<code>tauPOB</code>, engage within <code>t_POB</code>. From <code>t_motor_lost</code> on one
motor is lost.
</p>
</html>"));
end PDU;
