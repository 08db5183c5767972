within HighLift.Mechanical;
model Jam "Failure element: locks the flange to the structure at a given time or on a command"
  import Modelica.Units.SI;
  extends Modelica.Mechanics.Rotational.Interfaces.PartialElementaryOneFlangeAndSupport2;

  parameter SI.RotationalSpringConstant c(min=Modelica.Constants.small) = 1e5
    "Stiffness of the jammed load path to the structure";
  parameter SI.RotationalDampingConstant d(min=0) = 0 "Damping of the jammed load path";
  parameter SI.Time t_jam = Modelica.Constants.inf "Time of the jam";
  parameter Boolean useJamInput = false "= true, if the jam is commanded by the input jam"
    annotation (Evaluate=true, HideResult=true, choices(checkBox=true));

  Modelica.Blocks.Interfaces.BooleanInput jam if useJamInput "= true: jam (latched)"
    annotation (Placement(transformation(
        origin={0,120},
        extent={{20,-20},{-20,20}},
        rotation=90)));
  SI.Angle phi "Angle of the flange relative to the support";
  SI.AngularVelocity w "Speed of the flange relative to the support";
  SI.Torque tau "Torque of the jam on the flange (opposing the motion after the jam)";
  Boolean jammed(start=false, fixed=true) "= true after the jam";
  discrete SI.Angle phi_jam(start=0, fixed=true) "Angle at which the flange jammed";

protected
  Modelica.Blocks.Interfaces.BooleanInput jam_internal "Command in use";

equation
  connect(jam, jam_internal);
  if not useJamInput then
    jam_internal = false;
  end if;
  phi = flange.phi - phi_support;
  w = der(phi);
  jammed = pre(jammed) or time >= t_jam or jam_internal;
  when jammed then
    phi_jam = phi;
  end when;
  tau = if jammed then c*(phi - phi_jam) + d*w else 0;
  flange.tau = tau;

  annotation (
    Icon(coordinateSystem(preserveAspectRatio=true, extent={{-100,-100},{100,100}}),
      graphics={
        Rectangle(extent={{-100,10},{-20,-10}}, lineColor={64,64,64},
          fillColor={192,192,192}, fillPattern=FillPattern.HorizontalCylinder),
        Line(points={{-20,60},{20,-60}}, color={255,0,0}, thickness=1),
        Line(points={{-20,-60},{20,60}}, color={255,0,0}, thickness=1),
        Text(extent={{-150,100},{150,70}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>
Causes jamming in the drive train (for instance in a flap track or an actuator). From
<code>time &ge; t_jam</code>, or when the input <code>jam</code> becomes true, the flange is
tied to the structure at the angle <code>phi_jam</code> it had at that instant, through the
stiffness <code>c</code> and damping <code>d</code> of the jammed load path:
</p>
<pre>
  flange.tau = c*(phi - phi_jam) + d*w     (after the jam; 0 before)
</pre>
<p>
The kinetic energy of the drive goes into the twist of the transmission, equation (1) of the
paper: <code>tau_max = w_max*sqrt(c*J)</code> for a single-inertia oscillator.
</p>
</html>"));
end Jam;
