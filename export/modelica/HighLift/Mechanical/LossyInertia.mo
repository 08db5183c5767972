within HighLift.Mechanical;
model LossyInertia "Inertia with Stribeck bearing friction and load-dependent gear loss to the housing"
  import Modelica.Units.SI;
  extends Modelica.Mechanics.Rotational.Interfaces.PartialTwoFlangesAndSupport;

  parameter SI.Inertia J(min=0, start=1e-3) "Moment of inertia";
  parameter SI.Torque tau_C(min=0) = 0 "Coulomb friction torque, equation (3)";
  parameter SI.RotationalDampingConstant d_vis(min=0) = 0 "Viscous friction coefficient, equation (3)";
  parameter SI.Torque tau_S(min=0) = 0 "Stribeck torque at standstill, equation (3)";
  parameter Real f_exp(unit="s/rad", min=0) = 10 "Decay of the Stribeck torque with speed, equation (3)";
  parameter Real peak(min=1) = 1 "Static friction at standstill = peak*(tau_C + tau_S)";
  parameter Real eta_GE(min=0, max=1) = 1 "Gearbox efficiency of the load-dependent loss, equation (4)";
  parameter SI.AngularVelocity w_small(min=0) = 0
    "Regularisation speed: 0 = exact stick/slip; > 0 = friction scaled by tanh(w/w_small), no stick/slip";

  Modelica.Mechanics.Rotational.Components.Inertia inertia(J=J)
    annotation (Placement(transformation(extent={{-60,-10},{-40,10}})));
  StribeckFriction friction(tau_C=tau_C, d_vis=d_vis, tau_S=tau_S, f_exp=f_exp, peak=peak,
    w_small=w_small, eta_GE=eta_GE, useSupport=true)
    annotation (Placement(transformation(extent={{20,-10},{40,10}})));

equation
  connect(flange_a, inertia.flange_a)
    annotation (Line(points={{-100,0},{-60,0}}));
  connect(inertia.flange_b, friction.flange_a)
    annotation (Line(points={{-40,0},{20,0}}));
  connect(friction.flange_b, flange_b)
    annotation (Line(points={{40,0},{100,0}}));
  connect(friction.support, internalSupport)
    annotation (Line(points={{30,-10},{30,-80},{0,-80}}));

  annotation (
    Icon(coordinateSystem(preserveAspectRatio=true, extent={{-100,-100},{100,100}}),
      graphics={
        Rectangle(extent={{-100,10},{-50,-10}}, lineColor={64,64,64},
          fillColor={192,192,192}, fillPattern=FillPattern.HorizontalCylinder),
        Rectangle(extent={{50,10},{100,-10}}, lineColor={64,64,64},
          fillColor={192,192,192}, fillPattern=FillPattern.HorizontalCylinder),
        Rectangle(extent={{-50,50},{50,-50}}, lineColor={64,64,64},
          fillColor={192,192,192}, fillPattern=FillPattern.HorizontalCylinder, radius=10),
        Line(points={{-50,-70},{50,-70}}, color={0,0,0}),
        Text(extent={{-150,100},{150,60}}, textString="%name", textColor={0,0,255}),
        Text(extent={{-150,-80},{150,-110}}, textString="J=%J")}),
    Documentation(info="<html>
<p>
The modified inertia of the paper (<em>LossyInertia</em>): a rigid rotating mass
<code>J</code> whose bearings and gear stages cause friction losses to the housing,
</p>
<pre>
  J*der(w) = flange_a.tau + flange_b.tau - tau_fric
  tau_fric = tau_C + d_vis*|w| + tau_S*exp(-f_exp*|w|) + (1 - eta_GE)*|tau_load|   (sliding)
</pre>
<p>
(equations 3 and 4, see <a href=\"modelica://HighLift.Mechanical.StribeckFriction\">StribeckFriction</a>),
with stiction at standstill, or with <code>w_small &gt; 0</code> the regularised law
<code>tau_fric = tanh(w/w_small)*(tau_C + tau_S*exp(-f_exp*|w|) + (1 - eta_GE)*|tau_load|) + d_vis*w</code>
without stick/slip. The housing reacts the friction torque only; with
<code>useSupport=true</code> it is available at the support flange.
</p>
</html>"));
end LossyInertia;
