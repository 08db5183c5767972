within HighLift.Mechanical;
model Disconnector "Failure element: a stiff coupling that breaks (shaft rupture) at a given time or on a command"
  import Modelica.Units.SI;
  extends Modelica.Mechanics.Rotational.Interfaces.PartialCompliantWithRelativeStates;

  parameter SI.RotationalSpringConstant c(min=Modelica.Constants.small) = 1e6
    "Stiffness of the intact coupling";
  parameter SI.RotationalDampingConstant d(min=0) = 100 "Damping of the intact coupling";
  parameter SI.Time t_disconnect = Modelica.Constants.inf "Time of the rupture";
  parameter Boolean useDisconnectInput = false
    "= true, if the rupture is commanded by the input disconnect"
    annotation (Evaluate=true, HideResult=true, choices(checkBox=true));

  Modelica.Blocks.Interfaces.BooleanInput disconnect if useDisconnectInput
    "= true: break the coupling (latched)"
    annotation (Placement(transformation(
        origin={0,120},
        extent={{20,-20},{-20,20}},
        rotation=90)));
  Boolean broken(start=false, fixed=true) "= true after the rupture";

protected
  Modelica.Blocks.Interfaces.BooleanInput disconnect_internal "Command in use";

equation
  connect(disconnect, disconnect_internal);
  if not useDisconnectInput then
    disconnect_internal = false;
  end if;
  broken = pre(broken) or time >= t_disconnect or disconnect_internal;
  tau = if broken then 0 else c*phi_rel + d*w_rel;

  annotation (
    Icon(coordinateSystem(preserveAspectRatio=true, extent={{-100,-100},{100,100}}),
      graphics={
        Rectangle(extent={{-100,10},{-10,-10}}, lineColor={64,64,64},
          fillColor={192,192,192}, fillPattern=FillPattern.HorizontalCylinder),
        Rectangle(extent={{10,10},{100,-10}}, lineColor={64,64,64},
          fillColor={192,192,192}, fillPattern=FillPattern.HorizontalCylinder),
        Line(points={{-10,30},{0,10},{-10,-10},{0,-30}}, color={255,0,0}, thickness=0.5),
        Line(points={{10,30},{20,10},{10,-10},{20,-30}}, color={255,0,0}, thickness=0.5),
        Text(extent={{-150,80},{150,40}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>
Induces a mechanical disconnection of the drive train (shaft rupture). Before the rupture the
two flanges are held together by a stiff spring-damper, <code>tau = c*phi_rel + d*w_rel</code>
(choose <code>c</code> well above the stiffness of the adjacent shafts); from
<code>time &ge; t_disconnect</code>, or when the input <code>disconnect</code> becomes true,
the coupling transmits no torque. The rupture is permanent.
</p>
</html>"));
end Disconnector;
