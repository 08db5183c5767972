within HighLift.Hydraulics;
model Tank "Return line (reservoir) at constant pressure"
  import Modelica.Units.SI;
  parameter SI.AbsolutePressure p_return = 5e5 "Return pressure";
  Interfaces.Port port "Return port"
    annotation (Placement(transformation(extent={{-110,-10},{-90,10}})));
equation
  port.p = p_return;

  annotation (
    Icon(coordinateSystem(preserveAspectRatio=true, extent={{-100,-100},{100,100}}),
      graphics={
        Rectangle(extent={{-60,40},{60,-60}}, lineColor={0,0,255}),
        Text(extent={{-150,100},{150,60}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>Holds the return pressure <code>p_return</code> at its port whatever the flow.</p>
</html>"));
end Tank;
