#pragma once
// The quasi-static scheme (time.scheme = quasi_static; a cavity fluid: cavity_fluid.hpp): each step of
// time.dt_ns moves the loads (the plates, the drying ramp), integrates Eq 11 over it
// (backward Euler, one mass per cell), and relaxes the wall to equilibrium under them. The plates'
// speed and L_p keep their meaning: a step is dt of physical time, a sequence of equilibria.
//
// The relaxation minimises the potential (the wall's stored energy, plates and contacts included, less
// the fluid pressure's work along the volume's path in the increment) by Newton's method
// (newton_solver.hpp), preconditioned with the wall's stiffness, its cells' pressures and a tissue's
// contacts and lamella (newton_preconditioner.hpp). Equilibrium: the largest
// force on a wall particle below time.equilibrium_tolerance x its pressure load, max(P_T0, |P|) x the
// mean area a wall particle owns; the wall is then at rest (no kinetic energy). Each step's test and
// force evaluations are recorded (relaxation_residual, relaxation_evaluations).
//
// A step moves the loads with the wall that touches a plate keeping its overlap (a plate pushed at fixed
// particles would thrust them k_pw x its travel into its springs, and a soft wall relaxed from there
// dimples onto another branch); with time.predictor = secant the wall also moves by the last increment's
// motion, scaled, where that starts nearer equilibrium (increment_predictor.hpp). The energy account: the
// loads' work is the trapezoid of their powers at the two equilibria (plate work: its force x its speed;
// drive: the ramp of P_T and L_ref), Eq 11's water a jump per step (cavity_fluid.hpp), and the
// relaxation's loss the rest: what the wall released in snaps as it folded, and the trapezoid's error,
// which shrinks as dt^2.
// The wall's history (plastic sliders, the lamella's damage) follows the accepted points only.
// A lone cell's rigid rotation is held in compression (compression.cell_rotation, rotation_hold.hpp):
// its forces, moves and products are projected onto the hold, and its equilibrium is the projected one.
#include <cstdint>
#include <memory>
#include <optional>

#include <Eigen/Core>

#include "engine/fluid_model.hpp"
#include "engine/rotation_hold.hpp"
#include "core/state.hpp"
#include "engine/scheme.hpp"

namespace cellsim {

class Simulation;

struct Equilibrium {
  std::int64_t iterations = 0;
  double residual = 0;   // largest force on a wall particle / its pressure load, at the end
  bool converged = false;
  double loss_J = 0;     // energy the relaxation took out
  bool period_unbalanced = false;  // a periodic slab's period did not reach zero lateral stress
};

// No particle moves more than this share of the wall's mean bond rest length in one Newton step of a
// relaxation (newton_solver.hpp), unless the caller asks for less.
constexpr double kMaxMoveOverRestLength = 0.25;

// The relaxation's stiffness pattern and preconditioner (quasi_static.cpp). A caller that relaxes the same
// wall again and again (the scheme) keeps it, so its factor's ordering is found once, and again only where
// a tissue's neighbour list was rebuilt (the contacts the pattern holds moved on).
struct RelaxationStiffness;
struct RelaxationStiffnessDeleter {
  void operator()(RelaxationStiffness* stiffness) const;
};
using KeptStiffness = std::unique_ptr<RelaxationStiffness, RelaxationStiffnessDeleter>;

// Relaxes the wall of sim in place to equilibrium under its loads now, within max_iterations, in the
// increment its fluid's quasi-static face has begun; a held cell's on its hold (null: none); with the
// stiffness kept in `kept` where given (its pattern laid out there at the first call).
Equilibrium relax_wall(Simulation& sim, const IncrementFluid& increments, double tolerance,
                       std::int64_t max_iterations, const RotationHold* hold = nullptr,
                       double max_move_over_rest_length = kMaxMoveOverRestLength, KeptStiffness* kept = nullptr);

// The scheme: its steps; from the compression's start its hold on a lone cell's rotation
// (compression.cell_rotation = held); a periodic slab's lateral modulus, the secant of its period's last
// moves, from step to step.
class QuasiStaticScheme final : public Scheme {
 public:
  // Throws std::logic_error if sim's fluid has no quasi-static face (fluid_model.hpp).
  explicit QuasiStaticScheme(Simulation& sim);
  // One step. Throws NumericalFailure (naming the step) if the wall does not reach equilibrium within
  // time.relaxation_max_iterations, or a periodic slab's following period zero lateral stress within its moves.
  void step() override;
  void start_compression() override;
  const RotationHold* rotation_hold() const { return rotation_hold_ ? &*rotation_hold_ : nullptr; }

 private:
  struct Increment {
    Equilibrium eq;
    double loss_J = 0, loads_J = 0;  // the relaxation's loss, the loads' work over the increment
    double largest_move_m = 0;       // the farthest a wall particle moved in the relaxation (from the loads' move
                                     // on; measured only where move_limit_m_ > 0)
    Eigen::Matrix3Xd motion_m;       // the wall's motion over the increment (kept for the secant predictor)
  };
  Increment advance_by(double h_s, double max_move_over_rest_length);
  void start_at_secant(double h_s, const Eigen::Matrix3Xd& last_x, const Plates& plates_before);
  [[noreturn]] void fail(const Equilibrium& eq, double h_s) const;
  // The wall relaxed, and where a periodic slab's period follows (Simulation::period_follows), the period too.
  Equilibrium relax_wall_and_period(double tolerance, std::int64_t max_iterations, double max_move_over_rest_length);

  Simulation& sim_;
  IncrementFluid& increments_;
  std::optional<RotationHold> rotation_hold_;
  std::optional<Eigen::Vector2d> period_modulus_;  // Pa per unit strain, per axis
  double increment_s_;                             // the next increment's length (adaptive increments)
  double least_s_;                                 // the least increment (dt: one increment a step)
  double bond_m_;                                  // the wall's mean bond rest length (the mesh's, fixed)
  double move_limit_m_;                            // an increment's largest move before a cut (0: none)
  bool secant_;                                    // time.predictor = secant
  Eigen::Matrix3Xd last_motion_m_;                 // the last accepted increment's motion of the wall
  double last_motion_s_ = 0;                       // and its length (0: none yet in this stage)
  KeptStiffness stiffness_;                        // the relaxations' pattern and ordering, kept
};

}  // namespace cellsim
