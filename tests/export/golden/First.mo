within HighLift.Models;
model First "First"
  Modelica.Mechanics.Rotational.Components.Fixed fixed
    annotation (Placement(transformation(extent={{190,-130},{210,-110}})));
  Modelica.Mechanics.Rotational.Sources.Torque torque(useSupport=true)
    annotation (Placement(transformation(extent={{30,-10},{50,10}})));
  Modelica.Mechanics.Rotational.Components.Inertia inertia1(J=0.1)
    annotation (Placement(transformation(extent={{70,-10},{90,10}})));
  Modelica.Mechanics.Rotational.Components.IdealGear idealGear(ratio=10, useSupport=true)
    annotation (Placement(transformation(extent={{110,-10},{130,10}})));
  Modelica.Mechanics.Rotational.Components.Inertia inertia2(
    J=2,
    phi(start=0, fixed=true),
    w(start=0, fixed=true))
    annotation (Placement(transformation(extent={{150,-10},{170,10}})));
  Modelica.Mechanics.Rotational.Components.Spring spring(c=10000, phi_rel(start=0, fixed=true))
    annotation (Placement(transformation(extent={{190,-10},{210,10}})));
  Modelica.Mechanics.Rotational.Components.Inertia inertia3(J=2, w(start=0, fixed=true))
    annotation (Placement(transformation(extent={{230,-10},{250,10}})));
  Modelica.Mechanics.Rotational.Components.Damper damper(d=10)
    annotation (Placement(transformation(extent={{190,-50},{210,-30}})));
  Modelica.Blocks.Sources.Sine sine(amplitude=10, f=5)
    annotation (Placement(transformation(extent={{-10,-10},{10,10}})));

equation
  connect(sine.y, torque.tau)
    annotation (Line(points={{11,0},{28,0}}, color={0,0,127}));
  connect(torque.flange, inertia1.flange_a)
    annotation (Line(points={{50,0},{70,0}}));
  connect(inertia1.flange_b, idealGear.flange_a)
    annotation (Line(points={{90,0},{110,0}}));
  connect(idealGear.flange_b, inertia2.flange_a)
    annotation (Line(points={{130,0},{150,0}}));
  connect(inertia2.flange_b, spring.flange_a)
    annotation (Line(points={{170,0},{190,0}}));
  connect(spring.flange_b, inertia3.flange_a)
    annotation (Line(points={{210,0},{230,0}}));
  connect(damper.flange_a, inertia2.flange_b)
    annotation (Line(points={{190,-40},{170,0}}));
  connect(damper.flange_b, fixed.flange)
    annotation (Line(points={{210,-40},{200,-130}}));
  connect(torque.support, fixed.flange)
    annotation (Line(points={{40,-10},{200,-130}}));
  connect(idealGear.support, fixed.flange)
    annotation (Line(points={{120,-10},{200,-130}}));

  annotation (
    experiment(StopTime=1, Tolerance=1e-06, Interval=0.001),
    Diagram(coordinateSystem(preserveAspectRatio=false, extent={{-20,-140},{260,20}})),
    Documentation(info="<html>
<p>Element network of the highlift project <strong>First</strong>, exported by <code>highlift export</code>. Every element is the Modelica Standard Library 4.0.0 class of its element type, with the project's instance names and parameters.</p>
<p>Modelica.Mechanics.Rotational.Examples.First (MSL 4.0.0): a motor drives a gear, an inertia and an elastic load; the instance names and parameters are those of the MSL example (../shared/reference/msl/README.md s4.1).</p>
</html>"));
end First;
