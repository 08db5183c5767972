within HighLift.Hydraulics;
model MotorSpeedControl "Speed loop of a secondary-controlled motor: PI on the speed commands the displacement, position loop on the displacement cylinder"
  import Modelica.Units.SI;
  parameter Real ratio(min=Modelica.Constants.small) = 20 "Motor speed / PDU output speed";
  parameter Real k_w(unit="s/rad", min=0) = 1e-3 "Displacement command per motor speed error";
  parameter SI.Time T_i(min=Modelica.Constants.small) = 0.1 "Integral time of the speed loop";
  parameter Real k_s(min=0) = 1 "Valve command per displacement error";
  parameter SI.Length s_max(min=Modelica.Constants.small) = 0.02 "Stroke of the displacement cylinder";
  parameter Real eps_max(min=0, max=1) = 1 "Limit of the displacement command";

  Modelica.Blocks.Interfaces.RealInput w_ref(unit="rad/s") "Commanded PDU output speed"
    annotation (Placement(transformation(extent={{-140,20},{-100,60}})));
  Modelica.Blocks.Interfaces.RealInput active "1: motor in operation, 0: motor lost"
    annotation (Placement(transformation(extent={{-140,-60},{-100,-20}})));
  Modelica.Mechanics.Rotational.Interfaces.Flange_a flange_m "Motor shaft (speed sensed)"
    annotation (Placement(transformation(extent={{-10,90},{10,110}})));
  Modelica.Mechanics.Translational.Interfaces.Flange_a flange_s "Rod of the displacement cylinder (position sensed)"
    annotation (Placement(transformation(extent={{-10,-110},{10,-90}})));
  Modelica.Blocks.Interfaces.RealOutput u "Servo valve command"
    annotation (Placement(transformation(extent={{100,30},{120,50}})));
  Modelica.Blocks.Interfaces.RealOutput eps "Normalized motor displacement from the rod position"
    annotation (Placement(transformation(extent={{100,-50},{120,-30}})));

  Real z(start=0, fixed=true) "Integral of the motor speed error";
  SI.AngularVelocity e_w "Motor speed error";
  Real raw "Unlimited displacement command";
  Real eps_ref "Displacement command";

equation
  flange_m.tau = 0;
  flange_s.f = 0;
  e_w = ratio*w_ref - der(flange_m.phi);
  raw = k_w*(e_w + z/T_i);
  eps_ref = if active > 0.5 then max(-eps_max, min(eps_max, raw)) else 0;
  der(z) = if active > 0.5 then e_w + (if k_w > 0 then (eps_ref - raw)/k_w else 0) else 0;
  eps = 2*flange_s.s/s_max - 1;
  u = max(-1, min(1, k_s*(eps_ref - eps)));

  annotation (
    Icon(coordinateSystem(preserveAspectRatio=true, extent={{-100,-100},{100,100}}),
      graphics={
        Rectangle(extent={{-100,100},{100,-100}}, lineColor={0,0,127}),
        Text(extent={{-80,40},{80,-40}}, textString="PI", textColor={0,0,127}),
        Text(extent={{-150,150},{150,110}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>
Secondary control of a variable-displacement motor on constant supply pressure: a PI loop on the
motor speed (reference <code>ratio*w_ref</code>) commands the normalized displacement, with
back-calculation anti-windup; a proportional loop strokes the displacement cylinder through the
servo valve, the displacement being read from the rod position
(<code>eps = 2*s/s_max - 1</code>). With <code>active</code> &lt; 0.5 (motor lost) the
displacement is commanded to zero.
</p>
</html>"));
end MotorSpeedControl;
