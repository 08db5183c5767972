within HighLift.Mechanical;
model GearedRotaryActuator "Geared rotary actuator: single-stage gearbox whose efficiency depends on the input angle after a reversal"
  import Modelica.Units.SI;
  extends Modelica.Mechanics.Rotational.Interfaces.PartialTwoFlangesAndSupport;

  parameter Real ratio(start=200) "Gear ratio, input speed / output speed";
  parameter Real eta_op(min=0, max=1) = 0.85 "Efficiency driving against an opposing load";
  parameter Real eta_ai(min=0, max=1) = 0.70 "Efficiency with an aiding (back-driving) load";
  parameter SI.Angle phi_eta(min=Modelica.Constants.small) = 3.14
    "Input angle over which the efficiency settles after a start or reversal (figure 7b)";
  parameter SI.AngularVelocity w_eta(min=Modelica.Constants.small) = 0.1
    "Input speed below which the efficiency rises linearly to 1 when stopping (figure 7a)";
  parameter SI.Inertia J_in(min=0, start=1e-3) "Inertia referred to the input";
  parameter SI.Inertia J_load(min=0) = 0 "Flap inertia reflected to the input";
  parameter Boolean elastic = false "= true, if the actuator has a stiffness (and backlash)"
    annotation (Evaluate=true, choices(checkBox=true));
  parameter SI.RotationalSpringConstant c(min=Modelica.Constants.small) = 1e4
    "Torsional stiffness referred to the input (used only when elastic = true: give it then)" annotation (Dialog(enable=elastic));
  parameter SI.RotationalDampingConstant d(min=0) = 0 "Damping referred to the input"
    annotation (Dialog(enable=elastic));
  parameter SI.Angle b(min=0) = 0 "Total backlash referred to the input"
    annotation (Dialog(enable=elastic));
  parameter SI.Torque tau_C(min=0) = 0 "Coulomb friction torque, equation (3)";
  parameter SI.RotationalDampingConstant d_vis(min=0) = 0 "Viscous friction coefficient, equation (3)";
  parameter SI.Torque tau_S(min=0) = 0 "Stribeck torque at standstill, equation (3)";
  parameter Real f_exp(unit="s/rad", min=0) = 10 "Decay of the Stribeck torque with speed, equation (3)";
  parameter Real peak(min=1) = 1 "Static friction at standstill = peak*(tau_C + tau_S)";
  parameter SI.AngularVelocity w_small(min=0) = 0
    "Regularisation speed: 0 = exact stick/slip; > 0 = friction and load loss scaled by tanh(w/w_small), no stick/slip";

  Modelica.Mechanics.Rotational.Components.ElastoBacklash elastoBacklash(c=c, d=d, b=b) if elastic
    annotation (Placement(transformation(extent={{-90,-10},{-70,10}})));
  Modelica.Mechanics.Rotational.Components.Inertia inputInertia(J=J_in)
    annotation (Placement(transformation(extent={{-60,-10},{-40,10}})));
  StribeckFriction friction(tau_C=tau_C, d_vis=d_vis, tau_S=tau_S, f_exp=f_exp, peak=peak,
    w_small=w_small, useEfficiencyInput=true, useSupport=true)
    annotation (Placement(transformation(extent={{-20,-10},{0,10}})));
  Modelica.Mechanics.Rotational.Components.IdealGear idealGear(ratio=ratio, useSupport=true)
    annotation (Placement(transformation(extent={{20,-10},{40,10}})));
  Modelica.Mechanics.Rotational.Components.Inertia loadInertia(J=J_load*ratio^2)
    annotation (Placement(transformation(extent={{60,-10},{80,10}})));
  Modelica.Blocks.Interfaces.RealOutput eta_GE "Gearbox efficiency in use"
    annotation (Placement(transformation(extent={{100,50},{120,70}})));

  Real e_angle(min=0, max=1) "Mesh engagement after the last start or reversal, by input angle";
  Real e_speed(min=0, max=1) "Mesh engagement by input speed (falls to 0 when stopping)";
  Real eta_end(min=0, max=1) "Final efficiency for the current direction of power flow";
  discrete SI.Angle phi_start "Input angle at the last start, stop or reversal";

protected
  final parameter Boolean regularised = w_small > 0
    "= true: the friction has no stick/slip modes; figure 7 restarts at the speed reversals";

initial equation
  pre(phi_start) = friction.phi;

equation
  // Figure 7: after a start or reversal the teeth come into contact one after the other, so
  // the load-dependent loss builds up over the input angle phi_eta; when the unit stops, the
  // efficiency rises linearly to 1 below the speed w_eta.
  // The start angle: at each change of the friction mode (stick/slip), or with the regularised
  // friction (no modes) at each zero crossing of the input speed (a start or a reversal).
  when {not regularised and change(friction.mode), regularised and friction.w > 0,
      regularised and friction.w < 0} then
    phi_start = friction.phi;
  end when;
  e_angle = min(1, abs(friction.phi - phi_start)/phi_eta);
  e_speed = min(1, abs(friction.w)/w_eta);
  // Power into the actuator (load opposing the motion) or out of it (aiding load).
  eta_end = if friction.tau_load*friction.w >= 0 then eta_op else eta_ai;
  eta_GE = 1 - min(e_angle, e_speed)*(1 - eta_end);
  connect(eta_GE, friction.eta);

  connect(flange_a, elastoBacklash.flange_a)
    annotation (Line(points={{-100,0},{-90,0}}));
  connect(elastoBacklash.flange_b, inputInertia.flange_a)
    annotation (Line(points={{-70,0},{-60,0}}));
  if not elastic then
    connect(flange_a, inputInertia.flange_a)
      annotation (Line(points={{-100,0},{-96,0},{-96,20},{-64,20},{-64,0},{-60,0}}));
  end if;
  connect(inputInertia.flange_b, friction.flange_a)
    annotation (Line(points={{-40,0},{-20,0}}));
  connect(friction.flange_b, idealGear.flange_a)
    annotation (Line(points={{0,0},{20,0}}));
  connect(idealGear.flange_b, loadInertia.flange_a)
    annotation (Line(points={{40,0},{60,0}}));
  connect(loadInertia.flange_b, flange_b)
    annotation (Line(points={{80,0},{100,0}}));
  connect(friction.support, internalSupport)
    annotation (Line(points={{-10,-10},{-10,-80},{0,-80}}));
  connect(idealGear.support, internalSupport)
    annotation (Line(points={{30,-10},{30,-80},{0,-80}}));

  annotation (
    Icon(coordinateSystem(preserveAspectRatio=true, extent={{-100,-100},{100,100}}),
      graphics={
        Rectangle(extent={{-100,10},{-60,-10}}, lineColor={64,64,64},
          fillColor={192,192,192}, fillPattern=FillPattern.HorizontalCylinder),
        Ellipse(extent={{-60,60},{60,-60}}, lineColor={64,64,64},
          fillColor={255,255,255}, fillPattern=FillPattern.Sphere),
        Ellipse(extent={{-20,20},{20,-20}}, lineColor={64,64,64},
          fillColor={160,160,164}, fillPattern=FillPattern.Solid),
        Rectangle(extent={{60,10},{100,-10}}, lineColor={64,64,64},
          fillColor={192,192,192}, fillPattern=FillPattern.HorizontalCylinder),
        Text(extent={{-150,110},{150,70}}, textString="%name", textColor={0,0,255}),
        Text(extent={{-150,-70},{150,-100}}, textString="ratio=%ratio")}),
    Documentation(info="<html>
<p>
A geared rotary actuator (compound planetary gear with high reduction) modelled as a single
gear stage. From the input <code>flange_a</code> (transmission) to the output
<code>flange_b</code> (flap): optional <code>ElastoBacklash</code>, the input inertia
<code>J_in</code>, the friction of
<a href=\"modelica://HighLift.Mechanical.StribeckFriction\">StribeckFriction</a> (equations 3
and 4), an <code>IdealGear</code> and the flap inertia (<code>J_load</code> reflected to the
input, i.e. <code>J_load*ratio^2</code> at the output).
</p>
<p>
The load-dependent loss depends on the direction of power flow: driving against an opposing
load the efficiency is <code>eta_op</code>, with an aiding load <code>eta_ai</code>
(<code>eta_op &gt; eta_ai</code> in general). It does not appear stepwise when the unit
starts to move but builds up as the teeth come into contact (figure 7):
</p>
<pre>
  e_angle = min(1, |phi_in - phi_start|/phi_eta)   phi_start: input angle at the last start/stop/reversal
  e_speed = min(1, |w_in|/w_eta)
  eta_GE  = 1 - min(e_angle, e_speed)*(1 - eta_end),   eta_end = eta_op or eta_ai
</pre>
<p>
so that when the unit stops, <code>eta_GE</code> rises linearly to 1 below the speed threshold
<code>w_eta</code> (figure 7a) and the load-dependent friction disappears; when it starts again,
<code>eta_GE</code> is a function of the input angle <code>phi_in</code> and settles to the
final value for the sign of the transmitted power (figure 7b). The start angle
<code>phi_start</code> is taken at each change of the friction mode (start, stop, reversal);
with the regularised friction (<code>w_small &gt; 0</code>, no stick/slip modes, see
<a href=\"modelica://HighLift.Mechanical.StribeckFriction\">StribeckFriction</a>) at each zero
crossing of the input speed, as in the simulator.
</p>
</html>"));
end GearedRotaryActuator;
