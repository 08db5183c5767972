within HighLift.Hydraulics.Interfaces;
function Orifice "Turbulent orifice flow, regularised near zero pressure drop"
  import Modelica.Units.SI;
  input SI.Pressure dp "Pressure drop across the orifice";
  input SI.Area A "Opening area";
  input Real Cd "Discharge coefficient";
  input SI.Density rho "Density of the oil";
  input SI.Pressure dp_small "Pressure drop below which the flow becomes laminar-like";
  output SI.VolumeFlowRate V_flow "Volume flow rate in the direction of the pressure drop";
algorithm
  V_flow := Cd*A*sqrt(2/rho)*dp/(dp^2 + dp_small^2)^0.25;

  annotation (
    smoothOrder=1,
    Documentation(info="<html>
<p>
The turbulent orifice law <code>V_flow = Cd*A*sqrt(2*|dp|/rho)*sign(dp)</code> has an infinite
derivative at <code>dp = 0</code>. It is regularised as
</p>
<pre>
  V_flow = Cd*A*sqrt(2/rho) * dp/(dp^2 + dp_small^2)^(1/4)
</pre>
<p>
which equals the turbulent law for <code>|dp| &gt;&gt; dp_small</code>, is linear in
<code>dp</code> near zero (slope <code>Cd*A*sqrt(2/rho)/sqrt(dp_small)</code>), odd and smooth.
</p>
</html>"));
end Orifice;
