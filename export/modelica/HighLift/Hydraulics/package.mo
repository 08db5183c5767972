within HighLift;
package Hydraulics "Hydraulic components of power drive units (incompressible oil, volume flow)"
  extends Modelica.Icons.Package;

  annotation (Documentation(info="<html>
<p>
Lumped hydraulic components for modelling a hydraulic PDU drive train: pressure source and
return, turbulent resistance, 4/3-way servo valve, differential cylinder and
variable-displacement hydraulic motor (VDHM). The oil is incompressible in lines and
orifices; compressibility is modelled in the cylinder chambers (bulk modulus). Ports carry
the pressure and the volume flow rate into the component
(<a href=\"modelica://HighLift.Hydraulics.Interfaces.Port\">Interfaces.Port</a>).
</p>
</html>"));
end Hydraulics;
