// The quasi-static scheme (quasi_static.hpp).
#include "engine/quasi_static.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/errors.hpp"
#include "engine/increment_predictor.hpp"
#include "engine/newton_preconditioner.hpp"
#include "engine/newton_solver.hpp"
#include "engine/rotation_hold.hpp"
#include "engine/simulation.hpp"
#include "geometry/block_stiffness.hpp"
#include "physics/cell_contact.hpp"
#include "physics/plates.hpp"
#include "physics/wall_stiffness.hpp"

namespace cellsim {

// The relaxation's stiffness and its preconditioner, with the neighbour list build its pattern was laid
// out from (quasi_static.hpp: kept from one relaxation to the next).
struct RelaxationStiffness {
  explicit RelaxationStiffness(BlockStiffness pattern, long build) : stiffness(std::move(pattern)), list_build(build) {}
  BlockStiffness stiffness;
  long list_build;
  NewtonPreconditioner preconditioner;
};

void RelaxationStiffnessDeleter::operator()(RelaxationStiffness* stiffness) const { delete stiffness; }

namespace {

// The springs' stiffness in the preconditioner gets kStiffnessShift_N_m on its diagonal (the free motions
// between frictionless plates).
constexpr double kStiffnessShift_N_m = 1e-2;
constexpr double kLeastPressureLoad_Pa = 1e3;  // the load scale of a cell without turgor

double mean_rest_length_m(const Simulation& sim) {
  double sum_m = 0;
  for (double l0 : sim.mesh().rest_length_m) sum_m += l0;
  return sum_m / static_cast<double>(sim.mesh().rest_length_m.size());
}

// The load scale: max(P_T0, the largest |P| of a cell).
double load_pressure_Pa(const Simulation& sim) {
  double pressure = std::max(sim.params().turgor_Pa, kLeastPressureLoad_Pa);
  for (double P : sim.cell_mean_fluid_pressure_Pa()) pressure = std::max(pressure, std::abs(P));
  return pressure;
}

// What a wall particle carries: the load scale x the mean area a wall particle owns.
double pressure_load_N(const Simulation& sim) {
  return load_pressure_Pa(sim) * sim.surface().area_m2 / static_cast<double>(sim.state().wall.size());
}

// What the wall's laws write as they are evaluated (the plastic sliders, the middle lamella's damage): the
// relaxation's probes and rejected trials must leave none of it, so it is kept at the last accepted point
// and put back before every evaluation.
struct WallHistory {
  std::vector<double> plastic_elongation_m, lamella_peak_opening_m;
  std::vector<char> lamella_intact;
  double plastic_loss_J = 0;

  static WallHistory of(const State& s) {
    return {s.bond_plastic_elongation_m, s.lamella_peak_opening_m, s.lamella_intact, s.energy.integral[kPlasticLoss]};
  }
  void restore(State& s) const {
    s.bond_plastic_elongation_m = plastic_elongation_m;
    s.lamella_peak_opening_m = lamella_peak_opening_m;
    s.lamella_intact = lamella_intact;
    s.energy.integral[kPlasticLoss] = plastic_loss_J;
  }
};

const Eigen::Matrix3Xd& forces_at(Simulation& sim, const Eigen::Matrix3Xd& x, const WallHistory& history) {
  State& s = sim.mutable_state();
  s.wall.x = x;
  history.restore(s);
  sim.refresh_rates();
  return sim.wall_force();
}

// The forces that can move the wall: a held cell's (rotation_hold.hpp) less the hold's reaction.
void drop_held_directions(const RotationHold* hold, Eigen::Ref<Eigen::VectorXd> v) {
  if (hold) hold->project(v);
}

// What the relaxation descends, the potential, at the state's positions and rates now: the stored energy of
// the wall (springs, bending, plates, contacts) less the work of the fluid's pressure along the volume's
// path in this increment, which is the fluid's potential there (cavity_fluid.hpp; its mass is slaved to V,
// so M e(M/V) at the step's mass is not); and what the wall's history took (plastic flow, the lamella's
// damage) up to here.
void potential_now(Simulation& sim, const IncrementFluid& increments, double& potential_J, double& dissipated_J) {
  const EnergyValues e = sim.energy_terms_now();
  potential_J = stored_energy_J(e) - e[kInternal] - increments.increment_work_J(sim.fluid_context());
  dissipated_J = e[kPlasticLoss] + e[kLamellaLoss];
}

// Whether a tissue's contacts and lamella join its cells (a lone cell has neither).
bool cells_joined(const Simulation& sim) { return sim.cells().count() > 1; }

// The pattern of the relaxation's stiffness: the wall's bonds, and in a tissue the lamella bonds and the
// wall pairs of different cells the neighbour list holds at its start (the contacts it may make; the
// list's skin covers a relaxation's moves unless it is rebuilt within it).
BlockStiffness stiffness_pattern(const Simulation& sim) {
  if (!cells_joined(sim)) return BlockStiffness(sim.state().wall.x.cols(), sim.mesh().bonds);
  std::vector<std::array<int, 2>> pairs = sim.mesh().bonds;
  for (const LamellaBond& bond : sim.lamella()) pairs.push_back({bond.a, bond.b});
  const PairList& wall_wall = sim.neighbours().wall_wall();
  for (int k = 0; k < wall_wall.rows(); ++k)
    for (int q = wall_wall.offset[static_cast<std::size_t>(k)]; q < wall_wall.offset[static_cast<std::size_t>(k) + 1]; ++q)
      pairs.push_back({k, wall_wall.index[static_cast<std::size_t>(q)]});
  return BlockStiffness(sim.state().wall.x.cols(), pairs);
}

// The wall's stiffness at x for the preconditioner (newton_preconditioner.hpp): the force field's terms'
// (force_field.hpp: the springs, the bending's Gauss-Newton part on the bonds, a tissue's contacts and
// lamella, the cells' pressures' follower stiffness, the plates), kStiffnessShift_N_m on the diagonal, and
// the cells' volume springs. Where the neighbour list was rebuilt since the pattern was laid out, a
// tissue's pattern is laid out again from it (the contacts it may make moved on), its ordering found anew.
void factor_at(Simulation& sim, const IncrementFluid& increments, const Eigen::Matrix3Xd& x, const WallHistory& history,
               RelaxationStiffness& at) {
  forces_at(sim, x, history);  // the cells' pressures and the surface at x (the last evaluation may be a probe's)
  if (cells_joined(sim) && sim.neighbours().builds() != at.list_build) {
    at.stiffness = stiffness_pattern(sim);
    at.list_build = sim.neighbours().builds();
    at.preconditioner.forget_ordering();
  }
  BlockStiffness& stiffness = at.stiffness;
  sim.force_field().stiffness(sim.state(), sim.force_context(), stiffness);
  const Eigen::Matrix3d shift = kStiffnessShift_N_m * Eigen::Matrix3d::Identity();
  for (int k = 0; k < static_cast<int>(x.cols()); ++k) stiffness.add(k, k, shift);
  at.preconditioner.factor(stiffness.matrix(), increments.volume_gradients(sim.surface()), sim.cells(),
                           increments.volume_stiffness_Pa_m3(sim.eos()), cells_joined(sim));
}

// The largest force on a wall particle over its pressure load, at the state's positions and rates now (on
// the hold where one holds the cell).
double force_over_load(const Simulation& sim, const RotationHold* hold) {
  Eigen::Matrix3Xd force = sim.wall_force();
  if (hold) hold->project(force);
  return std::sqrt(force.colwise().squaredNorm().maxCoeff()) / pressure_load_N(sim);
}

// The relaxation as a problem of newton_solver.hpp: a point is the wall at x, its force the wall's forces
// on the rotation hold, its potential the one above, its load the pressure load there. Every evaluation
// starts from the history of the last accepted point.
class WallRelaxation final : public NewtonProblem {
 public:
  WallRelaxation(Simulation& sim, const IncrementFluid& increments, const RotationHold* hold,
                 KeptStiffness& stiffness)
      : sim_(sim), increments_(increments), hold_(hold), history_(WallHistory::of(sim.state())),
        stiffness_(stiffness) {}

  Point evaluate(const Eigen::Matrix3Xd& x) override {
    Point point{x, forces_at(sim_, x, history_)};
    if (hold_) hold_->project(point.force);
    potential_now(sim_, increments_, point.potential_J, point.dissipated_J);
    point.load_N = pressure_load_N(sim_);
    return point;
  }
  const Eigen::Matrix3Xd& unconstrained_force(const Eigen::Matrix3Xd& x) override { return forces_at(sim_, x, history_); }
  void accept_last() override { history_ = WallHistory::of(sim_.state()); }
  // The pattern is laid out at the first factoring (of the first relaxation where it is kept), from the
  // lists the first evaluation left.
  void factor_at(const Point& point) override {
    if (!stiffness_)
      stiffness_.reset(new RelaxationStiffness(stiffness_pattern(sim_), sim_.neighbours().builds()));
    cellsim::factor_at(sim_, increments_, point.x, history_, *stiffness_);
  }
  Eigen::VectorXd precondition(const Eigen::VectorXd& r) const override { return stiffness_->preconditioner.solve(r); }
  void project(Eigen::Ref<Eigen::VectorXd> v) const override { drop_held_directions(hold_, v); }
  // The state and rates at x, from the accepted history (the probes and trials moved the particles).
  void leave_at(const Eigen::Matrix3Xd& x) { forces_at(sim_, x, history_); }

 private:
  Simulation& sim_;
  const IncrementFluid& increments_;
  const RotationHold* hold_;
  WallHistory history_;
  KeptStiffness& stiffness_;
};

}  // namespace

// Newton's method (newton_solver.hpp) on the relaxation above, no particle moving more than
// max_move_over_rest_length of a bond's mean rest length in one step. The loss is the fall of the potential
// from start to end, less what the wall's history dissipated on the way (plastic_loss_J, lamella_loss_J).
Equilibrium relax_wall(Simulation& sim, const IncrementFluid& increments, double tolerance, std::int64_t max_iterations,
                       const RotationHold* hold, double max_move_over_rest_length, KeptStiffness* kept) {
  State& s = sim.mutable_state();
  s.wall.v.setZero();
  const double max_move_m = max_move_over_rest_length * mean_rest_length_m(sim);
  KeptStiffness own;
  WallRelaxation relaxation(sim, increments, hold, kept ? *kept : own);
  const NewtonResult result = minimise(relaxation, s.wall.x, {tolerance, max_iterations, max_move_m});
  relaxation.leave_at(result.end.x);
  Equilibrium eq;
  eq.iterations = result.evaluations;
  eq.residual = result.residual;
  eq.converged = result.converged;
  eq.loss_J = (result.start.potential_J + result.start.dissipated_J) - (result.end.potential_J + result.end.dissipated_J);
  return eq;
}

namespace {

// A periodic slab's period in the quasi-static steps: its first strain is the lateral stress over
// kFirstLateralModulus x the load scale, later ones a secant per axis, carried from step to step; no more
// than kLargestPeriodMove a move, kMaxPeriodMoves moves a step.
constexpr double kFirstLateralModulus = 10, kLargestPeriodMove = 1e-2;
constexpr int kMaxPeriodMoves = 40;
// Adaptive increments (time.min_increment_ns below time.dt_ns): a cut keeps a quarter of the increment, as
// Abaqus' automatic increments do; an easy one doubles the next; a rest below kLeastRest of dt joins the increment.
// An increment at the least length is relaxed with Newton steps of at most kSnapMoveOverRestLength of the
// mean rest length: a snap there then descends close to the wall's path of steepest descent, and lands on
// the branch that path reaches, not on one a long step jumps to (the branch after a fold would otherwise
// depend on where the plate's step put its start).
constexpr double kCutTo = 0.25, kGrowBy = 2.0, kLeastRest = 1e-9, kSnapMoveOverRestLength = 0.02;

// The wall relaxed, and where a periodic slab's period follows (Simulation::period_follows), the period
// too: staggered, the wall relaxed at a fixed period, then the period strained (the cells moving with it
// whole) by a secant step on its lateral stress, until that stress is within the tolerance of the load
// scale at an equilibrium of the wall. The lateral stress of the pairs across the period is exact there
// (periodic_slab.hpp). The period does no work on anything outside: what its moves change of the potential
// is the relaxation's (its loss counts the fall over every relaxation and move).
}  // namespace

Equilibrium QuasiStaticScheme::relax_wall_and_period(double tolerance, std::int64_t max_iterations,
                                                      double max_move_over_rest_length) {
  Simulation& sim = sim_;
  const RotationHold* hold = rotation_hold();
  Equilibrium eq =
      relax_wall(sim, increments_, tolerance, max_iterations, hold, max_move_over_rest_length, &stiffness_);
  if (!eq.converged || !sim.period_follows()) return eq;
  const State& s = sim.state();
  const auto lateral_stress = [&] { return Eigen::Vector2d(s.lateral_stress_x_Pa, s.lateral_stress_y_Pa); };
  Eigen::Vector2d stress = lateral_stress();
  if (!period_modulus_) period_modulus_ = Eigen::Vector2d::Constant(kFirstLateralModulus * load_pressure_Pa(sim));
  Eigen::Vector2d& modulus = *period_modulus_;
  for (int move = 0;; ++move) {
    if (stress.cwiseAbs().maxCoeff() <= tolerance * load_pressure_Pa(sim)) return eq;
    if (move == kMaxPeriodMoves) {
      eq.converged = false;
      eq.period_unbalanced = true;
      return eq;
    }
    // Tension (positive) asks for a smaller period, and the tension grows with the period: so the step is
    // -stress / modulus, the modulus d(stress)/d(strain) > 0.
    const Eigen::Vector2d by = (-stress.array() / modulus.array()).cwiseMax(-kLargestPeriodMove).cwiseMin(kLargestPeriodMove);
    double before_J = 0, dissipated_before_J = 0, after_J = 0, dissipated_after_J = 0;
    potential_now(sim, increments_, before_J, dissipated_before_J);
    sim.strain_period(by);
    sim.refresh_rates();
    potential_now(sim, increments_, after_J, dissipated_after_J);
    const Equilibrium next = relax_wall(sim, increments_, tolerance, max_iterations - eq.iterations, hold,
                                        max_move_over_rest_length, &stiffness_);
    eq.iterations += next.iterations;
    eq.residual = next.residual;
    eq.converged = next.converged;
    eq.loss_J += next.loss_J - ((after_J + dissipated_after_J) - (before_J + dissipated_before_J));
    if (!eq.converged) return eq;
    const Eigen::Vector2d stress_now = lateral_stress();
    for (int axis = 0; axis < 2; ++axis) {
      const double secant = (stress_now[axis] - stress[axis]) / by[axis];
      if (by[axis] != 0 && std::isfinite(secant) && secant > 0) modulus[axis] = secant;
    }
    stress = stress_now;
  }
}

// The scheme's fluid must have increments: the case's reader refuses time.scheme = quasi_static for SPH.
IncrementFluid& increments_of(Simulation& sim) {
  IncrementFluid* increments = sim.fluid_increments();
  if (!increments) throw std::logic_error("the quasi-static scheme needs a fluid with increments (fluid_model.hpp)");
  return *increments;
}

QuasiStaticScheme::QuasiStaticScheme(Simulation& sim)
    : sim_(sim),
      increments_(increments_of(sim)),
      increment_s_(sim.params().dt_s),
      least_s_(std::min(sim.params().min_increment_s.value_or(sim.params().dt_s), sim.params().dt_s)),
      bond_m_(mean_rest_length_m(sim)),
      move_limit_m_(least_s_ < sim.params().dt_s ? sim.params().increment_move_over_spacing * bond_m_ : 0),
      secant_(sim.params().increment_predictor == kPredictorSecant) {}

void QuasiStaticScheme::start_compression() {
  sim_.start_compression();
  last_motion_s_ = 0;  // the drying's motion does not predict the plates'
  if (sim_.params().cell_rotation == kRotationHeld) rotation_hold_.emplace(sim_.state().wall.x);
}

// The secant predictor (time.predictor = secant): the relaxation starts from the last equilibrium moved by
// the last increment's motion, scaled to h_s (each particle keeping its plate overlap, on the hold), where
// the largest force there is below the plain start's; otherwise from the plain start, as before. It is part
// of the loads' move: the stored energy's jump and the relaxation's loss are counted from where it starts.
void QuasiStaticScheme::start_at_secant(double h_s, const Eigen::Matrix3Xd& last_x, const Plates& plates_before) {
  Simulation& sim = sim_;
  State& s = sim.mutable_state();
  const RotationHold* hold = rotation_hold();
  const WallHistory history = WallHistory::of(s);  // the secant's evaluation may write the wall's history
  const double plain = force_over_load(sim, hold);
  Eigen::Matrix3Xd plain_x = s.wall.x;
  s.wall.x = last_x + (h_s / last_motion_s_) * last_motion_m_;
  keep_plate_overlaps(s.wall.x, last_x, sim.plate_law(), plates_before, s.plates);
  if (hold) hold->project(s.wall.x);
  sim.refresh_rates();
  if (force_over_load(sim, hold) < plain) return;
  s.wall.x = std::move(plain_x);
  history.restore(s);
  sim.refresh_rates();
}

// One increment of h_s: the loads move (the plates, the drying ramp), the wall touching a plate with it
// (increment_predictor.hpp) and, with the secant predictor, the wall by its last motion; Eq 11 is
// integrated over it and the wall relaxed. The loads' work over it is the trapezoid of their powers at the
// two equilibria (the plate's force x its speed, the ramp's rate of the stored energy: the rates of the
// last evaluation are the start's); the relaxation's loss closes the account from the stored energy's jump
// over the move.
QuasiStaticScheme::Increment QuasiStaticScheme::advance_by(double h_s, double max_move_over_rest_length) {
  Simulation& sim = sim_;
  const RotationHold* hold = rotation_hold();
  const Params& p = sim.params();
  State& s = sim.mutable_state();
  const EnergyValues power_at_start_W = sim.power_W();
  const EnergyValues stored_before = sim.energy_terms_now();
  const Plates plates_before = s.plates;
  std::optional<Eigen::Matrix3Xd> last_x;  // the last equilibrium, kept where the secant predictor reads it
  if (secant_) last_x = s.wall.x;
  sim.advance_loads(h_s);
  keep_plate_overlaps(s.wall.x, s.wall.x, sim.plate_law(), plates_before, s.plates);
  if (hold) hold->project(s.wall.x);  // back onto C = 0: the least move
  sim.refresh_rates();  // the surface at the particles now (a periodic slab's period moved them)
  if (last_x && last_motion_s_ > 0) start_at_secant(h_s, *last_x, plates_before);
  const EnergyValues stored_at_start = sim.energy_terms_now();
  const double jump_J = stored_energy_J(stored_at_start) - stored_energy_J(stored_before);
  // The move may already have made the wall's history dissipate (a slider yielding): the history counts
  // it (plastic_loss_J, lamella_loss_J), so the relaxation's loss must not count it again.
  const double dissipated_in_move_J = stored_at_start[kPlasticLoss] + stored_at_start[kLamellaLoss] -
                                      stored_before[kPlasticLoss] - stored_before[kLamellaLoss];

  increments_.begin_increment(s, sim.fluid_context(), h_s);
  std::optional<Eigen::Matrix3Xd> moved_x;  // kept only where the move limit reads the relaxation's move
  if (move_limit_m_ > 0) moved_x = s.wall.x;
  Increment done;
  done.eq = relax_wall_and_period(p.equilibrium_tolerance, p.relaxation_max_iterations, max_move_over_rest_length);
  if (moved_x) done.largest_move_m = (s.wall.x - *moved_x).colwise().norm().maxCoeff();
  if (last_x) done.motion_m = s.wall.x - *last_x;
  const EnergyValues& power_at_end_W = sim.power_W();
  for (EnergyTermId load : {kPlateWork, kDrive}) {
    const double work_J = 0.5 * (power_at_start_W[load] + power_at_end_W[load]) * h_s;
    s.energy.integral[load] += work_J;
    done.loads_J += work_J;
  }
  // The relaxation took the potential down from the start's jump; what the loads did not put in of that
  // jump it dissipated too (the account: stored energy now - before = loads' work - losses).
  done.loss_J = done.eq.loss_J + done.loads_J - jump_J - dissipated_in_move_J;
  s.energy.integral[kRelaxationLoss] += done.loss_J;
  s.energy.integral[kMassTransfer] += increments_.end_increment(s, sim.fluid_context());
  s.relaxation_residual = done.eq.residual;
  return done;
}

// A step of time.dt_ns in increments: one, unless time.min_increment_ns below it lets the scheme cut an
// increment to kCutTo of itself where its relaxation fails, releases more than time.snap_loss_share of
// the loads' work over it (a snap; and more than the energy a relaxation resolves, snap_floor_J: at rest the
// loads do no work), or moves a wall particle farther than time.increment_move_over_spacing of a bond (a
// jump to another branch that releases little); and grow it kGrowBy after an easy one (a quarter of that
// share at most, half that move), back up to dt. The state is recorded once a step, at the asked strain.
void QuasiStaticScheme::step() {
  const Params& p = sim_.params();
  const double least_s = least_s_, move_limit_m = move_limit_m_;
  const bool adaptive = least_s < p.dt_s;
  // The energy one relaxation resolves: its tolerance's force on a particle over a bond's rest length.
  const double snap_floor_J = p.equilibrium_tolerance * pressure_load_N(sim_) * bond_m_;
  double left_s = p.dt_s;
  std::int64_t evaluations = 0;
  while (left_s > 0) {
    double h_s = std::min(increment_s_, left_s);
    if (left_s - h_s < kLeastRest * p.dt_s) h_s = left_s;  // no sliver of round-off left over
    const bool at_least = adaptive && h_s <= least_s * (1 + kLeastRest);
    std::optional<State> before;
    if (adaptive) before = sim_.state();
    Increment done = advance_by(h_s, at_least ? kSnapMoveOverRestLength : kMaxMoveOverRestLength);
    evaluations += done.eq.iterations;
    const bool failed = !done.eq.converged;
    const bool snapped = done.loss_J > std::max(p.snap_loss_share * std::abs(done.loads_J), snap_floor_J);
    const bool jumped = move_limit_m > 0 && done.largest_move_m > move_limit_m;
    if (adaptive && (failed || snapped || jumped) && !at_least) {
      sim_.restore(*before);
      increment_s_ = std::max(kCutTo * h_s, least_s);
      continue;
    }
    if (failed) fail(done.eq, h_s);
    left_s -= h_s;
    if (secant_) {
      last_motion_m_ = secant_motion(done.motion_m);
      last_motion_s_ = h_s;
    }
    const bool easy = done.loss_J <= 0.25 * p.snap_loss_share * std::abs(done.loads_J) &&
                      (move_limit_m == 0 || done.largest_move_m <= move_limit_m / kGrowBy);
    if (adaptive && easy) increment_s_ = std::min(kGrowBy * h_s, p.dt_s);
  }
  sim_.mutable_state().relaxation_evaluations = static_cast<double>(evaluations);
  sim_.refresh_rates();  // the rates at the increment's masses
  sim_.finish_step();
}

// Throws NumericalFailure naming the step, its strain, and what could let it through.
void QuasiStaticScheme::fail(const Equilibrium& eq, double h_s) const {
  const Params& p = sim_.params();
  const State& s = sim_.state();
  std::ostringstream msg;
  msg << "step " << s.step + 1 << " (t = " << s.time_s * 1e6 << " us, "
      << (s.stage == Stage::Drying ? "drying" : "compression, strain " + std::to_string(sim_.nominal_strain())) << ")";
  if (h_s < p.dt_s) msg << ", in an increment of " << h_s * 1e9 << " ns (time.min_increment_ns = "
                        << p.min_increment_s.value_or(p.dt_s) * 1e9 << ")";
  if (eq.period_unbalanced)
    msg << ": the periodic slab's period did not reach zero lateral stress within " << kMaxPeriodMoves
        << " moves (lateral stress " << s.lateral_stress_x_Pa / 1e3 << " / " << s.lateral_stress_y_Pa / 1e3
        << " kPa, time.equilibrium_tolerance = " << p.equilibrium_tolerance << " of the load); give a smaller time.dt_ns";
  else
    msg << ": the wall did not reach equilibrium within time.relaxation_max_iterations = " << p.relaxation_max_iterations
        << " (largest force " << eq.residual << " of its pressure load, time.equilibrium_tolerance = "
        << p.equilibrium_tolerance << "); give more iterations, a looser tolerance or a smaller time.dt_ns";
  throw NumericalFailure(msg.str());
}

}  // namespace cellsim
