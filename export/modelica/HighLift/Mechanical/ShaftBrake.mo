within HighLift.Mechanical;
model ShaftBrake "Brake between the shaft and the housing, commanded by the normalized dynamic brake torque"
  import Modelica.Units.SI;
  extends Modelica.Mechanics.Rotational.Interfaces.PartialElementaryTwoFlangesAndSupport2;
  extends Modelica.Mechanics.Rotational.Interfaces.PartialFriction;
  extends Modelica.Thermal.HeatTransfer.Interfaces.PartialElementaryConditionalHeatPortWithoutT;

  parameter SI.Torque tauB_max(min=0, start=500)
    "Maximum dynamic (sliding) brake torque, reached at u = 1";
  parameter SI.Torque tauB_lim(min=0, start=700)
    "Maximum static (holding) brake torque after the halt, reached at u = 1 (>= tauB_max)";

  Modelica.Blocks.Interfaces.RealInput u(min=0, max=1)
    "Normalized maximum dynamic brake torque, 0 (released) ... 1 (fully applied)"
    annotation (Placement(transformation(
        origin={0,110},
        extent={{20,-20},{-20,20}},
        rotation=90)));

  SI.Angle phi "Angle of the shaft (flange_a and flange_b) relative to the support";
  SI.AngularVelocity w "Speed of the shaft relative to the support";
  SI.AngularAcceleration a "Acceleration of the shaft relative to the support";
  SI.Torque tau "Brake torque, positive when it opposes forward rotation";

equation
  assert(tauB_lim >= tauB_max, "ShaftBrake: tauB_lim must not be smaller than tauB_max");
  phi = flange_a.phi - phi_support;
  flange_b.phi = flange_a.phi;
  w = der(phi);
  a = der(w);
  w_relfric = w;
  a_relfric = a;

  // The brake absorbs tau: the shaft feels -tau, the support +tau.
  flange_a.tau + flange_b.tau - tau = 0;

  // Friction torques at zero speed: sliding (dynamic) and breakaway (static) capacity.
  tau0 = max(u, 0)*tauB_max;
  tau0_max = max(u, 0)*tauB_lim;
  free = u <= 0;

  // Sliding: the dynamic brake torque against the direction of motion; stuck: constraint torque.
  tau = if locked then sa*unitTorque else if free then 0 else
    (if startForward then tau0 else if startBackward then -tau0 else
     if pre(mode) == Forward then tau0 else -tau0);
  lossPower = tau*w_relfric;

  annotation (
    Icon(coordinateSystem(preserveAspectRatio=true, extent={{-100,-100},{100,100}}),
      graphics={
        Rectangle(extent={{-100,10},{-20,-10}}, lineColor={64,64,64},
          fillColor={192,192,192}, fillPattern=FillPattern.HorizontalCylinder),
        Rectangle(extent={{20,10},{100,-10}}, lineColor={64,64,64},
          fillColor={192,192,192}, fillPattern=FillPattern.HorizontalCylinder),
        Rectangle(extent={{-20,60},{20,-60}}, lineColor={64,64,64},
          fillColor={255,255,255}, fillPattern=FillPattern.HorizontalCylinder, radius=10),
        Rectangle(extent={{-40,-25},{-30,-55}}, fillPattern=FillPattern.Solid),
        Rectangle(extent={{30,-25},{40,-55}}, fillPattern=FillPattern.Solid),
        Line(points={{0,90},{-80,70},{-80,-40},{-70,-40}}, color={0,0,127}),
        Line(points={{0,90},{80,70},{80,-40},{70,-40}}, color={0,0,127}),
        Text(extent={{-150,-140},{150,-180}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>
The brake function of a wing-tip brake (WTB) or a pressure-off brake: when applied, friction
packs between the shaft and the housing produce a torque that stops the transmission and then
holds it. The model needs only the data of a specification: the maximum dynamic brake torque
<code>tauB_max</code> and the maximum static brake torque <code>tauB_lim</code>. The input
<code>u</code> is the normalized dynamic brake torque, so that the transient build-up of the
brake torque (for instance the time to reach the maximum dynamic torque) is described by the
signal that drives <code>u</code> (see
<a href=\"modelica://HighLift.Control.BrakeActuation\">BrakeActuation</a>); friction
coefficients are not needed.
</p>
<p>
With <code>w</code> the shaft speed relative to the support:
</p>
<pre>
  free   (u &lt;= 0):  tau = 0
  sliding (w &ne; 0):  tau = sign(w) * u * tauB_max
  stuck  (w = 0):    |tau| &lt;= u * tauB_lim   (torque from the balance of the connected parts)
</pre>
<p>
After reaching a halt the static friction torque may rise up to the brake's limit load
<code>tauB_lim</code>; the brake slips again when the torque needed to hold the shaft exceeds
it. Stick/slip switching uses the state machine of
<code>Modelica.Mechanics.Rotational.Interfaces.PartialFriction</code> (the same as the MSL
<code>Brake</code>): <code>tau0 = u*tauB_max</code> is the sliding torque at zero speed and
<code>tau0_max = u*tauB_lim</code> the breakaway torque.
</p>
</html>"));
end ShaftBrake;
