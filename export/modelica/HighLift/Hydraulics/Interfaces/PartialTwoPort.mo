within HighLift.Hydraulics.Interfaces;
partial model PartialTwoPort "Two hydraulic ports, no storage: the flow into port_a leaves at port_b"
  import Modelica.Units.SI;

  Port port_a "Inlet (positive flow from port_a to port_b)"
    annotation (Placement(transformation(extent={{-110,-10},{-90,10}})));
  Port port_b "Outlet"
    annotation (Placement(transformation(extent={{90,-10},{110,10}})));
  SI.Pressure dp "Pressure drop port_a.p - port_b.p";
  SI.VolumeFlowRate V_flow "Volume flow rate from port_a to port_b";

equation
  dp = port_a.p - port_b.p;
  V_flow = port_a.V_flow;
  port_a.V_flow + port_b.V_flow = 0;

  annotation (Documentation(info="<html>
<p>
Base of the components without storage between two hydraulic ports: the flow
<code>V_flow</code> enters at <code>port_a</code> and leaves at <code>port_b</code>,
<code>dp = port_a.p - port_b.p</code>. A subclass adds the law relating <code>V_flow</code>
and <code>dp</code>.
</p>
</html>"));
end PartialTwoPort;
