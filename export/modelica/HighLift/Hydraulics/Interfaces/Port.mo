within HighLift.Hydraulics.Interfaces;
connector Port "Hydraulic port: pressure and volume flow rate into the component"
  Modelica.Units.SI.AbsolutePressure p "Pressure at the port";
  flow Modelica.Units.SI.VolumeFlowRate V_flow "Volume flow rate into the component";

  annotation (
    Icon(coordinateSystem(preserveAspectRatio=true, extent={{-100,-100},{100,100}}),
      graphics={Ellipse(extent={{-100,100},{100,-100}}, lineColor={0,0,255},
        fillColor={0,0,255}, fillPattern=FillPattern.Solid)}),
    Documentation(info="<html>
<p>
Connector of the hydraulic components: the pressure <code>p</code> and the volume flow rate
<code>V_flow</code> into the component (flow variable). Connected ports share the pressure and
their flows sum to zero.
</p>
</html>"));
end Port;
