#pragma once
// One run of a tissue (one cell, or several: model.md §10): the state, and the leapfrog step that advances
// it (model.md §2-7). The step reads like the model: geometry -> neighbours -> density and mass transfer
// -> fluid forces -> the force field on the wall (its springs, bending, the contacts between cells, the
// fluid's push, the plates: force_field.hpp) -> integrate -> checks. The fluid is a model of its own,
// seen through the faces of fluid_model.hpp; the quasi-static scheme (quasi_static.hpp) steps the same
// state through the same force field.
#include <cmath>
#include <memory>
#include <string>

#include "core/params.hpp"
#include "core/state.hpp"
#include "engine/energy_account.hpp"
#include "engine/fluid_model.hpp"
#include "engine/measures.hpp"
#include "engine/phase_timer.hpp"
#include "engine/force_field.hpp"
#include "engine/force_terms.hpp"
#include "geometry/neighbours.hpp"
#include "geometry/heterogeneity.hpp"
#include "geometry/surface.hpp"
#include "geometry/tissue.hpp"
#include "geometry/wall_mesh.hpp"
#include "physics/bending.hpp"
#include "physics/cell_contact.hpp"
#include "physics/eos.hpp"
#include "physics/plate_motion.hpp"
#include "physics/plates.hpp"
#include "physics/wall_bonds.hpp"

namespace cellsim {

class Simulation {
 public:
  Simulation(const Params& p, const Tissue& tissue);

  void step();                  // one kick-drift-kick step of dt
  // A quasi-static step (quasi_static.hpp) moves the loads at fixed particles: the clock by dt, and with
  // it the plates and the drying ramp; relaxes (a periodic slab's period with the wall, where it
  // follows); then ends as every step does (the unloading plate's turn, the step counts, the state's checks).
  void advance_loads(double dt);
  // Whether a periodic slab's period follows zero lateral stress now: in drying, and in compression if
  // unconfined (model.md §10b).
  bool period_follows() const;
  // Strains a periodic slab's period, the cells moving with it whole (periodic_slab.hpp).
  void strain_period(const Eigen::Vector2d& strain);
  void finish_step();
  void start_compression();     // switches L_p and places the plates (model.md §6)
  // Continue from a saved state of this case (one read from a file: check_restorable, io/state_io.hpp).
  void restore(const State& saved);
  double nominal_strain() const;     // (H_c - H) / H_c during compression, 0 before

  const State& state() const { return s_; }
  // A step's neighbour lists trust that only its drift moved the particles since the last step (and
  // skip their pass over the positions while the drifts leave the skin unused). This forgets that, for
  // the next step; after moving particles through a reference kept from an earlier call, call it again.
  State& mutable_state() {
    moved_since_lists_m_ = INFINITY;
    return s_;
  }
  const WallMesh& mesh() const { return mesh_; }
  const BondLaw& bond_law() const { return bond_law_; }
  const FluidModel& fluid() const { return *fluid_.model; }
  // The fluid's quasi-static face (fluid_model.hpp), for the increments of the quasi-static scheme, the
  // closed cells' settle and the volumetric modulus; null for a fluid that has none (SPH).
  IncrementFluid* fluid_increments() { return fluid_.increments; }
  // The terms on the wall, and what they read of the moment (force_field.hpp).
  const ForceField& force_field() const { return field_; }
  ForceContext force_context() const;
  const Params& params() const { return p_; }
  EquationOfState eos() const;  // with the turgor of the moment
  double turgor_Pa() const;      // P_T: ramps from P_T0 to P_T(X) during drying (drying.hpp)
  Record record() const;
  const PhaseTimer& timer() const { return timer_; }
  const NeighbourLists& neighbours() const { return neighbours_; }
  PhaseTimer& timer() { return timer_; }
  // Threads for the fluid pair loop (threads.hpp); 1 unless set. Throws InputError if impossible.
  void set_threads(int threads);

  // Checks for a record: every fluid particle inside its own cell's wall, and no wall particle inside
  // another cell. Throws NumericalFailure.
  void check_containment() const;

  // For the relaxation at rest (settle.hpp): forces at the current positions, and the restart of
  // the clock once the cell is at rest (t = 0, velocities zero, D0 of Eq 6 and M_f0 taken anew).
  void refresh_rates() {
    moved_since_lists_m_ = INFINITY;  // the settle moves the particles itself
    compute_rates();
  }
  // The force on each fluid particle (none for a fluid without particles).
  const Eigen::Matrix3Xd& fluid_force() const;
  const Eigen::Matrix3Xd& wall_force() const { return wall_force_; }
  void start_at_rest();
  // For a relaxation of the wall (quasi_static.hpp): the plates' law, the powers of the last force
  // evaluation, what the fluid reads of the step, every term of the energy account now.
  const PlateLaw& plate_law() const { return plate_law_; }
  const EnergyValues& power_W() const { return energy_power_W_; }
  FluidContext fluid_context() const;
  EnergyValues energy_terms_now() const;

  // Per cell: the wall pressure (outward push along the normals / the cell's wall area) and the mean
  // fluid pressure, at the last force evaluation.
  const std::vector<double>& cell_wall_pressure_Pa() const { return push_->cell_wall_pressure_Pa(); }
  std::vector<double> cell_mean_fluid_pressure_Pa() const { return fluid_.model->cell_mean_pressure_Pa(cells_); }
  const CellRanges& cells() const { return cells_; }
  const std::vector<LamellaBond>& lamella() const { return lamella_; }
  const WallSurface& surface() const { return surface_; }

 private:
  // The constructor's work, with the heterogeneous properties' factors drawn once (they set the bond law
  // and the fluid's viscosity).
  Simulation(const Params& p, const Tissue& tissue, const PropertyFactors& factors);
  // density_step_s > 0: first advance the density and mass by that step from the continuity rates at
  // these positions and velocities (time.density_update = drift), then the forces at the new density.
  void compute_rates(double density_step_s = 0);
  void update_geometry();
  void update_neighbours();
  double contraction_ramp() const;  // of L_ref and P_T: smoothstep in drying (drying.hpp), 1 in compression
  // time.density_update = drift, for a fluid of particles (a closed cell has no density to drift).
  bool density_in_drift() const { return fluid_.particles && fluid_.particles->density_in_drift(); }
  void lay_out_force_field();
  void follow_lateral_stress(double dt);  // a periodic slab's period (model.md §10b)
  void kick(double half_dt);
  void drift(double dt);
  void check_state() const;
  void check_time_step() const;
  void start_energy_account();  // t = 0: the flows start from zero, the stored energy is the reference
  void advance_clock(double dt);  // time, and the plates with it
  std::string where() const;

  int threads_ = 1;

  Params p_;
  WallMesh mesh_;
  CellRanges cells_;
  std::vector<LamellaBond> lamella_;
  CellContactLaw contact_law_;
  State s_;
  Bending bending_;
  NeighbourLists neighbours_;
  Fluid fluid_;
  double fluid_wall_cutoff_m_ = 0;  // of the wall-fluid pair list, at the current h (the fluid's choice)
  PlateLaw plate_law_;
  PlateMotion plate_motion_;
  BondLaw bond_law_;
  ForceField field_;
  const FluidPushTerm* push_ = nullptr;  // the field's fluid term, for its push on the wall

  // Rates at the current positions.
  Eigen::Matrix3Xd wall_force_;
  EnergyValues energy_power_W_{};  // of the terms integrated over the kicks, at the current positions
  WallSurface surface_;  // area, volume and normals at the current positions
  double Lp_m_per_s_Pa_;
  double moved_since_lists_m_ = INFINITY;  // how far any particle can have moved since the lists looked
  PhaseTimer timer_;
};

}  // namespace cellsim
