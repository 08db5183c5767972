within HighLift.Mechanical;
model NonlinearSpring "Torque limiter spring: three stiffnesses (figure 4) and normalized brake output y (equation 2)"
  import Modelica.Units.SI;
  extends Modelica.Mechanics.Rotational.Interfaces.PartialCompliantWithRelativeStates;

  parameter SI.Torque tau1_ext(min=0, start=470)
    "Lock-out torque tau_1 for positive phi_rel (extend direction)";
  parameter SI.Torque tau1_ret(min=0, start=470)
    "Lock-out torque tau_1 for negative phi_rel (retract direction), as a magnitude";
  parameter SI.Torque tau2_ext(min=0, start=590)
    "End-stop torque tau_2 for positive phi_rel (> tau1_ext)";
  parameter SI.Torque tau2_ret(min=0, start=590)
    "End-stop torque tau_2 for negative phi_rel (> tau1_ret), as a magnitude";
  parameter SI.RotationalSpringConstant c1(min=Modelica.Constants.small, start=2e4)
    "Stiffness in normal operation (balls seated)";
  parameter SI.RotationalSpringConstant c2(min=Modelica.Constants.small, start=1e3)
    "Stiffness during lock-out (balls running up the ramps)";
  parameter SI.RotationalSpringConstant c3(min=Modelica.Constants.small, start=1e5)
    "Stiffness at the end stop (device grounded)";
  parameter SI.RotationalDampingConstant d(min=0) = 0 "Damping constant";

  final parameter SI.Angle phi1_ext = tau1_ext/c1 "Relative angle at lock-out, extend";
  final parameter SI.Angle phi2_ext = phi1_ext + (tau2_ext - tau1_ext)/c2
    "Relative angle at the end stop, extend";
  final parameter SI.Angle phi1_ret = tau1_ret/c1 "Relative angle at lock-out (magnitude), retract";
  final parameter SI.Angle phi2_ret = phi1_ret + (tau2_ret - tau1_ret)/c2
    "Relative angle at the end stop (magnitude), retract";

  Modelica.Blocks.Interfaces.RealOutput y(min=0, max=1)
    "Normalized brake torque of the lock-out, equation (2)"
    annotation (Placement(transformation(
        origin={0,-110},
        extent={{-10,-10},{10,10}},
        rotation=270)));
  SI.Torque tau_c "Spring torque";

equation
  assert(tau2_ext > tau1_ext and tau2_ret > tau1_ret,
    "NonlinearSpring: the end-stop torques tau2 must exceed the lock-out torques tau1");
  tau_c = if phi_rel >= phi2_ext then tau2_ext + c3*(phi_rel - phi2_ext)
    else if phi_rel >= phi1_ext then tau1_ext + c2*(phi_rel - phi1_ext)
    else if phi_rel >= 0 then c1*phi_rel
    else if phi_rel > -phi1_ret then c1*phi_rel
    else if phi_rel > -phi2_ret then -tau1_ret + c2*(phi_rel + phi1_ret)
    else -tau2_ret + c3*(phi_rel + phi2_ret);
  tau = tau_c + d*w_rel;
  y = if phi_rel >= phi2_ext or phi_rel <= -phi2_ret then 1
    else if phi_rel >= phi1_ext then (phi_rel - phi1_ext)/(phi2_ext - phi1_ext)
    else if phi_rel <= -phi1_ret then (-phi_rel - phi1_ret)/(phi2_ret - phi1_ret)
    else 0;

  annotation (
    Icon(coordinateSystem(preserveAspectRatio=true, extent={{-100,-100},{100,100}}),
      graphics={
        Line(points={{-100,0},{-58,0},{-43,-30},{-13,30},{17,-30},{47,30},{62,0},{100,0}},
          color={0,0,0}),
        Line(points={{-60,-70},{-20,-60},{20,-20},{60,40}}, color={255,0,0}, thickness=0.5),
        Text(extent={{-150,80},{150,40}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>
The spring of a ball-ramp torque limiter (figure 4 of the paper). In normal operation the balls
sit in their pockets and the device is stiff (<code>c1</code>). Above the lock-out torque
<code>tau1</code> the balls run up their ramps, the stiffness drops to <code>c2</code> and a
friction device is pressed on; when the balls reach their end stop at <code>tau2</code> the
device is grounded and the stiffness is <code>c3</code>. With
<code>phi1 = tau1/c1</code> and <code>phi2 = phi1 + (tau2 - tau1)/c2</code>, for
<code>phi_rel &ge; 0</code>:
</p>
<pre>
  tau = c1*phi_rel                          phi_rel &lt; phi1
  tau = tau1 + c2*(phi_rel - phi1)           phi1 &le; phi_rel &lt; phi2
  tau = tau2 + c3*(phi_rel - phi2)           phi2 &le; phi_rel
</pre>
<p>
and mirrored with the retract settings for <code>phi_rel &lt; 0</code> (torque limiters trip
at a lower torque in retract than in extend); <code>d*w_rel</code> is added. The output
<code>y</code> is the normalized brake torque of equation (2):
</p>
<pre>
  y = 0                                  |phi_rel| &lt; phi1
  y = (|phi_rel| - phi1)/(phi2 - phi1)   phi1 &le; |phi_rel| &lt; phi2
  y = 1                                  |phi_rel| &ge; phi2
</pre>
<p>
(The paper prints the first case as <code>phi_rel &lt; phi1</code>; the magnitude is meant,
as in the other two cases.) Torque and output are continuous in <code>phi_rel</code>.
</p>
</html>"));
end NonlinearSpring;
