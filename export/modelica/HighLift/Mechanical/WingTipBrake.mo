within HighLift.Mechanical;
model WingTipBrake "Wing-tip brake: brake rotor inertia and shaft brake applied by a Boolean command"
  import Modelica.Units.SI;
  extends Modelica.Mechanics.Rotational.Interfaces.PartialTwoFlangesAndSupport;

  parameter SI.Torque tauB_max(min=0, start=550) "Maximum dynamic (sliding) brake torque";
  parameter SI.Torque tauB_lim(min=0, start=700) "Maximum static (holding) brake torque (>= tauB_max)";
  parameter SI.Time t_B(min=0) = 0.03 "Time from engagement to the maximum dynamic brake torque";
  parameter SI.Time t_lat(min=0) = 0.1 "Delay from the command to engagement";
  parameter SI.Inertia J(min=0) = 5e-4 "Inertia of the brake rotor";

  Modelica.Blocks.Interfaces.BooleanInput apply "= true: apply the brake (latched)"
    annotation (Placement(transformation(
        origin={0,120},
        extent={{20,-20},{-20,20}},
        rotation=90)));
  Modelica.Mechanics.Rotational.Components.Inertia rotor(J=J)
    annotation (Placement(transformation(extent={{-60,-10},{-40,10}})));
  ShaftBrake brake(tauB_max=tauB_max, tauB_lim=tauB_lim, useSupport=true)
    annotation (Placement(transformation(extent={{0,-10},{20,10}})));
  HighLift.Control.BrakeActuation actuation(t_lat=t_lat, t_rise=t_B, latch=true)
    annotation (Placement(transformation(
        origin={10,60},
        extent={{-10,-10},{10,10}},
        rotation=270)));

equation
  connect(flange_a, rotor.flange_a)
    annotation (Line(points={{-100,0},{-60,0}}));
  connect(rotor.flange_b, brake.flange_a)
    annotation (Line(points={{-40,0},{0,0}}));
  connect(brake.flange_b, flange_b)
    annotation (Line(points={{20,0},{100,0}}));
  connect(brake.support, internalSupport)
    annotation (Line(points={{10,-10},{10,-80},{0,-80}}));
  connect(apply, actuation.trigger)
    annotation (Line(points={{0,120},{0,90},{10,90},{10,72}}, color={255,0,255}));
  connect(actuation.y, brake.u)
    annotation (Line(points={{10,49},{10,11}}, color={0,0,127}));

  annotation (
    Icon(coordinateSystem(preserveAspectRatio=true, extent={{-100,-100},{100,100}}),
      graphics={
        Rectangle(extent={{-100,10},{100,-10}}, lineColor={64,64,64},
          fillColor={192,192,192}, fillPattern=FillPattern.HorizontalCylinder),
        Rectangle(extent={{-20,60},{20,-60}}, lineColor={64,64,64},
          fillColor={255,255,255}, fillPattern=FillPattern.HorizontalCylinder, radius=10),
        Rectangle(extent={{-40,-25},{-30,-55}}, fillPattern=FillPattern.Solid),
        Rectangle(extent={{30,-25},{40,-55}}, fillPattern=FillPattern.Solid),
        Text(extent={{-150,-70},{150,-110}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>
A wing-tip brake (WTB) at the outboard end of the transmission. When <code>apply</code>
becomes true (the monitor detected an asymmetry, overspeed or uncommanded movement), the brake
engages after the latency <code>t_lat</code> and its dynamic torque rises linearly to
<code>tauB_max</code> within <code>t_B</code>
(<a href=\"modelica://HighLift.Control.BrakeActuation\">BrakeActuation</a>); the
<a href=\"modelica://HighLift.Mechanical.ShaftBrake\">ShaftBrake</a> stops the shaft and holds
it with up to <code>tauB_lim</code>. The command is latched: WTBs are reset on ground only.
<code>flange_b</code> may be left open when the brake sits at the shaft end.
</p>
</html>"));
end WingTipBrake;
