within HighLift;
package Drives "Power drive units"
  extends Modelica.Icons.Package;

  annotation (Documentation(info="<html>
<p>
The power drive unit (PDU) in the centre fuselage that drives the left and right transmission.
</p>
</html>"));
end Drives;
