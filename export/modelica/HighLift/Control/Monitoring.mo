within HighLift.Control;
block Monitoring "Failure monitoring: asymmetry, overspeed and uncommanded movement command the wing-tip brakes"
  import Modelica.Units.SI;
  extends Modelica.Blocks.Icons.Block;

  parameter SI.Angle phi_asym(min=0) = 12.57
    "Asymmetry threshold: shaft angle difference between the tips, or a tip and the PDU";
  parameter SI.AngularVelocity w_over(min=0) = 33
    "Overspeed threshold of the transmission speed at the tips";
  parameter SI.Angle phi_unc(min=0) = 12.57
    "Uncommanded movement threshold: difference between PDU angle and commanded angle";
  parameter SI.Time t_detect(min=0) = 0.01
    "Detection latency: delay from the first fault detection to the brake command";
  parameter Boolean enableAsymmetry = true "= true, if the asymmetry monitor is active";
  parameter Boolean enableOverspeed = true "= true, if the overspeed monitor is active";
  parameter Boolean enableUncommanded = true "= true, if the uncommanded movement monitor is active";

  Modelica.Blocks.Interfaces.RealInput phi_left(unit="rad") "Shaft angle at the left tip (APPU)"
    annotation (Placement(transformation(extent={{-140,60},{-100,100}})));
  Modelica.Blocks.Interfaces.RealInput phi_right(unit="rad") "Shaft angle at the right tip (APPU)"
    annotation (Placement(transformation(extent={{-140,20},{-100,60}})));
  Modelica.Blocks.Interfaces.RealInput phi_pdu(unit="rad") "Shaft angle at the PDU output (FPPU)"
    annotation (Placement(transformation(extent={{-140,-20},{-100,20}})));
  Modelica.Blocks.Interfaces.RealInput phi_cmd(unit="rad") "Commanded shaft angle"
    annotation (Placement(transformation(extent={{-140,-60},{-100,-20}})));
  Modelica.Blocks.Interfaces.RealInput w_left(unit="rad/s") "Shaft speed at the left tip"
    annotation (Placement(transformation(extent={{-140,-100},{-100,-60}})));
  Modelica.Blocks.Interfaces.RealInput w_right(unit="rad/s") "Shaft speed at the right tip"
    annotation (Placement(transformation(
        origin={0,-120},
        extent={{-20,-20},{20,20}},
        rotation=90)));
  Modelica.Blocks.Interfaces.BooleanOutput asymmetry "Asymmetry detected"
    annotation (Placement(transformation(extent={{100,60},{120,80}})));
  Modelica.Blocks.Interfaces.BooleanOutput overspeed "Overspeed detected"
    annotation (Placement(transformation(extent={{100,20},{120,40}})));
  Modelica.Blocks.Interfaces.BooleanOutput uncommanded "Uncommanded movement detected"
    annotation (Placement(transformation(extent={{100,-20},{120,0}})));
  Modelica.Blocks.Interfaces.BooleanOutput wtb "Wing-tip brake command (latched)"
    annotation (Placement(transformation(extent={{100,-80},{120,-60}})));

  Boolean fault(start=false, fixed=true) "A fault has been detected (latched)";
  discrete SI.Time t_fault(start=0, fixed=true) "Time of the first detection";

equation
  asymmetry = enableAsymmetry and (abs(phi_left - phi_right) > phi_asym
    or abs(phi_left - phi_pdu) > phi_asym or abs(phi_right - phi_pdu) > phi_asym);
  overspeed = enableOverspeed and (abs(w_left) > w_over or abs(w_right) > w_over);
  uncommanded = enableUncommanded and abs(phi_pdu - phi_cmd) > phi_unc;
  fault = pre(fault) or asymmetry or overspeed or uncommanded;
  when fault then
    t_fault = time;
  end when;
  wtb = fault and time >= t_fault + t_detect;

  annotation (
    Icon(coordinateSystem(preserveAspectRatio=true, extent={{-100,-100},{100,100}}),
      graphics={
        Polygon(points={{-60,-50},{0,60},{60,-50},{-60,-50}}, lineColor={255,0,0}, lineThickness=0.5),
        Text(extent={{-10,30},{10,-30}}, textString="!", textColor={255,0,0}),
        Text(extent={{-150,150},{150,110}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>
The monitoring of the slat/flap control computer: the wing-tip brakes (WTB) are applied when
the monitor finds a failure by comparing the positions at the transmission ends (APPU), the
drive unit output angle (FPPU) and the commanded position:
</p>
<ul>
<li><strong>asymmetry</strong>: <code>|phi_left - phi_right|</code>, <code>|phi_left - phi_pdu|</code>
    or <code>|phi_right - phi_pdu|</code> above <code>phi_asym</code> (shaft rupture, loss of a
    wing's transmission);</li>
<li><strong>overspeed</strong>: <code>|w_left|</code> or <code>|w_right|</code> above
    <code>w_over</code> (runaway of a disconnected, back-driven transmission);</li>
<li><strong>uncommanded movement</strong>: <code>|phi_pdu - phi_cmd|</code> above
    <code>phi_unc</code>.</li>
</ul>
<p>
The first detection is latched (WTBs are reset on ground only); the brake command
<code>wtb</code> follows after the detection latency <code>t_detect</code>. All angles are shaft
angles at the same gear ratio. For a one-wing system connect the same tip signal to both tip
inputs.
</p>
</html>"));
end Monitoring;
