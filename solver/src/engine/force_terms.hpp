#pragma once
// The force field's terms (force_field.hpp), each one law's three faces over its physics/ file: the
// wall's springs (Eqs 15, 16, 21), its bending (Eq 20), the contacts and middle lamella between cells
// (model.md §10), the fluid's push on the wall (its model's, fluid_model.hpp) and the plates (Eq 22).
#include <vector>

#include "engine/force_field.hpp"
#include "engine/fluid_model.hpp"
#include "geometry/wall_mesh.hpp"
#include "physics/bending.hpp"
#include "physics/cell_contact.hpp"
#include "physics/plate_motion.hpp"
#include "physics/plates.hpp"
#include "physics/wall_bonds.hpp"

namespace cellsim {

// Eq 15's stiff springs, Eq 21's contraction and Eq 16's damping on every bond, with a plastic wall's
// sliders (wall_plasticity.hpp); and the drying ramp's power at fixed particles (its P_T and L_ref: the
// drive, drying.hpp), which needs the fluid's share of the stored energy per unit of turgor.
class WallSpringsTerm final : public ForceTerm {
 public:
  WallSpringsTerm(const WallMesh& mesh, const BondLaw& law, const FluidModel& fluid, double turgor_Pa, double dryness,
                  double contraction_ratio)
      : mesh_(mesh), law_(law), fluid_(fluid), turgor_Pa_(turgor_Pa), dryness_(dryness),
        contraction_ratio_(contraction_ratio) {}
  void add_forces(State& s, const ForceContext& c, Eigen::Matrix3Xd& wall_force, EnergyValues& power_W) override;
  void add_energy(const State& s, const ForceContext& c, EnergyValues& e) const override;
  // The springs at the sliders' elongations held (wall_stiffness.hpp).
  bool add_stiffness(const State& s, const ForceContext& c, BlockStiffness& K) const override;
  Phase phase() const override { return Phase::WallBonds; }

 private:
  const WallMesh& mesh_;
  const BondLaw& law_;
  const FluidModel& fluid_;
  double turgor_Pa_, dryness_, contraction_ratio_;
  BondScratch scratch_;
};

// Eq 20 over the wall's triangles.
class BendingTerm final : public ForceTerm {
 public:
  explicit BendingTerm(const Bending& bending) : bending_(bending) {}
  void add_forces(State& s, const ForceContext& c, Eigen::Matrix3Xd& wall_force, EnergyValues& power_W) override;
  void add_energy(const State& s, const ForceContext& c, EnergyValues& e) const override;
  // Its Gauss-Newton part on the bonds (bending.hpp): a bound of the exact Hessian, in the bonds' pattern.
  bool add_stiffness(const State& s, const ForceContext& c, BlockStiffness& K) const override;
  Phase phase() const override { return Phase::Bending; }

 private:
  const Bending& bending_;
};

// Contact and middle lamella between the walls of different cells (cell_contact.hpp); a periodic slab's
// lateral stress from their virial (periodic_slab.hpp). In the field of a tissue only.
class CellContactTerm final : public ForceTerm {
 public:
  CellContactTerm(const std::vector<LamellaBond>& lamella, const CellContactLaw& law) : lamella_(lamella), law_(law) {}
  void add_forces(State& s, const ForceContext& c, Eigen::Matrix3Xd& wall_force, EnergyValues& power_W) override;
  void add_energy(const State& s, const ForceContext& c, EnergyValues& e) const override;
  // Along each contact's line and each intact bond's (cell_contact.hpp), where the pattern joins the pair.
  bool add_stiffness(const State& s, const ForceContext& c, BlockStiffness& K) const override;
  Phase phase() const override { return Phase::CellContact; }

 private:
  const std::vector<LamellaBond>& lamella_;
  const CellContactLaw& law_;
};

// The fluid's push on the wall (the LJ coupling, the pressure coupling, or a closed cell's P dV/dx:
// coupling.model, fluid.model), and the outward push along the normals that the pressure closure and the
// Young-Laplace check compare with the fluid's pressure. Its energy is the fluid's share of the account.
class FluidPushTerm final : public ForceTerm {
 public:
  // increments: the fluid's quasi-static face (null for a fluid that has none), whose pressures' follower
  // stiffness this term adds.
  FluidPushTerm(FluidModel& fluid, const IncrementFluid* increments, const WallMesh& mesh)
      : fluid_(fluid), increments_(increments), mesh_(mesh) {}
  void add_forces(State& s, const ForceContext& c, Eigen::Matrix3Xd& wall_force, EnergyValues& power_W) override;
  void add_energy(const State& s, const ForceContext& c, EnergyValues& e) const override;
  bool add_stiffness(const State& s, const ForceContext& c, BlockStiffness& K) const override;
  Phase phase() const override { return Phase::WallFluid; }

  // At the last evaluation: the push on each wall particle (its share beyond the fluid's pressure, the
  // pressure coupling's backstop, too), and per cell the outward push / the cell's wall area.
  const Eigen::Matrix3Xd& on_wall() const { return on_wall_; }
  const Eigen::Matrix3Xd& backstop_on_wall() const { return backstop_on_wall_; }
  const std::vector<double>& cell_wall_pressure_Pa() const { return cell_wall_pressure_Pa_; }

 private:
  FluidModel& fluid_;
  const IncrementFluid* increments_;
  const WallMesh& mesh_;
  Eigen::Matrix3Xd on_wall_, backstop_on_wall_;
  std::vector<double> cell_wall_pressure_Pa_;
};

// Eq 22 in compression; the first contact of the top plate starts the plate strain, and the plate's work
// is its force times its speed.
class PlatesTerm final : public ForceTerm {
 public:
  PlatesTerm(const PlateLaw& law, const PlateMotion& motion) : law_(law), motion_(motion) {}
  void add_forces(State& s, const ForceContext& c, Eigen::Matrix3Xd& wall_force, EnergyValues& power_W) override;
  void add_energy(const State& s, const ForceContext& c, EnergyValues& e) const override;
  // k_pw along z on each particle a plate touches (plates.hpp).
  bool add_stiffness(const State& s, const ForceContext& c, BlockStiffness& K) const override;
  Phase phase() const override { return Phase::Plates; }

 private:
  const PlateLaw& law_;
  const PlateMotion& motion_;
};

}  // namespace cellsim
