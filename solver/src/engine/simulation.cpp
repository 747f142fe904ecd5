// The step of a run (simulation.hpp): the wall's forces, the contacts between cells and the plates here,
// the fluid's through its model (fluid_model.hpp), in the order of the model.
#include "engine/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/errors.hpp"
#include "geometry/containment.hpp"
#include "engine/leapfrog.hpp"
#include "engine/periodic_slab.hpp"
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

// The case's fluid model (fluid_model.hpp, fluid.model): SPH, with either coupling (coupling.model), or the
// closed cell of one pressure.
std::unique_ptr<FluidModel> fluid_model(const Params& p, const CellRanges& cells, const PropertyFactors& factors) {
  if (p.fluid_model == kCavityFluid) return std::make_unique<CavityFluid>(p);
  return std::make_unique<SphFluid>(p, cells, factors);
}

// The seeded factors of the heterogeneous properties (heterogeneity.hpp), from the tissue as built.
PropertyFactors property_factors(const Params& p, const Tissue& tissue) {
  const HeterogeneityLaw law{p.heterogeneity_seed, p.G_cv, p.thickness_cv, p.viscosity_cv, p.correlation_length_m};
  return draw_property_factors(law, tissue.wall_x, tissue.mesh, tissue.cells.cell_of_wall(), tissue.cells.count());
}

// Adds the coupling's forces on wall particles [begin, end) to their forces, and returns the sum of
// their push along their unit normals (packed norms and divisions), for the wall pressure.
double add_coupling(const Eigen::Matrix3Xd& on_wall, const Eigen::Matrix3Xd& vertex_normal, Eigen::Index begin,
                    Eigen::Index end, Eigen::Matrix3Xd& wall_force) {
  const Eigen::Index count = end - begin;
  wall_force.middleCols(begin, count) += on_wall.middleCols(begin, count);
  return (on_wall.middleCols(begin, count).cwiseProduct(vertex_normal.middleCols(begin, count)).colwise().sum().array() /
          vertex_normal.middleCols(begin, count).colwise().norm().array())
      .sum();
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
      fluid_(fluid_model(p, tissue.cells, factors)),
      plate_law_(cellsim::plate_law(p)),
      plate_motion_(plate_motion(p)),
      bond_law_(make_bond_law(p, factors)),
      Lp_m_per_s_Pa_(p.drying_Lp_m_per_s_Pa) {
  const WallSurface built = wall_surface(tissue.wall_x, mesh_);
  fluid_->fill(s_, tissue, built);
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
  s_.initial_fluid_mass_kg = fluid_->mass_kg(s_);
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

EnergyValues Simulation::energy_terms_now() const {
  const bool tissue = cells_.count() > 1;
  const FluidContext fluid_now = fluid_context();
  return energy_terms(s_, {*fluid_, fluid_now, mesh_, bond_law_, contraction_ramp(), bending_, plate_law_,
                           tissue ? &contact_law_ : nullptr, &neighbours_.wall_wall(), &lamella_});
}

FluidContext Simulation::fluid_context() const {
  return {surface_, neighbours_, cells_, eos(), Lp_m_per_s_Pa_, threads_};
}

const SphFluid& Simulation::sph_fluid() const {
  const auto* sph = dynamic_cast<const SphFluid*>(fluid_.get());
  if (!sph) throw std::logic_error("this case's fluid is not SPH (fluid_model.hpp)");
  return *sph;
}

CavityFluid& Simulation::cavity_fluid() {
  auto* cavity = dynamic_cast<CavityFluid*>(fluid_.get());
  if (!cavity) throw std::logic_error("this case's fluid is not a closed cell (fluid_model.hpp)");
  return *cavity;
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
  compute_rates(fluid_->density_in_drift() ? p_.dt_s : 0.0);
  kick(0.5 * p_.dt_s);
  if (s_.stage == Stage::Drying) fluid_->apply_drying_closure(s_, fluid_context(), cell_wall_pressure_Pa_);
  if (s_.stage == Stage::Compression) fluid_->apply_compression_closure(s_, fluid_context());
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
  const FluidContext fluid_now = fluid_context();  // the positions' surface and lists, the clock's EOS
  if (density_step_s > 0) fluid_->advance_density(s_, fluid_now, density_step_s, energy_power_W_);
  timer_.lap(Phase::DensityDrift);
  fluid_->compute_forces(s_, fluid_now, density_step_s > 0, energy_power_W_);
  timer_.lap(Phase::FluidPairs);
  fluid_->transfer_mass(s_, fluid_now, energy_power_W_);
  timer_.lap(Phase::MassTransfer);
  wall_force_.resize(3, s_.wall.size());
  for_blocks(threads_, s_.wall.size(), [&](Eigen::Index begin, Eigen::Index end) {
    wall_force_.middleCols(begin, end - begin).setZero();
  });
  wall_terms();
  cell_contact_terms();
  wall_fluid_terms(fluid_now, density_step_s > 0);
  timer_.lap(Phase::WallFluid);
  plate_terms();
  timer_.lap(Phase::Plates);
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
  fluid_wall_cutoff_m_ = fluid_->follow_smoothing_length(s_.smoothing_length_m);
}

void Simulation::update_neighbours() {
  neighbours_.update(s_.fluid.x, s_.wall.x, 2.0 * s_.smoothing_length_m, fluid_wall_cutoff_m_, threads_, moved_since_lists_m_,
                     s_.box);  // the period of the moment: a dried slab's has shrunk from the one built
  moved_since_lists_m_ = 0;
}

// Stiff (Eq 15), contraction (Eq 21, ramped during drying) and damping (Eq 16) on every bond.
void Simulation::wall_terms() {
  const BondSums bonds =
      add_bond_forces(s_.wall, mesh_, bond_law_, contraction_ramp(), threads_, s_.bond_plastic_elongation_m, wall_force_,
                      bond_scratch_);
  s_.energy.integral[kPlasticLoss] += bonds.plastic_loss_J;  // at fixed positions: a jump, not a rate
  s_.wall_tension_N_m = bonds.tension_times_length / (2.0 * surface_.area_m2);
  energy_power_W_[kDampingLoss] = bonds.damping_loss_W;
  // The drying ramp moves P_T and L_ref (drying.hpp): the stored energy changes at fixed particles.
  const double ramp_rate = s_.stage == Stage::Drying ? drying::smoothstep_ramp_rate(s_.time_s, p_.ramp_time_s) : 0.0;
  const double drying_share = (1.0 - p_.dryness) * ramp_rate;  // d/dt of (1 - X) ramp
  energy_power_W_[kDrive] = ramp_rate == 0 ? 0.0
                                           : drive_power_W(fluid_->stored_energy_per_turgor_m3(s_, eos()),
                                                           -p_.turgor_Pa * drying_share,
                                                           bonds.contraction_times_l0_N_m,
                                                           p_.contraction_ratio * drying_share);
  timer_.lap(Phase::WallBonds);
  bending_.add_forces(s_.wall.x, surface_.triangles, threads_, wall_force_);
  timer_.lap(Phase::Bending);
}

// Contact and middle lamella between the walls of different cells (cell_contact.hpp); none for one cell.
void Simulation::cell_contact_terms() {
  if (cells_.count() == 1) return;
  Eigen::Vector2d period_virial_J;
  add_cell_contact_forces(s_.wall.x, neighbours_.wall_wall(), lamella_, contact_law_, s_.box, s_.lamella_intact,
                          s_.lamella_peak_opening_m, wall_force_, &period_virial_J);
  if (s_.box.periodic()) {
    const Eigen::Vector2d stress = lateral_stress_Pa(period_virial_J, s_.box, cell_height_m(s_.wall.x));
    s_.lateral_stress_x_Pa = stress.x();
    s_.lateral_stress_y_Pa = stress.y();
  }
  timer_.lap(Phase::CellContact);
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

// The wall-fluid coupling (Lennard-Jones or the fluid's pressure, coupling.model); also the outward
// push on the wall that the pressure closure and the Young-Laplace check compare with the fluid pressure.
// weights_fresh: advance_density has weighed the pressure coupling's pairs at these positions.
void Simulation::wall_fluid_terms(const FluidContext& fluid_now, bool weights_fresh) {
  fluid_->couple_to_wall(s_, fluid_now, weights_fresh, coupling_on_wall_, backstop_on_wall_, energy_power_W_);
  const std::vector<double> outward = sum_by_cell(threads_, cells_.wall, [&](Eigen::Index begin, Eigen::Index end) {
    return add_coupling(coupling_on_wall_, surface_.vertex_normal, begin, end, wall_force_);
  });
  cell_wall_pressure_Pa_.resize(outward.size());
  double outward_sum = 0;
  for (std::size_t c = 0; c < outward.size(); ++c) {
    cell_wall_pressure_Pa_[c] = outward[c] / surface_.cell_area_m2[c];
    outward_sum += outward[c];
  }
  s_.wall_pressure_Pa = outward_sum / surface_.area_m2;
}

// Eq 22 during compression; the first contact of the top plate starts the plate strain.
void Simulation::plate_terms() {
  Plates& plates = s_.plates;
  energy_power_W_[kPlateWork] = 0;
  if (!plates.active) return;
  add_plate_forces(s_.wall.x, plate_law_, plates, wall_force_, threads_);
  // The wall pushes up; the plate moves down (negative speed while it unloads).
  energy_power_W_[kPlateWork] = plates.force_top_N * top_plate_speed_m_s(plates, plate_motion_);
  if (std::isnan(plates.first_contact_top_z_m) && plates.force_top_N > 0) plates.first_contact_top_z_m = plates.top_z_m;
}

void Simulation::kick(double half_dt) {
  add_half_kick(energy_power_W_, half_dt, !fluid_->density_in_drift(), s_.energy);
  fluid_->kick(s_, half_dt, threads_);
  for_blocks(threads_, s_.wall.size(), [&](Eigen::Index begin, Eigen::Index end) {
    add_scaled(half_dt / s_.wall.mass_kg, wall_force_, begin, end, s_.wall.v);
  });
}

void Simulation::drift(double dt) {
  const double fluid_v2 = fluid_->drift(s_, dt, threads_);
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
  s_.initial_fluid_mass_kg = fluid_->mass_kg(s_);
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
  const std::string violation = fluid_->time_step_violation(s_, fluid_context());
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
  fluid_->start_compression(s_, fluid_context());
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
      top_plate_load(s_.wall.x, wall_force_, coupling_on_wall_, backstop_on_wall_, plate_law_, s_.plates);
  Record r = measure(s_, mesh_, cells_, surface_, p_, fluid_->readings(s_, cells_, surface_, eos()), load);
  add_energy_account(energy_terms_now(), s_.energy.initial_J, r);
  return r;
}

double Simulation::nominal_strain() const {
  return s_.plates.active ? cellsim::nominal_strain(s_.plates.contact_height_m, cell_height_m(s_.wall.x)) : 0.0;
}
}  // namespace cellsim
