within HighLift.Models;
model OneStationRig "one-station rig"
  HighLift.Mechanical.WingTipBrake wtb(tauB_max=550, tauB_lim=700, t_B=0.03, t_lat=0.1, J=5e-04)
    annotation (Placement(transformation(extent={{110,-130},{130,-110}})));
  Modelica.Mechanics.Rotational.Components.Inertia appu(J=1e-05)
    annotation (Placement(transformation(extent={{150,-50},{170,-30}})));
  HighLift.Mechanical.LossyInertia shaft_3_mass_a(J=0.000378486583537772, tau_C=0.1875, w_small=0.1)
    "lumped: shaft_3"
    annotation (Placement(transformation(extent={{270,-50},{290,-30}})));
  Modelica.Mechanics.Rotational.Components.SpringDamper shaft_3_spring(
    c=3349.1019961110037,
    d=1.3396407984444016)
    "series stiffness of shaft_3"
    annotation (Placement(transformation(extent={{230,-50},{250,-30}})));
  HighLift.Mechanical.LossyInertia shaft_3_mass_b(J=0.000378486583537772, tau_C=0.1875, w_small=0.1)
    "lumped: shaft_3"
    annotation (Placement(transformation(extent={{190,-50},{210,-30}})));
  HighLift.Mechanical.GearedRotaryActuator gra_1(
    ratio=200,
    eta_op=0.85,
    eta_ai=0.7,
    phi_eta=3.141592653589793,
    w_eta=0.1,
    J_in=0.001,
    J_load=0.0388,
    tau_C=0.2,
    d_vis=2e-04,
    tau_S=0.07,
    f_exp=10,
    w_small=0.1)
    annotation (Placement(transformation(extent={{310,-10},{330,10}})));
  HighLift.Mechanical.TorqueLimiter stl_1(
    tau1_ext=180,
    tau1_ret=126,
    tau2_ext=225,
    tau2_ret=157.5,
    c1=20000,
    c2=1000,
    c3=1e+05,
    d=8,
    tauB_max=360,
    J=5e-04)
    annotation (Placement(transformation(extent={{270,-10},{290,10}})));
  HighLift.Mechanical.BranchGearbox gbx_1(
    ratio=2,
    elastic=false,
    J=0.000625,
    tau_C=0.1,
    d_vis=1e-04,
    tau_S=0.035,
    f_exp=10,
    w_small=0.1,
    eta_GE=0.97)
    annotation (Placement(transformation(extent={{230,-10},{250,10}})));
  HighLift.Mechanical.LossyInertia shaft_1_shaft_2_mass_a(
    J=0.0019479110579574866,
    tau_C=0.675,
    w_small=0.1)
    "lumped: shaft_1, brg_1, shaft_2"
    annotation (Placement(transformation(extent={{110,-10},{130,10}})));
  HighLift.Mechanical.Disconnector shaft_1_shaft_2_spring(
    c=1531.3680823552831,
    d=0.6125472329421133,
    t_disconnect=1)
    "series stiffness of shaft_1, brg_1, shaft_2 (ruptures)"
    annotation (Placement(transformation(extent={{150,-10},{170,10}})));
  HighLift.Mechanical.LossyInertia shaft_1_shaft_2_mass_b(
    J=0.0019479110579574866,
    tau_C=0.675,
    w_small=0.1)
    "lumped: shaft_1, brg_1, shaft_2"
    annotation (Placement(transformation(extent={{190,-10},{210,10}})));
  HighLift.Mechanical.TorqueLimiter stl(
    tau1_ext=470,
    tau1_ret=470,
    tau2_ext=587.5,
    tau2_ret=587.5,
    c1=20000,
    c2=1000,
    c3=1e+05,
    d=8,
    tauB_max=940,
    J=0.001)
    annotation (Placement(transformation(extent={{70,-10},{90,10}})));
  HighLift.Drives.PDU pdu(
    n_m=2,
    J_m=3e-04,
    ratio=20,
    J_g=0.02,
    w_max=25.3,
    tau_stall=1000,
    P_max=18000,
    t_ramp=0.4,
    tauPOB=1100,
    useStopInput=true)
    annotation (Placement(transformation(extent={{30,-10},{50,10}})));
  Modelica.Blocks.Sources.CombiTimeTable pdu_speed_command(
    table=[0, 0; 0.4, 25.3; 3, 25.3],
    extrapolation=Modelica.Blocks.Types.Extrapolation.HoldLastPoint)
    "PDU output speed command [rad/s] of load case extend_opposing"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}})));
  Modelica.Mechanics.Rotational.Sources.Torque gra_1_airload
    "airload on gra_1 (torque on the output, positive in the extend direction: the load case's table times -1, as its positive values oppose the extension)"
    annotation (Placement(transformation(extent={{350,-10},{370,10}})));
  Modelica.Mechanics.Rotational.Sensors.AngleSensor gra_1_output_angle
    "output angle of gra_1"
    annotation (Placement(transformation(extent={{350,-50},{370,-30}})));
  Modelica.Blocks.Tables.CombiTable1Ds gra_1_airload_table(
    table=[0, -5000; 2.2, -20000],
    extrapolation=Modelica.Blocks.Types.Extrapolation.HoldLastPoint)
    "airload [N*m] against the output angle of gra_1 [rad]"
    annotation (Placement(transformation(extent={{390,-10},{410,10}})));
  HighLift.Control.Monitoring monitor(
    phi_asym=12.566370614359172,
    w_over=32.89,
    phi_unc=12.566370614359172,
    t_detect=0.01)
    "failure monitoring: asymmetry, overspeed, uncommanded movement"
    annotation (Placement(transformation(extent={{70,-50},{90,-30}})));
  Modelica.Mechanics.Rotational.Sensors.AngleSensor appu_angle_sensor
    "shaft angle at appu"
    annotation (Placement(transformation(extent={{110,-50},{130,-30}})));
  Modelica.Mechanics.Rotational.Sensors.SpeedSensor appu_speed_sensor
    "shaft speed at appu"
    annotation (Placement(transformation(extent={{110,-90},{130,-70}})));
  Modelica.Blocks.Continuous.Integrator monitor_commanded_angle
    "commanded PDU angle"
    annotation (Placement(transformation(extent={{30,-50},{50,-30}})));

equation
  connect(shaft_3_mass_a.flange_b, shaft_3_spring.flange_a)
    annotation (Line(points={{290,-40},{230,-40}}));
  connect(shaft_3_spring.flange_b, shaft_3_mass_b.flange_a)
    annotation (Line(points={{250,-40},{190,-40}}));
  connect(shaft_1_shaft_2_mass_a.flange_b, shaft_1_shaft_2_spring.flange_a)
    annotation (Line(points={{130,0},{150,0}}));
  connect(shaft_1_shaft_2_spring.flange_b, shaft_1_shaft_2_mass_b.flange_a)
    annotation (Line(points={{170,0},{190,0}}));
  connect(pdu_speed_command.y[1], pdu.w_ref)
    annotation (Line(points={{0,0},{28,0}}, color={0,0,127}));
  connect(pdu.flange_left, stl.flange_a)
    annotation (Line(points={{40,10},{70,0}}));
  connect(stl.flange_b, shaft_1_shaft_2_mass_a.flange_a)
    annotation (Line(points={{90,0},{110,0}}));
  connect(shaft_1_shaft_2_mass_b.flange_b, gbx_1.flange_a)
    annotation (Line(points={{210,0},{230,0}}));
  connect(gbx_1.flange_branch, stl_1.flange_a)
    annotation (Line(points={{240,10},{270,0}}));
  connect(stl_1.flange_b, gra_1.flange_a)
    annotation (Line(points={{290,0},{310,0}}));
  connect(gbx_1.flange_b, shaft_3_mass_a.flange_a)
    annotation (Line(points={{250,0},{270,-40}}));
  connect(shaft_3_mass_b.flange_b, appu.flange_a)
    annotation (Line(points={{210,-40},{150,-40}}));
  connect(appu.flange_b, wtb.flange_a)
    annotation (Line(points={{170,-40},{110,-120}}));
  connect(gra_1_airload.flange, gra_1.flange_b)
    annotation (Line(points={{370,0},{330,0}}));
  connect(gra_1.flange_b, gra_1_output_angle.flange)
    annotation (Line(points={{330,0},{370,-40}}));
  connect(gra_1_output_angle.phi, gra_1_airload_table.u)
    annotation (Line(points={{371,-46},{388,0}}, color={0,0,127}));
  connect(gra_1_airload_table.y[1], gra_1_airload.tau)
    annotation (Line(points={{400,0},{348,0}}, color={0,0,127}));
  connect(appu.flange_a, appu_angle_sensor.flange)
    annotation (Line(points={{150,-40},{130,-40}}));
  connect(appu.flange_a, appu_speed_sensor.flange)
    annotation (Line(points={{150,-40},{130,-80}}));
  connect(appu_angle_sensor.phi, monitor.phi_left)
    annotation (Line(points={{131,-46},{80,-40}}, color={0,0,127}));
  connect(appu_speed_sensor.w, monitor.w_left)
    annotation (Line(points={{131,-89},{80,-40}}, color={0,0,127}));
  connect(appu_angle_sensor.phi, monitor.phi_right)
    annotation (Line(points={{131,-46},{80,-40}}, color={0,0,127}));
  connect(appu_speed_sensor.w, monitor.w_right)
    annotation (Line(points={{131,-89},{80,-40}}, color={0,0,127}));
  connect(pdu.phi, monitor.phi_pdu)
    annotation (Line(points={{51,-6},{80,-40}}, color={0,0,127}));
  connect(pdu_speed_command.y[1], monitor_commanded_angle.u)
    annotation (Line(points={{0,0},{28,-40}}, color={0,0,127}));
  connect(monitor_commanded_angle.y, monitor.phi_cmd)
    annotation (Line(points={{51,-40},{80,-40}}, color={0,0,127}));
  connect(monitor.wtb, wtb.apply)
    annotation (Line(points={{80,-40},{120,-108}}, color={0,0,127}));
  connect(monitor.wtb, pdu.stop)
    annotation (Line(points={{80,-40},{40,0}}, color={0,0,127}));

  annotation (
    experiment(StopTime=3, Tolerance=1e-06, Interval=0.001),
    Diagram(coordinateSystem(preserveAspectRatio=false, extent={{-20,-140},{420,20}})),
    Documentation(info="<html>
<p>Drive system of the highlift project <strong>one-station rig</strong>, exported by <code>highlift export</code> at reduced resolution (inertias lumped at gearboxes and stations). It is the element network that <code>highlift simulate</code> integrates; instance names are its element ids.</p>
<p>A PDU drives one wing transmission: system torque limiter, two shaft segments with a steady bearing, a station (T-gearbox, station torque limiter, geared rotary actuator) and the outboard shaft to the APPU and the wing-tip brake. Numbers: domain.md s3 (E) and the catalogue defaults.</p>
<p>Scenario <strong>rupture_wtb</strong> (rupture), load case <strong>extend_opposing</strong> (extend).</p>
<p>Positive rotation is the extend direction. The model starts at rest with untwisted springs (exported with <code>--start rest</code>; <code>highlift simulate</code> starts from the static equilibrium of the loads held by the parked brakes).</p>
<p>Lumped chains (spring-damper or inertia: members):</p>
<ul>
<li>shaft_3: shaft_3</li>
<li>shaft_1-shaft_2: shaft_1, brg_1, shaft_2</li>
</ul>
</html>"));
end OneStationRig;
