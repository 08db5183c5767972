within HighLift;
package Control "Monitoring and brake actuation"
  extends Modelica.Icons.Package;

  annotation (Documentation(info="<html>
<p>
The failure detection of the drive system (asymmetry, overspeed and uncommanded movement, with
a detection latency) that commands the wing-tip brakes, and the actuation of brakes from a
Boolean command.
</p>
</html>"));
end Control;
