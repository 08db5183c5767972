within HighLift.Hydraulics;
model TurbulentResistance "Turbulent flow resistance (orifice), regularised near zero flow"
  import Modelica.Units.SI;
  extends Interfaces.PartialTwoPort;
  parameter SI.Area A(min=0) = 1e-5 "Opening area";
  parameter Real Cd(min=0) = 0.7 "Discharge coefficient";
  parameter SI.Density rho(min=Modelica.Constants.small) = 850 "Density of the oil";
  parameter SI.Pressure dp_small(min=Modelica.Constants.small) = 1e4
    "Regularisation: below this pressure drop the flow is nearly linear";
equation
  V_flow = Interfaces.Orifice(dp, A, Cd, rho, dp_small);

  annotation (
    Icon(coordinateSystem(preserveAspectRatio=true, extent={{-100,-100},{100,100}}),
      graphics={
        Line(points={{-90,0},{90,0}}, color={0,0,255}),
        Polygon(points={{-30,30},{0,5},{30,30},{-30,30}}, lineColor={0,0,255}),
        Polygon(points={{-30,-30},{0,-5},{30,-30},{-30,-30}}, lineColor={0,0,255}),
        Text(extent={{-150,80},{150,40}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>
A turbulent resistance (orifice): <code>V_flow = Cd*A*sqrt(2*|dp|/rho)*sign(dp)</code>,
regularised near zero pressure drop as described in
<a href=\"modelica://HighLift.Hydraulics.Interfaces.Orifice\">Interfaces.Orifice</a> so that the
flow is a smooth, odd function of <code>dp</code>.
</p>
</html>"));
end TurbulentResistance;
