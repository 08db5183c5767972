within HighLift.Models;
model Friction "Friction"
  Modelica.Mechanics.Rotational.Components.Fixed fixed
    annotation (Placement(transformation(extent={{70,-130},{90,-110}})));
  Modelica.Blocks.Sources.Sine sine(amplitude=200, f=15.915494309189533)
    annotation (Placement(transformation(extent={{-10,-10},{10,10}})));
  Modelica.Blocks.Sources.Step step2(height=-1, offset=1, startTime=0.5)
    annotation (Placement(transformation(extent={{70,-10},{90,10}})));
  Modelica.Blocks.Math.Product product
    annotation (Placement(transformation(extent={{30,-10},{50,10}})));
  Modelica.Mechanics.Rotational.Sources.Torque torque(useSupport=true)
    annotation (Placement(transformation(extent={{70,-50},{90,-30}})));
  Modelica.Mechanics.Rotational.Components.Inertia inertia3(
    J=1,
    phi(start=0, fixed=true),
    w(start=100, fixed=true))
    annotation (Placement(transformation(extent={{110,-10},{130,10}})));
  Modelica.Mechanics.Rotational.Components.Clutch clutch(fn_max=160)
    annotation (Placement(transformation(extent={{150,-10},{170,10}})));
  Modelica.Blocks.Sources.Constant const(k=1)
    annotation (Placement(transformation(extent={{190,-10},{210,10}})));
  Modelica.Mechanics.Rotational.Components.Inertia inertia2(
    J=0.05,
    phi(start=0, fixed=true),
    w(start=90, fixed=true))
    annotation (Placement(transformation(extent={{190,-50},{210,-30}})));
  Modelica.Mechanics.Rotational.Components.SpringDamper spring(c=160, d=1)
    annotation (Placement(transformation(extent={{230,-10},{250,10}})));
  Modelica.Mechanics.Rotational.Components.Brake brake(fn_max=1600, useSupport=true)
    annotation (Placement(transformation(extent={{270,-10},{290,10}})));
  Modelica.Blocks.Sources.Step step(height=1, startTime=0.5)
    annotation (Placement(transformation(extent={{310,-10},{330,10}})));
  Modelica.Mechanics.Rotational.Components.Inertia inertia1(
    J=1,
    phi(start=0, fixed=true),
    w(start=90, fixed=true))
    annotation (Placement(transformation(extent={{310,-50},{330,-30}})));

equation
  connect(sine.y, product.u1)
    annotation (Line(points={{11,0},{32,0}}, color={0,0,127}));
  connect(step2.y, product.u2)
    annotation (Line(points={{91,0},{40,-8}}, color={0,0,127}));
  connect(product.y, torque.tau)
    annotation (Line(points={{51,0},{68,-40}}, color={0,0,127}));
  connect(torque.flange, inertia3.flange_a)
    annotation (Line(points={{90,-40},{110,0}}));
  connect(torque.support, fixed.flange)
    annotation (Line(points={{80,-50},{80,-130}}));
  connect(inertia3.flange_b, clutch.flange_a)
    annotation (Line(points={{130,0},{150,0}}));
  connect(const.y, clutch.f_normalized)
    annotation (Line(points={{211,0},{160,11}}, color={0,0,127}));
  connect(clutch.flange_b, inertia2.flange_a)
    annotation (Line(points={{170,0},{190,-40}}));
  connect(inertia2.flange_b, spring.flange_a)
    annotation (Line(points={{210,-40},{230,0}}));
  connect(spring.flange_b, brake.flange_a)
    annotation (Line(points={{250,0},{270,0}}));
  connect(brake.support, fixed.flange)
    annotation (Line(points={{280,-10},{80,-130}}));
  connect(step.y, brake.f_normalized)
    annotation (Line(points={{331,0},{280,11}}, color={0,0,127}));
  connect(brake.flange_b, inertia1.flange_a)
    annotation (Line(points={{290,0},{310,-40}}));

  annotation (
    experiment(StopTime=3, Tolerance=1e-06, Interval=0.001),
    Diagram(coordinateSystem(preserveAspectRatio=false, extent={{-20,-140},{340,20}})),
    Documentation(info="<html>
<p>Element network of the highlift project <strong>Friction</strong>, exported by <code>highlift export</code>. Every element is the Modelica Standard Library 4.0.0 class of its element type, with the project's instance names and parameters.</p>
<p>Modelica.Mechanics.Rotational.Examples.Friction (MSL 4.0.0): a drive train with a clutch and a brake (wing-tip-brake-like); instance names and parameters of the MSL example (../shared/reference/msl/README.md s4.4).</p>
</html>"));
end Friction;
