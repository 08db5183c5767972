within HighLift.Examples;
model WingTipBrakeStop "A back-driven transmission is stopped by the wing-tip brake"
  extends Modelica.Icons.Example;

  Modelica.Mechanics.Rotational.Components.Inertia transmission(J=0.05, phi(start=0, fixed=true),
    w(start=30, fixed=true))
    annotation (Placement(transformation(extent={{-60,-10},{-40,10}})));
  Modelica.Mechanics.Rotational.Components.SpringDamper shaft(c=3349, d=0.5)
    annotation (Placement(transformation(extent={{-30,-10},{-10,10}})));
  HighLift.Mechanical.WingTipBrake wtb(tauB_max=550, tauB_lim=700, t_B=0.03, t_lat=0.1, J=5e-4)
    annotation (Placement(transformation(extent={{0,-10},{20,10}})));
  Modelica.Blocks.Sources.BooleanStep trigger(startTime=0.2)
    annotation (Placement(transformation(extent={{-30,30},{-10,50}})));
  Modelica.Mechanics.Rotational.Sources.ConstantTorque airload(tau_constant=40)
    annotation (Placement(transformation(extent={{-100,-10},{-80,10}})));

initial equation
  // The brake rotor turns with the transmission, the shaft untwisted.
  wtb.flange_a.phi = 0;
  der(wtb.flange_a.phi) = 30;

equation
  connect(airload.flange, transmission.flange_a)
    annotation (Line(points={{-80,0},{-60,0}}));
  connect(transmission.flange_b, shaft.flange_a)
    annotation (Line(points={{-40,0},{-30,0}}));
  connect(shaft.flange_b, wtb.flange_a)
    annotation (Line(points={{-10,0},{0,0}}));
  connect(trigger.y, wtb.apply)
    annotation (Line(points={{-9,40},{10,40},{10,12}}, color={255,0,255}));

  annotation (
    experiment(StopTime=1, Tolerance=1e-6, Interval=0.0005),
    Documentation(info="<html>
<p>
After a shaft rupture the outboard transmission is back-driven by an aiding airload. The
monitor fires at 0.2 s; after the latency of 0.1 s the wing-tip brake engages, its torque rises
within 30 ms and it stops the transmission. The peak shaft torque exceeds the brake torque
because of the kinetic energy stored in the transmission (equation 1 of the paper).
</p>
</html>"));
end WingTipBrakeStop;
