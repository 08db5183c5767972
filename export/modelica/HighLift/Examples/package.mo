within HighLift;
package Examples "Small test models of the HighLift components"
  extends Modelica.Icons.ExamplesPackage;
end Examples;
