within HighLift.Mechanical;
model BranchGearbox "T-gearbox or down-drive: 1:1 through-drive and a geared branch to the station"
  import Modelica.Units.SI;
  extends Modelica.Mechanics.Rotational.Interfaces.PartialTwoFlangesAndSupport;

  parameter Real ratio(start=2) "Gear ratio, input speed / branch speed";
  parameter Boolean elastic = false
    "= true, if the branch has a stiffness (and backlash)"
    annotation (Evaluate=true, choices(checkBox=true));
  parameter SI.RotationalSpringConstant c(min=Modelica.Constants.small) = 1e4
    "Torsional stiffness of the branch, referred to the input (used only when elastic = true: give it then)" annotation (Dialog(enable=elastic));
  parameter SI.RotationalDampingConstant d(min=0) = 0 "Damping of the branch"
    annotation (Dialog(enable=elastic));
  parameter SI.Angle b(min=0) = 0 "Total backlash of the branch, referred to the input"
    annotation (Dialog(enable=elastic));
  parameter SI.Inertia J(min=0, start=1e-3) "Inertia referred to the input";
  parameter SI.Torque tau_C(min=0) = 0 "Coulomb friction torque, equation (3)";
  parameter SI.RotationalDampingConstant d_vis(min=0) = 0 "Viscous friction coefficient, equation (3)";
  parameter SI.Torque tau_S(min=0) = 0 "Stribeck torque at standstill, equation (3)";
  parameter Real f_exp(unit="s/rad", min=0) = 10 "Decay of the Stribeck torque with speed, equation (3)";
  parameter Real eta_GE(min=0, max=1) = 1 "Efficiency of the branch gear meshes, equation (4)";
  parameter SI.AngularVelocity w_small(min=0) = 0
    "Regularisation speed: 0 = exact stick/slip; > 0 = friction scaled by tanh(w/w_small), no stick/slip";

  Modelica.Mechanics.Rotational.Interfaces.Flange_b flange_branch "Down-drive flange to the station"
    annotation (Placement(transformation(extent={{-10,90},{10,110}})));
  GeneralRotationalElement branch(elastic=elastic, c=c, d=d, b=b, J=J, tau_C=tau_C, d_vis=d_vis,
    tau_S=tau_S, f_exp=f_exp, eta_GE=eta_GE, w_small=w_small, ratio=ratio, useSupport=true)
    annotation (Placement(transformation(
        origin={0,40},
        extent={{-10,-10},{10,10}},
        rotation=90)));

equation
  connect(flange_a, flange_b)
    annotation (Line(points={{-100,0},{100,0}}));
  connect(flange_a, branch.flange_a)
    annotation (Line(points={{-100,0},{0,0},{0,30}}));
  connect(branch.flange_b, flange_branch)
    annotation (Line(points={{0,50},{0,100}}));
  connect(branch.support, internalSupport)
    annotation (Line(points={{10,40},{40,40},{40,-80},{0,-80}}));

  annotation (
    Icon(coordinateSystem(preserveAspectRatio=true, extent={{-100,-100},{100,100}}),
      graphics={
        Rectangle(extent={{-100,10},{100,-10}}, lineColor={64,64,64},
          fillColor={192,192,192}, fillPattern=FillPattern.HorizontalCylinder),
        Rectangle(extent={{-10,100},{10,10}}, lineColor={64,64,64},
          fillColor={192,192,192}, fillPattern=FillPattern.VerticalCylinder),
        Rectangle(extent={{-40,40},{40,-40}}, lineColor={64,64,64},
          fillColor={255,255,255}, fillPattern=FillPattern.HorizontalCylinder),
        Text(extent={{-150,-50},{150,-90}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>
A T-gearbox or station down-drive: the transmission passes through 1:1 from
<code>flange_a</code> (input, towards the PDU) to <code>flange_b</code> (through-drive), and a
<a href=\"modelica://HighLift.Mechanical.GeneralRotationalElement\">GeneralRotationalElement</a>
drives the station at <code>flange_branch</code> with
<code>ratio</code> = input speed / branch speed. Inertia, friction (equation 3) and the
load-dependent mesh loss (equation 4, with the torque of the branch) are referred to the input;
with <code>w_small &gt; 0</code> they follow the regularised law of
<a href=\"modelica://HighLift.Mechanical.StribeckFriction\">StribeckFriction</a> (no stick/slip).
</p>
</html>"));
end BranchGearbox;
