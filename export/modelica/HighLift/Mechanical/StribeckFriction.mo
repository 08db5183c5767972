within HighLift.Mechanical;
model StribeckFriction "Bearing friction after the Stribeck law (3) plus load-dependent gear loss (4), with stick-slip or regularised"
  import Modelica.Units.SI;
  extends Modelica.Mechanics.Rotational.Interfaces.PartialElementaryTwoFlangesAndSupport2;
  extends Modelica.Thermal.HeatTransfer.Interfaces.PartialElementaryConditionalHeatPortWithoutT;

  parameter SI.Torque tau_C(min=0) = 0 "Coulomb friction torque";
  parameter SI.RotationalDampingConstant d_vis(min=0) = 0 "Viscous friction coefficient";
  parameter SI.Torque tau_S(min=0) = 0 "Stribeck torque (excess of the breakaway torque at standstill)";
  parameter Real f_exp(unit="s/rad", min=0) = 10 "Decay of the Stribeck torque with speed";
  parameter Real peak(min=1) = 1
    "Static friction at standstill = peak*(tau_C + tau_S)";
  parameter SI.AngularVelocity w_small(min=0) = 0
    "Regularisation speed: 0 = exact stick/slip; > 0 = friction and load loss scaled by tanh(w/w_small), no stick/slip";
  parameter Boolean useEfficiencyInput = false
    "= true, if the gearbox efficiency eta_GE is given by the input eta"
    annotation (Evaluate=true, HideResult=true, choices(checkBox=true));
  parameter Real eta_GE(min=0, max=1) = 1
    "Gearbox efficiency of the load-dependent loss (if not useEfficiencyInput)"
    annotation (Dialog(enable=not useEfficiencyInput));

  Modelica.Blocks.Interfaces.RealInput eta(min=0, max=1) if useEfficiencyInput
    "Gearbox efficiency eta_GE of the load-dependent loss"
    annotation (Placement(transformation(
        origin={0,110},
        extent={{20,-20},{-20,20}},
        rotation=90)));

  SI.Angle phi "Angle of the shaft relative to the support";
  SI.AngularVelocity w "Speed of the shaft relative to the support";
  SI.AngularAcceleration a "Acceleration of the shaft relative to the support";
  SI.Torque tau "Friction torque, positive when it opposes forward rotation";
  SI.Torque tau_load "Transmitted load torque (mean of the flange torques)";
  SI.Torque tau_slide_pos "Friction magnitude for forward sliding at speed w";
  SI.Torque tau_slide_neg "Friction magnitude for backward sliding at speed w";

  // The stick/slip state machine of Modelica.Mechanics.Rotational.Interfaces.PartialFriction
  // (MSL 4.0.0), declared here because the MSL base class has a parameter w_small of its own
  // (the speed threshold for velocity jumps by reinit, default 1e10) that would clash with the
  // regularisation speed w_small of this class. The equations are those of the MSL class with
  // its default threshold (w_jump = 1e10 below).
  SI.AngularVelocity w_relfric "Relative angular velocity between frictional surfaces";
  SI.AngularAcceleration a_relfric "Relative angular acceleration between frictional surfaces";
  SI.Torque tau0 "Friction torque for w=0 and forward sliding";
  SI.Torque tau0_max "Maximum friction torque for w=0 and locked";
  Boolean free "= true, if frictional element is not active (here: the regularised law)";
  Real sa(final unit="1") "Path parameter of friction characteristic tau = f(a_relfric)";
  Boolean startForward(start=false, fixed=true) "= true, if w_rel=0 and start of forward sliding";
  Boolean startBackward(start=false, fixed=true) "= true, if w_rel=0 and start of backward sliding";
  Boolean locked(start=false) "true, if w_rel=0 and not sliding";
  constant Integer Unknown=3 "Value of mode is not known";
  constant Integer Free=2 "Element is not active";
  constant Integer Forward=1 "w_rel > 0 (forward sliding)";
  constant Integer Stuck=0 "w_rel = 0 (forward sliding, locked or backward sliding)";
  constant Integer Backward=-1 "w_rel < 0 (backward sliding)";
  Integer mode(final min=Backward, final max=Unknown, start=Unknown, fixed=true);

protected
  constant SI.AngularAcceleration unitAngularAcceleration=1;
  constant SI.Torque unitTorque=1;
  constant SI.AngularVelocity w_jump=1.0e10
    "The w_small of MSL PartialFriction at its default: no velocity jumps by reinit";
  Modelica.Blocks.Interfaces.RealInput eta_internal "Efficiency in use";

equation
  connect(eta, eta_internal);
  if not useEfficiencyInput then
    eta_internal = eta_GE;
  end if;

  phi = flange_a.phi - phi_support;
  flange_b.phi = flange_a.phi;
  w = der(phi);
  a = der(w);
  w_relfric = w;
  a_relfric = a;
  flange_a.tau + flange_b.tau - tau = 0;

  // Torque passed through the element: flange_a receives tau_load, flange_b passes on
  // tau_load less the friction; the mean is independent of the flange orientation.
  tau_load = (flange_a.tau - flange_b.tau)/2;

  // Equation (3) plus the load-dependent loss of equation (4), only while sliding.
  tau_slide_pos = tau_C + d_vis*w + tau_S*exp(-f_exp*abs(w)) + (1 - eta_internal)*abs(tau_load);
  tau_slide_neg = tau_C - d_vis*w + tau_S*exp(-f_exp*abs(w)) + (1 - eta_internal)*abs(tau_load);

  // At standstill the breakaway torque is the Stribeck value of equation (3) at w = 0.
  tau0 = tau_C + tau_S;
  tau0_max = peak*tau0;
  // Regularised (w_small > 0): the state machine stays in mode Free and the friction is a
  // continuous function of the speed.
  free = w_small > 0;

  // The state machine (MSL PartialFriction).
  startForward = pre(mode) == Stuck and (sa > tau0_max/unitTorque or pre(startForward) and
    sa > tau0/unitTorque) or pre(mode) == Backward and w_relfric > w_jump or initial() and
    (w_relfric > 0);
  startBackward = pre(mode) == Stuck and (sa < -tau0_max/unitTorque or pre(startBackward) and
    sa < -tau0/unitTorque) or pre(mode) == Forward and w_relfric < -w_jump or initial() and
    (w_relfric < 0);
  locked = not free and not (pre(mode) == Forward or startForward or pre(mode) == Backward or
    startBackward);
  a_relfric/unitAngularAcceleration = if locked then 0 else if free then sa else if startForward
    then sa - tau0_max/unitTorque else if startBackward then sa + tau0_max/unitTorque else if
    pre(mode) == Forward then sa - tau0_max/unitTorque else sa + tau0_max/unitTorque;
  mode = if free then Free else (if (pre(mode) == Forward or pre(mode) == Free or startForward)
    and w_relfric > 0 then Forward else if (pre(mode) == Backward or pre(mode) == Free or
    startBackward) and w_relfric < 0 then Backward else Stuck);

  tau = if w_small > 0 then
      tanh(w/max(w_small, Modelica.Constants.small))*(tau_C + tau_S*exp(-f_exp*abs(w)) + (1 - eta_internal)*abs(tau_load)) + d_vis*w
    else if locked then sa*unitTorque else
      (if startForward then tau_slide_pos else if startBackward then -tau_slide_neg else
       if pre(mode) == Forward then tau_slide_pos else -tau_slide_neg);
  lossPower = tau*w_relfric;

  annotation (
    Icon(coordinateSystem(preserveAspectRatio=true, extent={{-100,-100},{100,100}}),
      graphics={
        Rectangle(extent={{-100,10},{100,-10}}, lineColor={64,64,64},
          fillColor={192,192,192}, fillPattern=FillPattern.HorizontalCylinder),
        Rectangle(extent={{-60,-20},{60,-40}}, lineColor={0,0,0},
          fillColor={175,175,175}, fillPattern=FillPattern.Solid),
        Rectangle(extent={{-60,40},{60,20}}, lineColor={0,0,0},
          fillColor={175,175,175}, fillPattern=FillPattern.Solid),
        Text(extent={{-150,100},{150,60}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>
Friction of drive-system parts (bearings, gearboxes, actuators) between the shaft and the
housing. While the part slides, the friction torque is the Stribeck law of equation (3) plus
the load-dependent gear-stage loss of equation (4):
</p>
<pre>
  tau_fric,S = tau_C + d_vis*|w| + tau_S*exp(-f_exp*|w|)             (3)
  tau_fric   = tau_fric,S + (1 - eta_GE)*|tau_load|                  (4)
</pre>
<p>
acting against the direction of motion, with <code>tau_load</code> the torque transmitted
through the element. The load-dependent part is present only in motion (after the
break-out): at standstill the part sticks until the torque needed to hold it exceeds
<code>peak*(tau_C + tau_S)</code>. Stick/slip switching uses the state machine of
<code>Modelica.Mechanics.Rotational.Interfaces.PartialFriction</code> (as the MSL
<code>BearingFriction</code>; its equations are declared in this class, since the MSL base
class has a parameter <code>w_small</code> of its own, the speed threshold for velocity jumps).
</p>
<p>
With a regularisation speed <code>w_small &gt; 0</code> the element has no stick/slip state
machine (it stays in mode <code>Free</code>) and the friction is continuous in the speed:
</p>
<pre>
  tau = tanh(w/w_small)*(tau_C + tau_S*exp(-f_exp*|w|) + (1 - eta_GE)*|tau_load|) + d_vis*w
</pre>
<p>
Far above <code>w_small</code> this is the sliding law above; at standstill the element
transmits the load without friction (no breakaway torque). Drive-system models use it for the
many bearings and gear stages of a transmission (<code>highlift export</code> writes
<code>w_small = 0.1 rad/s</code>, as the simulator), so that they do not switch between stuck
and sliding at every start and stop; <code>w_small = 0</code> (the default) is the exact
stick/slip law.
</p>
<p>
The efficiency <code>eta_GE</code> is a parameter, or an input (for the geared rotary
actuator, whose efficiency depends on the input angle after a reversal).
</p>
</html>"));
end StribeckFriction;
