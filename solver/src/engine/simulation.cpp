// The step of a run (simulation.hpp): the wall's forces, the contacts between cells and the plates here,
// the fluid's through its model (fluid_model.hpp), in the order of the model.
#include "engine/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/errors.hpp"
#include "geometry/containment.hpp"
#include "engine/cavity_fluid.hpp"
#include "engine/leapfrog.hpp"
#include "engine/periodic_slab.hpp"
#include "engine/sph_fluid.hpp"
#include "engine/step_checks.hpp"
#include "engine/strain_gauge.hpp"
#include "geometry/hull.hpp"
#include "parallel/cell_blocks.hpp"
#include "parallel/threads.hpp"
#include "physics/drying.hpp"
#include "physics/plates.hpp"

namespace cellsim {
namespace {

// Neighbour-list skin as a fraction of h0: lists are rebuilt about every skin / (2 |v|max) of time.
constexpr double kSkinOverH0 = 0.15;

// The case's fluid model (fluid.model) with its faces (fluid_model.hpp): SPH, with either coupling
// (coupling.model), or the closed cell of one pressure.
Fluid make_fluid(const Params& p, const CellRanges& cells, const PropertyFactors& factors) {
  if (p.fluid_model == kCavityFluid) return Fluid::of(std::make_unique<CavityFluid>(p));
  return Fluid::of(std::make_unique<SphFluid>(p, cells, factors));
}

// The seeded factors of the heterogeneous properties (heterogeneity.hpp), from the tissue as built.
PropertyFactors property_factors(const Params& p, const Tissue& tissue) {
  const HeterogeneityLaw law{p.heterogeneity_seed, p.G_cv, p.thickness_cv, p.viscosity_cv, p.correlation_length_m};
  return draw_property_factors(law, tissue.wall_x, tissue.mesh, tissue.cells.cell_of_wall(), tissue.cells.count());
}

}  // namespace

Simulation::Simulation(const Params& p, const Tissue& tissue) : Simulation(p, tissue, property_factors(p, tissue)) {}

Simulation::Simulation(const Params& p, const Tissue& tissue, const PropertyFactors& factors)
    : p_(p),
      mesh_(tissue.mesh),
      cells_(tissue.cells),
      lamella_(tissue.lamella),
      contact_law_{p.wall_gap_m.value_or(p.thickness_m), p.contact_stiffness_N_m,
                   make_lamella_law(p, tissue.wall_particle_area_m2)},
      bending_(mesh_, p.bending_stiffness_J),
      neighbours_(kSkinOverH0 * *p.h0_m),
      fluid_(make_fluid(p, tissue.cells, factors)),
      plate_law_(cellsim::plate_law(p)),
      plate_motion_(plate_motion(p)),
      bond_law_(make_bond_law(p, factors)),
      Lp_m_per_s_Pa_(p.drying_Lp_m_per_s_Pa) {
  lay_out_force_field();
  const WallSurface built = wall_surface(tissue.wall_x, mesh_);
  fluid_.model->fill(s_, tissue, built);
  s_.wall.x = tissue.wall_x;
  s_.wall.v = Eigen::Matrix3Xd::Zero(3, tissue.wall_x.cols());
  s_.wall.mass_kg = tissue.wall_mass_kg;
  s_.box = tissue.box;
  s_.lamella_intact.assign(lamella_.size(), 1);
  s_.lamella_peak_opening_m.assign(lamella_.size(), 0.0);
  s_.bond_plastic_elongation_m.assign(mesh_.bonds.size(), 0.0);
  if (cells_.count() > 1)
    neighbours_.set_cells(cells_.cell_of_fluid(), cells_.cell_of_wall(), contact_law_.gap_m);
  s_.smoothing_length_m = *p.h0_m;
  s_.initial_fluid_mass_kg = fluid_.model->mass_kg(s_);
  s_.plates.first_contact_top_z_m = std::nan("");
  const double wall_limit_s =
      wall_spring_dt_limit_s(mesh_, bond_law_, lamella_, p_, tissue.wall_mass_kg, tissue.wall_x.cols());
  // Known before the first step: bad input, not a blow-up (a quasi-static step is no leapfrog step).
  if (p_.time_scheme == kDynamic && p_.dt_s > wall_limit_s) {
    std::ostringstream msg;
    msg << "time.dt_ns = " << p_.dt_s * 1e9 << ": exceeds the wall-spring stability limit of this case ("
        << wall_limit_s * 1e9 << " ns, from its stiffest wall particle); use a smaller time step";
    throw InputError(msg.str());
  }
  // D0 of Eq 6: the initial mesh's own equivalent diameter, so h = h0 exactly at t = 0.
  s_.reference_diameter_m = equivalent_diameter_m(built.volume_m3);
  compute_rates();
  start_energy_account();
}

// The reference makes the residual zero now: the stored energy less what the state's own losses hold
// already (a tissue's lamella damaged in the settle), which the account does not count as put in since t = 0.
void Simulation::start_energy_account() {
  s_.energy = EnergyFlows{};
  s_.energy.initial_J = energy_residual_J(energy_terms_now(), 0.0);
}

// The terms in the order their forces are summed: the wall's own, the contacts between cells (a tissue's),
// the fluid's push, the plates.
void Simulation::lay_out_force_field() {
  field_.add(std::make_unique<WallSpringsTerm>(mesh_, bond_law_, *fluid_.model, p_.turgor_Pa, p_.dryness,
                                               p_.contraction_ratio));
  field_.add(std::make_unique<BendingTerm>(bending_));
  if (cells_.count() > 1) field_.add(std::make_unique<CellContactTerm>(lamella_, contact_law_));
  auto push = std::make_unique<FluidPushTerm>(*fluid_.model, fluid_.increments, mesh_);
  push_ = push.get();
  field_.add(std::move(push));
  field_.add(std::make_unique<PlatesTerm>(plate_law_, plate_motion_));
}

EnergyValues Simulation::energy_terms_now() const { return field_.energy(s_, force_context()); }

ForceContext Simulation::force_context() const {
  const double ramp_rate = s_.stage == Stage::Drying ? drying::smoothstep_ramp_rate(s_.time_s, p_.ramp_time_s) : 0.0;
  return {fluid_context(), contraction_ramp(), ramp_rate, false};
}

const Eigen::Matrix3Xd& Simulation::fluid_force() const {
  static const Eigen::Matrix3Xd none(3, 0);
  return fluid_.particles ? fluid_.particles->particle_force() : none;
}

FluidContext Simulation::fluid_context() const {
  return {surface_, neighbours_, cells_, eos(), Lp_m_per_s_Pa_, threads_};
}

double Simulation::contraction_ramp() const {
  return s_.stage == Stage::Drying ? drying::smoothstep_ramp(s_.time_s, p_.ramp_time_s) : 1.0;
}

void Simulation::set_threads(int threads) {
  check_thread_count(threads);
  threads_ = threads;
}

double Simulation::turgor_Pa() const {
  if (s_.stage != Stage::Drying) return p_.turgor_Pa * p_.dryness;
  return drying::turgor_Pa(p_.turgor_Pa, p_.dryness, drying::smoothstep_ramp(s_.time_s, p_.ramp_time_s));
}

EquationOfState Simulation::eos() const {
  return {turgor_Pa(), p_.bulk_modulus_Pa, p_.fluid_density_kg_m3, p_.eos_exponent};
}

void Simulation::step() {
  timer_.start();
  check_time_step();
  kick(0.5 * p_.dt_s);
  drift(p_.dt_s);
  follow_lateral_stress(p_.dt_s);
  timer_.lap(Phase::Integration);
  ParticleFluid* particles = fluid_.particles;
  compute_rates(density_in_drift() ? p_.dt_s : 0.0);
  kick(0.5 * p_.dt_s);
  if (particles && s_.stage == Stage::Drying)
    particles->apply_drying_closure(s_, fluid_context(), cell_wall_pressure_Pa());
  if (particles && s_.stage == Stage::Compression) particles->apply_compression_closure(s_, fluid_context());
  finish_step();
}

void Simulation::finish_step() {
  // compression.unload_at_strain: once the cell reaches it, the top plate turns back (plate_motion.hpp).
  if (awaits_turn(s_.plates, plate_motion_) && nominal_strain() >= *plate_motion_.turn_at_strain)
    turn_top_plate(s_.plates, s_.time_s);
  ++s_.step;
  ++s_.stage_step;
  check_state();
  timer_.lap(Phase::Integration);
}

void Simulation::advance_loads(double dt) { advance_clock(dt); }

bool Simulation::period_follows() const {
  return s_.box.periodic() && (s_.stage != Stage::Compression || p_.compression_lateral == kLateralUnconfined);
}

void Simulation::strain_period(const Eigen::Vector2d& strain) {
  moved_since_lists_m_ += cellsim::strain_period(s_, cells_, strain);
}

// Forces and rates at the current positions, in the order of the model.
void Simulation::compute_rates(double density_step_s) {
  update_geometry();
  timer_.lap(Phase::Geometry);
  update_neighbours();
  timer_.lap(Phase::Neighbours);
  ForceContext now = force_context();  // the positions' surface and lists, the clock's EOS and ramp
  now.pairs_fresh = density_step_s > 0;
  if (now.pairs_fresh) fluid_.particles->advance_density(s_, now.fluid, density_step_s, energy_power_W_);
  timer_.lap(Phase::DensityDrift);
  fluid_.model->compute_forces(s_, now.fluid, now.pairs_fresh, energy_power_W_);
  timer_.lap(Phase::FluidPairs);
  fluid_.model->transfer_mass(s_, now.fluid, energy_power_W_);
  timer_.lap(Phase::MassTransfer);
  field_.forces(s_, now, wall_force_, energy_power_W_, timer_);
}

// The wall surface (area, volume, normals) and the smoothing length of Eq 6: h = (D / D0) h0, D of
// the volume of all cells (one h for a tissue: model.md §10). A wall that encloses no volume has
// collapsed or turned inside out: Eq 6 has no D, so the run stops here (a non-finite volume comes from
// a non-finite position, which check_state names).
void Simulation::update_geometry() {
  surface_.update(s_.wall.x, mesh_, threads_);
  if (surface_.volume_m3 <= 0) {
    std::ostringstream msg;
    msg << where() << ": the wall encloses a volume of " << surface_.volume_m3
        << " m^3 (it must be positive: the wall has collapsed or turned inside out)";
    throw NumericalFailure(msg.str());
  }
  s_.smoothing_length_m = equivalent_diameter_m(surface_.volume_m3) / s_.reference_diameter_m * *p_.h0_m;
  fluid_wall_cutoff_m_ = fluid_.model->follow_smoothing_length(s_.smoothing_length_m);
}

void Simulation::update_neighbours() {
  neighbours_.update(s_.fluid.x, s_.wall.x, 2.0 * s_.smoothing_length_m, fluid_wall_cutoff_m_, threads_, moved_since_lists_m_,
                     s_.box);  // the period of the moment: a dried slab's has shrunk from the one built
  moved_since_lists_m_ = 0;
}

// A periodic slab's period follows zero lateral stress in drying, and in compression if unconfined
// (periodic_slab.hpp); the lists learn how far the move can have taken a pair (and read the period at their next build).
void Simulation::follow_lateral_stress(double dt) {
  if (!period_follows()) return;
  try {
    moved_since_lists_m_ +=
        cellsim::follow_lateral_stress(s_, cells_, p_.period_viscosity_Pa_s, dt, cell_height_m(s_.wall.x));
  } catch (const NumericalFailure& e) {
    throw NumericalFailure(where() + ": " + e.what());
  }
}

void Simulation::kick(double half_dt) {
  add_half_kick(energy_power_W_, half_dt, !density_in_drift(), s_.energy);
  fluid_.leapfrog->kick(s_, half_dt, threads_);
  for_blocks(threads_, s_.wall.size(), [&](Eigen::Index begin, Eigen::Index end) {
    add_scaled(half_dt / s_.wall.mass_kg, wall_force_, begin, end, s_.wall.v);
  });
}

void Simulation::drift(double dt) {
  const double fluid_v2 = fluid_.particles ? fluid_.particles->drift(s_, dt, threads_) : 0.0;
  const double wall_v2 = reduce_blocks<double>(
      threads_, s_.wall.size(),
      [&](Eigen::Index begin, Eigen::Index end) { return drift_columns(dt, s_.wall.v, begin, end, s_.wall.x); },
      [](double a, double b) { return std::max(a, b); });
  moved_since_lists_m_ += dt * std::sqrt(std::max(fluid_v2, wall_v2));
  advance_clock(dt);
}

void Simulation::advance_clock(double dt) {
  s_.time_s += dt;
  Plates& plates = s_.plates;
  if (plates.active) plates.top_z_m = top_plate_z_m(plates, plate_motion_, s_.time_s);
}

void Simulation::start_at_rest() {
  s_.fluid.v.setZero();
  s_.wall.v.setZero();
  s_.time_s = 0;
  s_.step = s_.stage_step = 0;
  s_.initial_fluid_mass_kg = fluid_.model->mass_kg(s_);
  s_.reference_diameter_m = equivalent_diameter_m(surface_.volume_m3);
  neighbours_.invalidate();
  compute_rates();
  start_energy_account();
}

std::string Simulation::where() const {
  std::ostringstream s;
  s << "step " << s_.step << " (t = " << s_.time_s * 1e6 << " us, "
    << (s_.stage == Stage::Drying ? "drying" : "compression") << ")";
  return s.str();
}

void Simulation::check_state() const {
  const std::string unsound = unsound_particle(s_, threads_);
  if (!unsound.empty()) throw NumericalFailure(where() + ": " + unsound);
}

// model.md §7: dt must stay under the fluid's limits (the constant wall-spring limit is checked once, in
// the constructor).
void Simulation::check_time_step() const {
  const std::string violation = fluid_.leapfrog->time_step_violation(s_, fluid_context());
  if (!violation.empty()) throw NumericalFailure(where() + ": " + violation);
}

void Simulation::check_containment() const {
  const auto at = [](const Eigen::Vector3d& x) {
    std::ostringstream s;
    s << "(" << x.x() * 1e6 << ", " << x.y() * 1e6 << ", " << x.z() * 1e6 << ") um";
    return s.str();
  };
  const bool tissue = cells_.count() > 1;
  std::vector<ClosedSurface> walls;
  for (int c = 0; c < cells_.count(); ++c) {
    walls.emplace_back(s_.wall.x, mesh_, c);
    const int outside = first_particle_outside(s_.fluid.x, cells_.fluid[c], cells_.fluid[c + 1], walls.back());
    if (outside >= 0)
      throw NumericalFailure(where() + ": fluid particle " + std::to_string(outside) + " is outside " +
                             (tissue ? "the wall of its cell " + std::to_string(c) : std::string("the cell wall")) +
                             " at " + at(s_.fluid.x.col(outside)));
  }
  // Walls of different cells must not pass through each other (model.md §10); in a periodic tissue each
  // wall particle is taken to its image nearest the other cell's centroid (model.md §10b).
  std::vector<Eigen::Vector3d> centroid;
  for (int c = 0; c < cells_.count(); ++c)
    centroid.push_back(s_.wall.x.middleCols(cells_.wall[c], cells_.wall_count(c)).rowwise().mean());
  for (int a = 0; a < cells_.count(); ++a)
    for (int b = 0; b < cells_.count(); ++b) {
      if (a == b || (!s_.box.periodic() && !walls[a].box_overlaps(walls[b]))) continue;
      for (Eigen::Index k = cells_.wall[a]; k < cells_.wall[a + 1]; ++k)
        if (walls[b].contains(centroid[b] + s_.box.nearest_image(s_.wall.x.col(k) - centroid[b])))
          throw NumericalFailure(where() + ": wall particle " + std::to_string(k) + " of cell " + std::to_string(a) +
                                 " is inside cell " + std::to_string(b) + " at " + at(s_.wall.x.col(k)) +
                                 " (the walls interpenetrate)");
    }
}

// model.md §6: L_p takes its compression value; the bottom plate touches the lowest wall particle
// (no force yet) and stays; the top plate starts `gap` above its reach of the highest one.
void Simulation::start_compression() {
  s_.stage = Stage::Compression;
  s_.stage_step = 0;
  Lp_m_per_s_Pa_ = p_.compression_Lp_m_per_s_Pa;
  Plates& plates = s_.plates;
  const auto& z = s_.wall.x.row(2);
  const Eigen::Vector3d centroid = s_.wall.x.rowwise().mean();
  plates.active = true;
  plates.axis_x_m = centroid.x();
  plates.axis_y_m = centroid.y();
  plates.bottom_z_m = z.minCoeff() - p_.plate_range_m;
  plates.top_start_z_m = plates.top_z_m = z.maxCoeff() + p_.plate_range_m + p_.plate_gap_m;
  plates.start_time_s = s_.time_s;
  plates.contact_height_m = cell_height_m(s_.wall.x);
  // A periodic slab's footprint is its period (model.md §10b): its cells overhang the period's edges.
  plates.footprint_m2 = s_.box.periodic() ? s_.box.area_m2() : convex_hull_area_2d(s_.wall.x.topRows<2>());
  plates.first_contact_top_z_m = std::nan("");
  plates.unloading = false;
  const LayerHeights heights = layer_heights(s_.wall.x, cells_);
  plates.gauge_length_m = gauge_length_m(heights.layer_centroid_z_m);
  plates.start_layer_height_m = heights.layer_height_m;
  // Rates and lists anew at this state, so a run continued from a saved state is bit-identical.
  neighbours_.invalidate();
  compute_rates();
  if (fluid_.particles) fluid_.particles->start_compression(s_, fluid_context());
}

void Simulation::restore(const State& saved) {
  s_ = saved;
  if (s_.bond_plastic_elongation_m.empty())  // saved before the wall could yield
    s_.bond_plastic_elongation_m.assign(mesh_.bonds.size(), 0.0);
  neighbours_.invalidate();
  compute_rates();
}

Record Simulation::record() const {
  const LoadPartition load =
      top_plate_load(s_.wall.x, wall_force_, push_->on_wall(), push_->backstop_on_wall(), plate_law_, s_.plates);
  Record r = measure(s_, mesh_, cells_, surface_, p_, fluid_.model->readings(s_, cells_, surface_, eos()), load);
  add_energy_account(energy_terms_now(), s_.energy.initial_J, r);
  return r;
}

double Simulation::nominal_strain() const {
  return s_.plates.active ? cellsim::nominal_strain(s_.plates.contact_height_m, cell_height_m(s_.wall.x)) : 0.0;
}
}  // namespace cellsim
