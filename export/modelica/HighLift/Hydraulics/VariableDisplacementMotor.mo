within HighLift.Hydraulics;
model VariableDisplacementMotor "Variable-displacement hydraulic motor (VDHM) with leakage"
  import Modelica.Units.SI;
  extends Modelica.Mechanics.Rotational.Interfaces.PartialElementaryOneFlangeAndSupport2;

  parameter Real D_max(unit="m3/rad", min=0) = 13.4e-6/(2*Modelica.Constants.pi)
    "Displacement per radian at full swash angle";
  parameter Real G_leak(unit="m3/(s.Pa)", min=0) = 1e-13 "Leakage conductance from A to B";
  parameter Real eta_m(min=Modelica.Constants.small, max=1) = 0.95
    "Mechanical efficiency (torque loss, in both directions of power flow)";

  Modelica.Blocks.Interfaces.RealInput eps "Normalized displacement (swash angle), -1 ... 1"
    annotation (Placement(transformation(
        origin={0,120},
        extent={{20,-20},{-20,20}},
        rotation=90)));
  Interfaces.Port port_A "High-pressure port for positive rotation"
    annotation (Placement(transformation(extent={{-110,-70},{-90,-50}})));
  Interfaces.Port port_B "Low-pressure port for positive rotation"
    annotation (Placement(transformation(extent={{-110,50},{-90,70}})));

  SI.Angle phi "Shaft angle relative to the housing";
  SI.AngularVelocity w "Shaft speed relative to the housing";
  SI.Torque tau_i "Ideal hydraulic torque eps*D_max*(p_A - p_B)";
  SI.Torque tau "Torque delivered to the shaft";
  SI.VolumeFlowRate V_flow "Volume flow rate through the motor from A to B";

equation
  phi = flange.phi - phi_support;
  w = der(phi);
  tau_i = max(-1, min(1, eps))*D_max*(port_A.p - port_B.p);
  // Mechanical losses reduce the torque when the motor drives and increase it when it is driven.
  tau = if tau_i*w >= 0 then eta_m*tau_i else tau_i/eta_m;
  V_flow = max(-1, min(1, eps))*D_max*w + G_leak*(port_A.p - port_B.p);
  port_A.V_flow = V_flow;
  port_B.V_flow = -V_flow;
  flange.tau = -tau;

  annotation (
    Icon(coordinateSystem(preserveAspectRatio=true, extent={{-100,-100},{100,100}}),
      graphics={
        Ellipse(extent={{-70,70},{70,-70}}, lineColor={0,0,255}),
        Line(points={{-40,-60},{40,60}}, color={0,0,255}, arrow={Arrow.None,Arrow.Filled}),
        Rectangle(extent={{70,10},{100,-10}}, lineColor={64,64,64},
          fillColor={192,192,192}, fillPattern=FillPattern.HorizontalCylinder),
        Text(extent={{-150,-80},{150,-120}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>
A variable-displacement hydraulic motor (VDHM), the motor of a hydraulic PDU. The swash angle
is commanded by the normalized displacement <code>eps</code>:
</p>
<pre>
  V_flow = eps*D_max*w + G_leak*(p_A - p_B)
  tau_i  = eps*D_max*(p_A - p_B)
  tau    = eta_m*tau_i  (motor drives the shaft),  tau_i/eta_m  (shaft drives the motor)
</pre>
<p>
<code>tau</code> acts on <code>flange</code>; the housing reacts it.
</p>
</html>"));
end VariableDisplacementMotor;
