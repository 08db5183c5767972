within HighLift.Examples;
model JamBehindTorqueLimiter "A station jams behind its torque limiter: the limiter locks out and grounds the drive torque"
  extends Modelica.Icons.Example;

  Modelica.Blocks.Sources.Ramp speedCommand(height=25, duration=0.4)
    annotation (Placement(transformation(extent={{-100,-10},{-80,10}})));
  Modelica.Mechanics.Rotational.Sources.Speed drive(exact=false, f_crit=20)
    annotation (Placement(transformation(extent={{-70,-10},{-50,10}})));
  Modelica.Mechanics.Rotational.Components.SpringDamper shaft(c=2000, d=1)
    annotation (Placement(transformation(extent={{-40,-10},{-20,10}})));
  HighLift.Mechanical.TorqueLimiter limiter(tau1_ext=90, tau1_ret=63, tau2_ext=112.5,
    tau2_ret=80, c1=2e4, c2=1e3, c3=1e5, d=2, tauB_max=180, J=5e-4)
    annotation (Placement(transformation(extent={{-10,-10},{10,10}})));
  HighLift.Mechanical.GearedRotaryActuator gra(ratio=200, J_in=1e-3, J_load=9.7e-3, tau_C=0.2,
    tau_S=0.07, d_vis=2e-4)
    annotation (Placement(transformation(extent={{20,-10},{40,10}})));
  HighLift.Mechanical.Jam jam(c=1e5, d=10, t_jam=1)
    annotation (Placement(transformation(extent={{60,-10},{80,10}})));

initial equation
  // One start per degree of freedom (the drive's angle and speed start in Speed itself): the
  // limiter's inertia and the actuator (input inertia and load, geared) at rest, untwisted.
  limiter.flange_a.phi = 0;
  der(limiter.flange_a.phi) = 0;
  gra.flange_a.phi = 0;
  der(gra.flange_a.phi) = 0;

equation
  connect(speedCommand.y, drive.w_ref)
    annotation (Line(points={{-79,0},{-72,0}}, color={0,0,127}));
  connect(drive.flange, shaft.flange_a)
    annotation (Line(points={{-50,0},{-40,0}}));
  connect(shaft.flange_b, limiter.flange_a)
    annotation (Line(points={{-20,0},{-10,0}}));
  connect(limiter.flange_b, gra.flange_a)
    annotation (Line(points={{10,0},{20,0}}));
  connect(gra.flange_b, jam.flange)
    annotation (Line(points={{40,0},{60,0}}));

  annotation (
    experiment(StopTime=2, Tolerance=1e-6, Interval=0.001),
    Documentation(info="<html>
<p>
A speed-controlled drive turns a shaft, a station torque limiter and a geared rotary actuator.
At 1 s the actuator output jams. The transmission torque rises until the limiter locks out
(90 N&middot;m); its brake then grounds the input side, so that the torque behind the limiter
stays bounded while the drive is stopped by the brake torque.
</p>
</html>"));
end JamBehindTorqueLimiter;
