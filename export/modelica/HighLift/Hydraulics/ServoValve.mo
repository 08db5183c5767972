within HighLift.Hydraulics;
model ServoValve "4/3-way servo valve: spool position as input, first- or second-order spool dynamics; turbulent metering edges"
  import Modelica.Units.SI;
  parameter SI.Area A_max(min=0) = 2e-6 "Opening area of a metering edge at full spool stroke";
  parameter Real leakage(min=0) = 1e-4 "Leakage opening as a fraction of A_max (closed edges)";
  parameter Integer order(min=0, max=2) = 1
    "Spool dynamics: 0 = the command u is the spool position, 1 = first order (T_v), 2 = second order (w_v, D_v)"
    annotation (Evaluate=true);
  parameter SI.Time T_v(min=Modelica.Constants.small) = 0.005 "Time constant of the spool (order = 1)"
    annotation (Dialog(enable=order == 1));
  parameter SI.AngularFrequency w_v(min=Modelica.Constants.small) = 280
    "Natural frequency of the spool (order = 2)" annotation (Dialog(enable=order == 2));
  parameter Real D_v(min=0) = 0.7 "Damping ratio of the spool (order = 2)"
    annotation (Dialog(enable=order == 2));
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

  Real x "Normalized spool position";
  Real v_x(unit="1/s") "Spool velocity (0 for order = 0)";
  Real x_open "Spool position limited to the full stroke, -1 ... 1";
  SI.VolumeFlowRate V_PA "Flow from P to A";
  SI.VolumeFlowRate V_PB "Flow from P to B";
  SI.VolumeFlowRate V_AT "Flow from A to T";
  SI.VolumeFlowRate V_BT "Flow from B to T";

initial equation
  if order == 1 then
    x = 0;
  elseif order == 2 then
    x = 0;
    v_x = 0;
  end if;

equation
  if order == 0 then
    x = max(-1, min(1, u));
    v_x = 0;
  elseif order == 1 then
    der(x) = (max(-1, min(1, u)) - x)/T_v;
    v_x = der(x);
  else
    der(x) = v_x;
    der(v_x) = w_v^2*(max(-1, min(1, u)) - x) - 2*D_v*w_v*v_x;
  end if;
  x_open = max(-1, min(1, x));
  V_PA = Interfaces.Orifice(port_P.p - port_A.p, A_max*(max(x_open, 0) + leakage), Cd, rho, dp_small);
  V_BT = Interfaces.Orifice(port_B.p - port_T.p, A_max*(max(x_open, 0) + leakage), Cd, rho, dp_small);
  V_PB = Interfaces.Orifice(port_P.p - port_B.p, A_max*(max(-x_open, 0) + leakage), Cd, rho, dp_small);
  V_AT = Interfaces.Orifice(port_A.p - port_T.p, A_max*(max(-x_open, 0) + leakage), Cd, rho, dp_small);
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
A 4/3-way servo valve (closed centre). The spool position <code>x</code> (normalized, &plusmn;1 at
full stroke) follows the command <code>u</code> by the parameter <code>order</code>:
</p>
<ul>
<li><code>order = 0</code>: the command is the spool position, <code>x = limit(u, -1, 1)</code>
(a valve much faster than the loop around it, or a spool position measured or prescribed);</li>
<li><code>order = 1</code> (default): first-order lag, <code>T_v*der(x) = limit(u, -1, 1) - x</code>;</li>
<li><code>order = 2</code>: second-order spool with natural frequency <code>w_v</code> and
damping ratio <code>D_v</code>, <code>der(x) = v_x</code>,
<code>der(v_x) = w_v^2*(limit(u, -1, 1) - x) - 2*D_v*w_v*v_x</code>. The defaults give the
low-frequency lag <code>2*D_v/w_v</code> = 5 ms of the first-order default.</li>
</ul>
<p>
The spool starts at rest in the centre. The edges open with <code>x_open = limit(x, -1, 1)</code>
(a spool that overshoots full stroke uncovers no more than the full port): for
<code>x_open &gt; 0</code> the edges P&rarr;A and B&rarr;T with area <code>A_max*x_open</code>,
for <code>x_open &lt; 0</code> the edges P&rarr;B and A&rarr;T with <code>A_max*|x_open|</code>;
closed edges leak through <code>leakage*A_max</code>.
Each edge is a turbulent orifice regularised near zero pressure drop
(<a href=\"modelica://HighLift.Hydraulics.Interfaces.Orifice\">Interfaces.Orifice</a>).
</p>
</html>"));
end ServoValve;
