within HighLift.Hydraulics;
model PressureSource "Ideal pressure supply"
  import Modelica.Units.SI;
  parameter SI.AbsolutePressure p_supply = 345e5 "Supply pressure";
  Interfaces.Port port "Supply port"
    annotation (Placement(transformation(extent={{90,-10},{110,10}})));
equation
  port.p = p_supply;

  annotation (
    Icon(coordinateSystem(preserveAspectRatio=true, extent={{-100,-100},{100,100}}),
      graphics={
        Ellipse(extent={{-80,80},{80,-80}}, lineColor={0,0,255}),
        Text(extent={{-60,40},{60,-40}}, textString="P", textColor={0,0,255}),
        Text(extent={{-150,130},{150,90}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>Holds the pressure <code>p_supply</code> at its port (aircraft hydraulic system: 207 bar on
the A320, 345 bar on the A380) whatever the flow.</p>
</html>"));
end PressureSource;
