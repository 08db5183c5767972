within HighLift;
package Mechanical "Mechanical components of the drive train"
  extends Modelica.Icons.Package;

  annotation (Documentation(info="<html>
<p>
One-dimensional rotational components of the transmission. Inertia, stiffness, damping and
backlash come from the Modelica Standard Library (<code>Inertia</code>,
<code>ElastoBacklash</code>, <code>IdealGear</code>); this package adds the friction laws of
drive-system parts (Stribeck law and load-dependent gear loss), the brakes and torque limiters,
and the failure elements.
</p>
</html>"));
end Mechanical;
