within HighLift.Control;
block BrakeActuation "Boolean brake command to the normalized brake torque: latency, then a linear rise"
  import Modelica.Units.SI;
  extends Modelica.Blocks.Icons.Block;

  parameter SI.Time t_lat(min=0) = 0 "Delay from the command to engagement";
  parameter SI.Time t_rise(min=0) = 0 "Time of the rise from 0 to 1 after engagement";
  parameter Boolean latch = false "= true: once commanded, the brake stays applied";

  Modelica.Blocks.Interfaces.BooleanInput trigger "Brake command"
    annotation (Placement(transformation(extent={{-140,-20},{-100,20}})));
  Modelica.Blocks.Interfaces.RealOutput y(min=0, max=1) "Normalized brake torque"
    annotation (Placement(transformation(extent={{100,-10},{120,10}})));
  Boolean applied(start=false, fixed=true) "Command in force (latched if latch)";
  discrete SI.Time t_on(start=0, fixed=true) "Time of the last command";

equation
  applied = trigger or (latch and pre(applied));
  when applied then
    t_on = time;
  end when;
  y = if not applied then 0
    else if t_rise > 0 then min(1, max(0, (time - t_on - t_lat)/t_rise))
    else (if time >= t_on + t_lat then 1 else 0);

  annotation (
    Icon(coordinateSystem(preserveAspectRatio=true, extent={{-100,-100},{100,100}}),
      graphics={
        Line(points={{-80,-60},{-20,-60},{20,60},{80,60}}, color={0,0,127}),
        Text(extent={{-150,150},{150,110}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>
Turns a Boolean brake command into the normalized dynamic brake torque <code>y</code> of a
<a href=\"modelica://HighLift.Mechanical.ShaftBrake\">ShaftBrake</a>. With
<code>t_on</code> the time the command became true:
</p>
<pre>
  y = 0                                         before t_on + t_lat
  y = min(1, (time - t_on - t_lat)/t_rise)       afterwards
</pre>
<p>
A command that is already true at the start engages from time 0. With <code>latch</code> the
brake stays applied when the command falls (wing-tip brakes are reset on ground only).
</p>
</html>"));
end BrakeActuation;
