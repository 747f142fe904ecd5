#pragma once
// The cell's volumetric elastic modulus eps = V dP/dV at rest (ours; issue 46), the number pressure probes
// measure in plant cells: water injected or withdrawn, the pressure's change over the volume's. For closed
// cells (fluid.model = cavity): each cell's fluid mass moved by +-kMassStep of itself, the wall relaxed to
// equilibrium with the mass kept (quasi_static.hpp), and eps = V (P+ - P-) / (V+ - V-), P the cells'
// volume-weighted mean pressure and V their total volume (a tissue's cells all at once). The pressure at
// equilibrium is the wall's (Young-Laplace), so eps is the wall's, whatever K: K sets how much of the
// mass goes into compressing the water instead. The state is put back as it was.
namespace cellsim {

class Simulation;

constexpr double kMassStep = 1e-3;  // the relative mass change of each side of the difference

// NaN for an SPH fluid (whose particles have no pressure-volume relation to relax along).
double volumetric_modulus_Pa(Simulation& sim);

}  // namespace cellsim
