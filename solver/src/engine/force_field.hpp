#pragma once
// The force field (model.md §2-7, §10-11): the ordered list of the terms that push on the wall (its
// springs, bending, the contacts between cells, the fluid's push, the plates). Each term has three faces
// of one law: its forces (with the powers of its own rows of the energy table), its stored energy, and
// where it has one, its stiffness -dF/dx. The leapfrog's forces, the energy account and the quasi-static
// preconditioner are the three loops below, over the one list; a new law is one term added to it
// (Simulation's constructor lays the list out).
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "core/energy_terms.hpp"
#include "core/state.hpp"
#include "engine/fluid_model.hpp"
#include "engine/phase_timer.hpp"
#include "geometry/block_stiffness.hpp"

namespace cellsim {

// What a term reads of the moment besides the state and its own law.
struct ForceContext {
  FluidContext fluid;         // the surface, the lists, the cells, the EOS of the moment, L_p, threads
  double ramp;                // of L_ref and P_T: the drying's smoothstep, 1 in compression (drying.hpp)
  double ramp_rate_1_s;       // its d/dt (0 out of drying)
  bool pairs_fresh;           // the density's drift step weighed the fluid's pairs at these positions
};

class ForceTerm {
 public:
  virtual ~ForceTerm() = default;
  // Adds its forces on the wall particles into wall_force, and writes the powers of its own rows of the
  // energy table into power_W (the kicks integrate them).
  virtual void add_forces(State& s, const ForceContext& c, Eigen::Matrix3Xd& wall_force, EnergyValues& power_W) = 0;
  // Writes its rows of the stored energy (and a loss that is a function of the state) into e.
  virtual void add_energy(const State& s, const ForceContext& c, EnergyValues& e) const = 0;
  // Adds its stiffness -dF/dx on the wall into K (in K's pattern), or the part of it the quasi-static
  // preconditioner keeps; returns false for a term that has none.
  virtual bool add_stiffness(const State&, const ForceContext&, BlockStiffness&) const { return false; }
  // Where `cellsim bench` counts the time of its forces.
  virtual Phase phase() const = 0;
};

class ForceField {
 public:
  void add(std::unique_ptr<ForceTerm> term) { terms_.push_back(std::move(term)); }
  // The wall's forces (wall_force, overwritten) and the terms' powers, in the list's order; each term's time
  // into its phase of the timer.
  void forces(State& s, const ForceContext& c, Eigen::Matrix3Xd& wall_force, EnergyValues& power_W,
              PhaseTimer& timer) const;
  // Every term of the account now: the running integrals from s.energy, the terms' stored energies, and
  // the wall's kinetic energy (added to the fluid's part).
  EnergyValues energy(const State& s, const ForceContext& c) const;
  // The terms' stiffnesses summed into K (set to zero first), in the list's order.
  void stiffness(const State& s, const ForceContext& c, BlockStiffness& K) const;
  const std::vector<std::unique_ptr<ForceTerm>>& terms() const { return terms_; }

 private:
  std::vector<std::unique_ptr<ForceTerm>> terms_;
};

}  // namespace cellsim
