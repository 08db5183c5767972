within HighLift.Hydraulics;
model DifferentialCylinder "Differential (single-rod) cylinder with compressible chambers and end stops"
  import Modelica.Units.SI;
  parameter SI.Area A_A(min=Modelica.Constants.small) = 1e-3 "Piston area (chamber A)";
  parameter SI.Area A_B(min=Modelica.Constants.small) = 5e-4 "Annulus area (chamber B, rod side)";
  parameter SI.Length s_max(min=Modelica.Constants.small) = 0.1 "Stroke";
  parameter SI.Volume V0_A(min=Modelica.Constants.small) = 1e-5 "Dead volume of chamber A";
  parameter SI.Volume V0_B(min=Modelica.Constants.small) = 1e-5 "Dead volume of chamber B";
  parameter SI.BulkModulus E(min=Modelica.Constants.small) = 1.2e9 "Bulk modulus of the oil";
  parameter SI.TranslationalDampingConstant d(min=0) = 1e3 "Viscous friction of the piston";
  parameter Real c_stop(unit="N/m", min=0) = 1e8 "Stiffness of the end stops";
  parameter SI.Position s_start = 0 "Initial rod position";

  Interfaces.Port port_A "Chamber A (piston side)"
    annotation (Placement(transformation(extent={{-70,-110},{-50,-90}})));
  Interfaces.Port port_B "Chamber B (rod side)"
    annotation (Placement(transformation(extent={{50,-110},{70,-90}})));
  Modelica.Mechanics.Translational.Interfaces.Flange_b flange "Rod end"
    annotation (Placement(transformation(extent={{90,-10},{110,10}})));

  SI.Position s(start=s_start, fixed=true) "Rod position (0: retracted, s_max: extended)";
  SI.Velocity v(start=0, fixed=true) "Rod velocity";
  SI.Pressure p_A(start=1e5, fixed=true) "Pressure in chamber A";
  SI.Pressure p_B(start=1e5, fixed=true) "Pressure in chamber B";
  SI.Force f "Force of the cylinder on the rod end";

equation
  s = flange.s;
  v = der(s);
  der(p_A) = E/(V0_A + A_A*s)*(port_A.V_flow - A_A*v);
  der(p_B) = E/(V0_B + A_B*(s_max - s))*(port_B.V_flow + A_B*v);
  port_A.p = p_A;
  port_B.p = p_B;
  f = p_A*A_A - p_B*A_B - d*v
    - (if s > s_max then c_stop*(s - s_max) else if s < 0 then c_stop*s else 0);
  flange.f = -f;

  annotation (
    Icon(coordinateSystem(preserveAspectRatio=true, extent={{-100,-100},{100,100}}),
      graphics={
        Rectangle(extent={{-90,40},{40,-40}}, lineColor={0,0,255}),
        Rectangle(extent={{-20,38},{-10,-38}}, lineColor={0,0,255}, fillColor={0,0,255},
          fillPattern=FillPattern.Solid),
        Rectangle(extent={{-10,5},{100,-5}}, lineColor={0,0,0}, fillColor={160,160,164},
          fillPattern=FillPattern.Solid),
        Text(extent={{-150,100},{150,60}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>
A single-rod cylinder with piston area <code>A_A</code> and annulus area <code>A_B</code>,
grounded housing, rod end at <code>flange</code> (position <code>s</code> from 0, retracted, to
<code>s_max</code>). The chambers are compressible:
</p>
<pre>
  der(p_A) = E/(V0_A + A_A*s)        * (V_flow_A - A_A*v)
  der(p_B) = E/(V0_B + A_B*(s_max-s)) * (V_flow_B + A_B*v)
  f        = p_A*A_A - p_B*A_B - d*v - f_stop
</pre>
<p>
<code>f</code> pushes the rod end; stiff end stops (<code>c_stop</code>) limit the stroke.
The initial state is the rod at <code>s_start</code>, at rest, both chambers at 1 bar.
</p>
</html>"));
end DifferentialCylinder;
