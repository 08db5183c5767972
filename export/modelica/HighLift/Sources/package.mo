within HighLift;
package Sources "Torque sources the Modelica Standard Library 4.0.0 does not have"
  extends Modelica.Icons.SourcesPackage;

  annotation (Documentation(info="<html>
<p>
Sources that the element networks of highlift use and that appear in the Modelica Standard
Library only after version 4.0.0, written here on the MSL 4.0.0 interfaces with the same
parameters and equations, so that the library and the exported models load under the
<code>uses(Modelica(version=\"4.0.0\"))</code> annotation of <code>HighLift</code>.
</p>
</html>"));
end Sources;
