within HighLift.Mechanical;
model TorqueLimiter "Ideal mechanical torque limiter: nonlinear spring and shaft brake to the housing (figure 5)"
  import Modelica.Units.SI;
  extends Modelica.Mechanics.Rotational.Interfaces.PartialTwoFlangesAndSupport;

  parameter SI.Torque tau1_ext(min=0, start=470) "Lock-out torque, extend direction";
  parameter SI.Torque tau1_ret(min=0, start=470) "Lock-out torque (magnitude), retract direction";
  parameter SI.Torque tau2_ext(min=0, start=590) "End-stop torque, extend direction (> tau1_ext)";
  parameter SI.Torque tau2_ret(min=0, start=590) "End-stop torque (magnitude), retract direction (> tau1_ret)";
  parameter SI.RotationalSpringConstant c1(min=Modelica.Constants.small, start=2e4)
    "Stiffness in normal operation";
  parameter SI.RotationalSpringConstant c2(min=Modelica.Constants.small, start=1e3)
    "Stiffness during lock-out";
  parameter SI.RotationalSpringConstant c3(min=Modelica.Constants.small, start=1e5)
    "Stiffness at the end stop";
  parameter SI.RotationalDampingConstant d(min=0) = 0 "Damping of the spring";
  parameter SI.Torque tauB_max(min=0, start=940)
    "Dynamic brake torque to the housing at the end stop (y = 1)";
  parameter SI.Torque tauB_lim(min=0) = tauB_max
    "Static brake torque to the housing at the end stop (>= tauB_max)";
  parameter SI.Inertia J(min=0) = 0 "Inertia of the limiter, on the input side";

  Modelica.Mechanics.Rotational.Components.Inertia inertia(J=J)
    annotation (Placement(transformation(extent={{-80,-10},{-60,10}})));
  ShaftBrake brake(tauB_max=tauB_max, tauB_lim=tauB_lim, useSupport=true)
    annotation (Placement(transformation(extent={{-40,-10},{-20,10}})));
  NonlinearSpring spring(tau1_ext=tau1_ext, tau1_ret=tau1_ret, tau2_ext=tau2_ext,
    tau2_ret=tau2_ret, c1=c1, c2=c2, c3=c3, d=d)
    annotation (Placement(transformation(extent={{10,-10},{30,10}})));
  Modelica.Blocks.Interfaces.RealOutput y "Normalized lock-out brake torque (lock-out indicator)"
    annotation (Placement(transformation(extent={{100,-70},{120,-50}})));

equation
  connect(flange_a, inertia.flange_a)
    annotation (Line(points={{-100,0},{-80,0}}));
  connect(inertia.flange_b, brake.flange_a)
    annotation (Line(points={{-60,0},{-40,0}}));
  connect(brake.flange_b, spring.flange_a)
    annotation (Line(points={{-20,0},{10,0}}));
  connect(spring.flange_b, flange_b)
    annotation (Line(points={{30,0},{100,0}}));
  connect(brake.support, internalSupport)
    annotation (Line(points={{-30,-10},{-30,-80},{0,-80}}));
  connect(spring.y, brake.u)
    annotation (Line(points={{20,-11},{20,-30},{-6,-30},{-6,30},{-30,30},{-30,11}}, color={0,0,127}));
  connect(spring.y, y)
    annotation (Line(points={{20,-11},{20,-60},{110,-60}}, color={0,0,127}));

  annotation (
    Icon(coordinateSystem(preserveAspectRatio=true, extent={{-100,-100},{100,100}}),
      graphics={
        Rectangle(extent={{-100,10},{-60,-10}}, lineColor={64,64,64},
          fillColor={192,192,192}, fillPattern=FillPattern.HorizontalCylinder),
        Rectangle(extent={{60,10},{100,-10}}, lineColor={64,64,64},
          fillColor={192,192,192}, fillPattern=FillPattern.HorizontalCylinder),
        Rectangle(extent={{-60,50},{-10,-50}}, lineColor={64,64,64},
          fillColor={255,255,255}, fillPattern=FillPattern.HorizontalCylinder),
        Rectangle(extent={{10,50},{60,-50}}, lineColor={64,64,64},
          fillColor={255,255,255}, fillPattern=FillPattern.HorizontalCylinder),
        Ellipse(extent={{-12,12},{12,-12}}, lineColor={0,0,0},
          fillColor={95,95,95}, fillPattern=FillPattern.Sphere),
        Text(extent={{-150,100},{150,60}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>
A ball-ramp torque limiter (system torque limiter at the PDU output, or station torque limiter
before an actuator). Balls embedded along the circumference of two flanges give a positive
connection in normal operation. Above the lock-out torque the balls run up their ramps and
push one flange against a friction device; the brake torque grows with the relative angle and
reaches its maximum when the balls hit their end stop.
</p>
<p>
The model combines the
<a href=\"modelica://HighLift.Mechanical.NonlinearSpring\">NonlinearSpring</a> (three
stiffnesses of figure 4, asymmetric extend/retract settings) with a
<a href=\"modelica://HighLift.Mechanical.ShaftBrake\">ShaftBrake</a> between the input side
and the housing (figure 5): the spring's output <code>y</code> (equation 2) is the normalized
dynamic brake torque of the brake, so that at the end stop the input is braked to the
housing with <code>tauB_max</code> (sliding) and held with up to <code>tauB_lim</code>.
The torque from the drive above the limiter's setting is thus reacted by the structure and not
passed on to the jammed part. <code>y</code> is also an output (lock-out indicator).
</p>
</html>"));
end TorqueLimiter;
