within HighLift.Sources;
model InverseSpeedDependentTorque "Torque inversely proportional to the speed (MSL 4.1.0's class of this name, for MSL 4.0.0)"
  import Modelica.Units.SI;
  extends Modelica.Mechanics.Rotational.Interfaces.PartialTorque;

  parameter SI.Torque tau_nominal
    "Nominal torque (if negative, torque is acting as load in positive direction of rotation)";
  parameter Boolean TorqueDirection = true
    "Same direction of torque in both directions of rotation";
  parameter SI.AngularVelocity w_nominal(min=Modelica.Constants.eps) "Nominal speed";
  parameter SI.AngularVelocity w0(final min=Modelica.Constants.eps, start=0.1)
    "Regularization below w0";
  SI.AngularVelocity w "Angular velocity of flange with respect to support (= der(phi))";
  SI.Torque tau "Accelerating torque acting at flange (= -flange.tau)";

equation
  w = der(phi);
  tau = -flange.tau;
  if TorqueDirection then
    tau = if abs(w) < w0 then tau_nominal*w_nominal/w0 else tau_nominal*w_nominal/abs(w);
  else
    tau = if abs(w) < w0 then tau_nominal*w/w0 else tau_nominal*w_nominal/w;
  end if;

  annotation (
    Icon(coordinateSystem(preserveAspectRatio=true, extent={{-100,-100},{100,100}}),
      graphics={
        Line(points={{-60,40},{-60,-50}}, color={192,192,192}),
        Line(points={{-75,-40},{75,-40}}, color={192,192,192}),
        Line(points={{60,-20},{20,-18},{-20,-12},{-40,-4},{-50,8},{-55,40}},
          color={0,0,127}, smooth=Smooth.Bezier)}),
    Documentation(info="<html>
<p>
A torque on the flange that falls with the inverse of the speed <code>w</code> of the flange
relative to the support. <code>Modelica.Mechanics.Rotational.Sources.InverseSpeedDependentTorque</code>
appears in the Modelica Standard Library only in version 4.1.0; this class has its parameters
and its law, on the MSL 4.0.0 interface <code>PartialTorque</code>, so that the element type
<code>InverseSpeedDependentTorque</code> of highlift exports under MSL 4.0.0:
</p>
<pre>
  TorqueDirection = true:   tau = tau_nominal*w_nominal/max(|w|, w0)
  TorqueDirection = false:  tau = tau_nominal*w/w0            for |w| &lt; w0
                            tau = tau_nominal*w_nominal/w     otherwise
</pre>
<p>
<code>tau</code> accelerates the flange (<code>flange.tau = -tau</code>); below <code>w0</code> the
law is regularised so that the torque stays finite at standstill.
</p>
</html>"));
end InverseSpeedDependentTorque;
