within HighLift.Hydraulics;
model ServoValve "4/3-way servo valve with first-order spool dynamics and turbulent metering edges"
  import Modelica.Units.SI;
  parameter SI.Area A_max(min=0) = 2e-6 "Opening area of a metering edge at full spool stroke";
  parameter Real leakage(min=0) = 1e-4 "Leakage opening as a fraction of A_max (closed edges)";
  parameter SI.Time T_v(min=Modelica.Constants.small) = 0.005 "Time constant of the spool";
  parameter Real Cd(min=0) = 0.7 "Discharge coefficient";
  parameter SI.Density rho(min=Modelica.Constants.small) = 850 "Density of the oil";
  parameter SI.Pressure dp_small(min=Modelica.Constants.small) = 1e4
    "Regularisation of the orifice law near zero pressure drop";

  Modelica.Blocks.Interfaces.RealInput u "Spool command, -1 (P to B, A to T) ... 1 (P to A, B to T)"
    annotation (Placement(transformation(extent={{-140,-20},{-100,20}})));
  Interfaces.Port port_P "Supply" annotation (Placement(transformation(extent={{-50,-110},{-30,-90}})));
  Interfaces.Port port_T "Return" annotation (Placement(transformation(extent={{30,-110},{50,-90}})));
  Interfaces.Port port_A "Consumer port A" annotation (Placement(transformation(extent={{-50,90},{-30,110}})));
  Interfaces.Port port_B "Consumer port B" annotation (Placement(transformation(extent={{30,90},{50,110}})));

  Real x(start=0, fixed=true) "Normalized spool position";
  SI.VolumeFlowRate V_PA "Flow from P to A";
  SI.VolumeFlowRate V_PB "Flow from P to B";
  SI.VolumeFlowRate V_AT "Flow from A to T";
  SI.VolumeFlowRate V_BT "Flow from B to T";

equation
  der(x) = (max(-1, min(1, u)) - x)/T_v;
  V_PA = Interfaces.Orifice(port_P.p - port_A.p, A_max*(max(x, 0) + leakage), Cd, rho, dp_small);
  V_BT = Interfaces.Orifice(port_B.p - port_T.p, A_max*(max(x, 0) + leakage), Cd, rho, dp_small);
  V_PB = Interfaces.Orifice(port_P.p - port_B.p, A_max*(max(-x, 0) + leakage), Cd, rho, dp_small);
  V_AT = Interfaces.Orifice(port_A.p - port_T.p, A_max*(max(-x, 0) + leakage), Cd, rho, dp_small);
  port_P.V_flow = V_PA + V_PB;
  port_T.V_flow = -(V_AT + V_BT);
  port_A.V_flow = V_AT - V_PA;
  port_B.V_flow = V_BT - V_PB;

  annotation (
    Icon(coordinateSystem(preserveAspectRatio=true, extent={{-100,-100},{100,100}}),
      graphics={
        Rectangle(extent={{-90,40},{-30,-40}}, lineColor={0,0,255}),
        Rectangle(extent={{-30,40},{30,-40}}, lineColor={0,0,255}),
        Rectangle(extent={{30,40},{90,-40}}, lineColor={0,0,255}),
        Line(points={{-40,40},{40,-40}}, color={0,0,255}, arrow={Arrow.None,Arrow.Filled}),
        Line(points={{40,40},{-40,-40}}, color={0,0,255}, arrow={Arrow.None,Arrow.Filled}),
        Text(extent={{-150,150},{150,110}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>
A 4/3-way servo valve (closed centre). The spool follows the command with a first-order lag,
<code>T_v*der(x) = limit(u, -1, 1) - x</code>. For <code>x &gt; 0</code> the edges P&rarr;A and
B&rarr;T open with area <code>A_max*x</code>, for <code>x &lt; 0</code> the edges P&rarr;B and
A&rarr;T with <code>A_max*|x|</code>; closed edges leak through <code>leakage*A_max</code>.
Each edge is a turbulent orifice regularised near zero pressure drop
(<a href=\"modelica://HighLift.Hydraulics.Interfaces.Orifice\">Interfaces.Orifice</a>).
</p>
</html>"));
end ServoValve;
