within HighLift.Hydraulics;
package Interfaces "Hydraulic connector and partial models"
  extends Modelica.Icons.InterfacesPackage;
end Interfaces;
