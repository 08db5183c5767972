within HighLift.Mechanical;
model GeneralRotationalElement "General rotational element: ElastoBacklash, LossyInertia and IdealGear in series"
  import Modelica.Units.SI;
  extends Modelica.Mechanics.Rotational.Interfaces.PartialTwoFlangesAndSupport;

  parameter Boolean elastic = true
    "= true, if the element has a stiffness (and backlash); otherwise rigid"
    annotation (Evaluate=true, choices(checkBox=true));
  parameter SI.RotationalSpringConstant c(min=Modelica.Constants.small) = 1e4
    "Torsional stiffness (used only when elastic = true: give it then)" annotation (Dialog(enable=elastic));
  parameter SI.RotationalDampingConstant d(min=0) = 0 "Structural damping"
    annotation (Dialog(enable=elastic));
  parameter SI.Angle b(min=0) = 0 "Total backlash" annotation (Dialog(enable=elastic));
  parameter SI.Inertia J(min=0, start=1e-3) "Moment of inertia (at the flange_a side of the gear)";
  parameter SI.Torque tau_C(min=0) = 0 "Coulomb friction torque, equation (3)";
  parameter SI.RotationalDampingConstant d_vis(min=0) = 0 "Viscous friction coefficient, equation (3)";
  parameter SI.Torque tau_S(min=0) = 0 "Stribeck torque at standstill, equation (3)";
  parameter Real f_exp(unit="s/rad", min=0) = 10 "Decay of the Stribeck torque with speed, equation (3)";
  parameter Real peak(min=1) = 1 "Static friction at standstill = peak*(tau_C + tau_S)";
  parameter Real eta_GE(min=0, max=1) = 1 "Gearbox efficiency of the load-dependent loss, equation (4)";
  parameter SI.AngularVelocity w_small(min=0) = 0
    "Regularisation speed: 0 = exact stick/slip; > 0 = friction scaled by tanh(w/w_small), no stick/slip";
  parameter Real ratio(start=1) "Gear ratio, speed of flange_a / speed of flange_b";

  Modelica.Mechanics.Rotational.Components.ElastoBacklash elastoBacklash(c=c, d=d, b=b) if elastic
    annotation (Placement(transformation(extent={{-70,-10},{-50,10}})));
  LossyInertia lossyInertia(J=J, tau_C=tau_C, d_vis=d_vis, tau_S=tau_S, f_exp=f_exp, peak=peak,
    eta_GE=eta_GE, w_small=w_small, useSupport=true)
    annotation (Placement(transformation(extent={{-10,-10},{10,10}})));
  Modelica.Mechanics.Rotational.Components.IdealGear idealGear(ratio=ratio, useSupport=true)
    annotation (Placement(transformation(extent={{50,-10},{70,10}})));

equation
  connect(flange_a, elastoBacklash.flange_a)
    annotation (Line(points={{-100,0},{-70,0}}));
  connect(elastoBacklash.flange_b, lossyInertia.flange_a)
    annotation (Line(points={{-50,0},{-10,0}}));
  if not elastic then
    connect(flange_a, lossyInertia.flange_a)
      annotation (Line(points={{-100,0},{-80,0},{-80,20},{-20,20},{-20,0},{-10,0}}));
  end if;
  connect(lossyInertia.flange_b, idealGear.flange_a)
    annotation (Line(points={{10,0},{50,0}}));
  connect(idealGear.flange_b, flange_b)
    annotation (Line(points={{70,0},{100,0}}));
  connect(lossyInertia.support, internalSupport)
    annotation (Line(points={{0,-10},{0,-80}}));
  connect(idealGear.support, internalSupport)
    annotation (Line(points={{60,-10},{60,-80},{0,-80}}));

  annotation (
    Icon(coordinateSystem(preserveAspectRatio=true, extent={{-100,-100},{100,100}}),
      graphics={
        Rectangle(extent={{-100,10},{100,-10}}, lineColor={64,64,64},
          fillColor={192,192,192}, fillPattern=FillPattern.HorizontalCylinder),
        Line(points={{-90,0},{-80,-20},{-70,20},{-60,-20},{-50,20},{-40,0}}, color={0,0,0}),
        Rectangle(extent={{-30,40},{10,-40}}, lineColor={64,64,64},
          fillColor={192,192,192}, fillPattern=FillPattern.HorizontalCylinder),
        Rectangle(extent={{30,60},{50,-60}}, lineColor={64,64,64},
          fillColor={255,255,255}, fillPattern=FillPattern.HorizontalCylinder),
        Rectangle(extent={{60,30},{80,-30}}, lineColor={64,64,64},
          fillColor={255,255,255}, fillPattern=FillPattern.HorizontalCylinder),
        Text(extent={{-150,110},{150,70}}, textString="%name", textColor={0,0,255}),
        Text(extent={{-150,-80},{150,-110}}, textString="ratio=%ratio")}),
    Documentation(info="<html>
<p>
The general rotational element of the paper: most mechanical parts of the transmission
(gearboxes, joints, bearings with their shaft sections) are characterised by their inertia,
torsional stiffness, structural damping, backlash, gear ratio and friction. The element puts in
series, from <code>flange_a</code> to <code>flange_b</code>:
</p>
<ol>
<li><code>Modelica.Mechanics.Rotational.Components.ElastoBacklash</code> (<code>c</code>,
    <code>d</code>, <code>b</code>); left out when <code>elastic = false</code>;</li>
<li><a href=\"modelica://HighLift.Mechanical.LossyInertia\">LossyInertia</a> (<code>J</code>,
    Stribeck friction of equation 3, load-dependent loss of equation 4; regularised without
    stick/slip when <code>w_small &gt; 0</code>);</li>
<li><code>Modelica.Mechanics.Rotational.Components.IdealGear</code>
    (<code>ratio</code> = speed of flange_a / speed of flange_b).</li>
</ol>
<p>
Inertia and friction are at the speed of <code>flange_a</code>; the housing reacts the
friction and the gear reaction torque.
</p>
</html>"));
end GeneralRotationalElement;
