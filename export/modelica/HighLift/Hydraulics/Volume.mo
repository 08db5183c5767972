within HighLift.Hydraulics;
model Volume "Compressible oil volume of a line or a chamber"
  import Modelica.Units.SI;
  parameter SI.Volume V(min=Modelica.Constants.small) = 1e-5 "Volume";
  parameter SI.BulkModulus E(min=Modelica.Constants.small) = 1.2e9 "Bulk modulus of the oil";
  parameter SI.AbsolutePressure p_start = 1e5 "Initial pressure";
  Interfaces.Port port "The node the volume belongs to"
    annotation (Placement(transformation(extent={{-10,-110},{10,-90}})));
  SI.Pressure p(start=p_start, fixed=true) "Pressure of the volume";
equation
  port.p = p;
  der(p) = E/V*port.V_flow;

  annotation (
    Icon(coordinateSystem(preserveAspectRatio=true, extent={{-100,-100},{100,100}}),
      graphics={
        Rectangle(extent={{-80,60},{80,-60}}, lineColor={0,0,255}),
        Text(extent={{-60,30},{60,-30}}, textString="V", textColor={0,0,255}),
        Text(extent={{-150,110},{150,70}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>
A compressible oil volume, <code>der(p) = E/V*port.V_flow</code>: the volume of a line between
valves, orifices and motors. Lines and orifices are otherwise incompressible, so a node that
joins only such components needs a volume (or a pressure source) to have a pressure state; the
simulator rejects a node with neither.
</p>
</html>"));
end Volume;
