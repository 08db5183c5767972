within HighLift.Examples;
model HydraulicMotorDrive "Valve-controlled variable-displacement motor driving an inertia against a load"
  extends Modelica.Icons.Example;

  HighLift.Hydraulics.PressureSource supply(p_supply=207e5)
    annotation (Placement(transformation(extent={{-100,-60},{-80,-40}})));
  HighLift.Hydraulics.Tank tank(p_return=5e5)
    annotation (Placement(transformation(extent={{80,-60},{100,-40}})));
  HighLift.Hydraulics.TurbulentResistance supplyLine(A=2e-5)
    annotation (Placement(transformation(extent={{-70,-60},{-50,-40}})));
  HighLift.Hydraulics.ServoValve valve(A_max=5e-6)
    annotation (Placement(transformation(extent={{-10,-60},{10,-40}})));
  Modelica.Blocks.Sources.Ramp valveCommand(height=1, duration=0.2, startTime=0.1)
    annotation (Placement(transformation(extent={{-50,-90},{-30,-70}})));
  HighLift.Hydraulics.VariableDisplacementMotor motor
    annotation (Placement(transformation(extent={{-10,0},{10,20}})));
  Modelica.Blocks.Sources.Constant swash(k=1)
    annotation (Placement(transformation(extent={{-50,40},{-30,60}})));
  Modelica.Mechanics.Rotational.Components.Inertia rotor(J=0.01, phi(start=0, fixed=true),
    w(start=0, fixed=true))
    annotation (Placement(transformation(extent={{30,0},{50,20}})));
  Modelica.Mechanics.Rotational.Sources.QuadraticSpeedDependentTorque load(tau_nominal=-10,
    w_nominal=400, TorqueDirection=false)
    annotation (Placement(transformation(extent={{80,0},{60,20}})));

equation
  connect(supply.port, supplyLine.port_a)
    annotation (Line(points={{-80,-50},{-70,-50}}, color={0,0,255}));
  connect(supplyLine.port_b, valve.port_P)
    annotation (Line(points={{-50,-50},{-30,-50},{-30,-70},{-4,-70},{-4,-60}}, color={0,0,255}));
  connect(valve.port_T, tank.port)
    annotation (Line(points={{4,-60},{4,-70},{70,-70},{70,-50},{80,-50}}, color={0,0,255}));
  connect(valveCommand.y, valve.u)
    annotation (Line(points={{-29,-80},{-20,-80},{-20,-50},{-12,-50}}, color={0,0,127}));
  connect(valve.port_A, motor.port_A)
    annotation (Line(points={{-4,-40},{-4,-20},{-20,-20},{-20,4},{-10,4}}, color={0,0,255}));
  connect(valve.port_B, motor.port_B)
    annotation (Line(points={{4,-40},{4,-30},{-24,-30},{-24,16},{-10,16}}, color={0,0,255}));
  connect(swash.y, motor.eps)
    annotation (Line(points={{-29,50},{0,50},{0,22}}, color={0,0,127}));
  connect(motor.flange, rotor.flange_a)
    annotation (Line(points={{10,10},{30,10}}));
  connect(rotor.flange_b, load.flange)
    annotation (Line(points={{50,10},{60,10}}));

  annotation (
    experiment(StopTime=1, Tolerance=1e-6, Interval=0.001),
    Documentation(info="<html>
<p>
The drive train of a hydraulic PDU: the aircraft supply (207 bar) feeds a servo valve through a
line resistance; the valve opens from 0.1 s and the variable-displacement motor accelerates a
rotor against a speed-dependent load until the flow through the valve limits the speed.
</p>
</html>"));
end HydraulicMotorDrive;
