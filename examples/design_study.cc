// Design study: how does the size of the inboard torque tube trade shaft mass against stiffness,
// peak loads and strength? Loads the A380-class flap project (examples/a380_class_flaps.json),
// varies the outer diameter of the 50 mm inboard tubes from 40 to 60 mm (wall thickness kept),
// and prints for each size the shaft mass, the first eigenfrequency (PDU clamped), the worst
// single-DOF peak load on an inboard tube (jam or rupture, paper eq. 1) and its margin to the
// tube's torque capacity. Usage: design_study [PROJECT.json]
#include <cstdio>
#include <numbers>

#include "highlift/core/project_io.h"
#include "highlift/reduced_models/analyses.h"

int main(int argc, char** argv) {
  namespace rm = highlift::reduced_models;
  const highlift::Project base = highlift::LoadProject(argc > 1 ? argv[1] : "examples/a380_class_flaps.json");
  std::printf("D [mm]  shaft mass [kg]  f1 [Hz]  worst peak on inboard tube, upper bound [N*m]  margin [%%]\n");
  for (double D : {0.040, 0.045, 0.050, 0.055, 0.060}) {
    highlift::Project p = base;
    for (highlift::Component& c : p.components)
      if (c.type == "torque_shaft" && c.parameters["outer_diameter"].nominal == 0.050)
        c.parameters["outer_diameter"].nominal = D, c.parameters["outer_diameter"].domain = highlift::Domain::Point(D);
    rm::PeakOptions options;
    options.rank = false;
    const rm::PeakReport peaks = rm::AnalysePeaks(p, options);
    const rm::ComponentPeak* worst = nullptr;  // the inboard tube with the smallest margin
    for (const rm::ComponentPeak& w : peaks.worst)
      if (p.FindComponent(w.component)->parameters["outer_diameter"].nominal == D && (!worst || w.margin < worst->margin))
        worst = &w;
    std::printf("%6.0f  %15.1f  %7.2f  %44.0f  %10.1f\n", D * 1e3, rm::ShaftMass(p),
                rm::FirstEigenfrequency(p) / (2 * std::numbers::pi), worst->torque.bounds.hi, 100 * worst->margin);
  }
}
