// The closed-cell fluid (cavity_fluid.hpp): what the step asks of a fluid (fluid_model.hpp), from Eqs 7
// and 11 with one pressure per cell.
#include "engine/cavity_fluid.hpp"

#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "physics/cavity_pressure.hpp"
#include "physics/mass_transfer.hpp"

namespace cellsim {
namespace {

// Five-point Gauss-Legendre on [-1, 1]: exact to degree 9, so the pressure's work along a volume path
// (smooth in V) is integrated to round-off.
constexpr std::array<double, 5> kGaussNode{-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                                           0.9061798459386640};
constexpr std::array<double, 5> kGaussWeight{0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                             0.4786286704993665, 0.2369268850561891};

}  // namespace

CavityFluid::CavityFluid(const Params& p)
    : rho0_kg_m3_(p.fluid_density_kg_m3), dt_s_(p.dt_s) {}

// Each cell full of water at rho0 (P = P_T0), no particles.
void CavityFluid::fill(State& s, const Tissue& tissue, const WallSurface& surface) const {
  s.fluid.x.resize(3, 0);
  s.fluid.v.resize(3, 0);
  s.fluid.m.resize(0);
  s.fluid.rho.resize(0);
  s.cavity_mass_kg.resize(static_cast<std::size_t>(tissue.cells.count()));
  for (std::size_t c = 0; c < s.cavity_mass_kg.size(); ++c) s.cavity_mass_kg[c] = rho0_kg_m3_ * surface.cell_volume_m3[c];
}

double CavityFluid::mass_kg(const State& s) const {
  double total = 0;
  for (double m : s.cavity_mass_kg) total += m;
  return total;
}

// The state's masses in the volumes now; the mean pressure is the cells' volume-weighted mean.
FluidReadings CavityFluid::readings(const State& s, const CellRanges& cells, const WallSurface& surface,
                                    const EquationOfState& eos) const {
  FluidReadings r;
  double pressure_volume = 0;
  for (int c = 0; c < cells.count(); ++c) {
    const double M = s.cavity_mass_kg[c], V = surface.cell_volume_m3[c];
    const double P = eos.pressure(M / V);
    r.cell_mass_kg.push_back(M);
    r.cell_mean_pressure_Pa.push_back(P);
    r.mass_kg += M;
    pressure_volume += P * V;
  }
  r.mean_pressure_Pa = pressure_volume / surface.volume_m3;
  r.volume_ratio = 1.0;  // the fluid fills the enclosed volume by construction
  return r;
}

double CavityFluid::density_in_increment(int cell, double volume_m3, const EquationOfState& eos) const {
  return implicit_cavity_density(increment_mass_kg_[cell], volume_m3, increment_a_m3_Pa_[cell], eos);
}

// Each cell's density and pressure at its enclosed volume now (in an increment: Eq 11's backward Euler).
void CavityFluid::compute_forces(State& s, const FluidContext& c, bool, EnergyValues& power_W) {
  const int cells = c.cells.count();
  rho_.resize(static_cast<std::size_t>(cells));
  pressure_Pa_.resize(static_cast<std::size_t>(cells));
  volume_m3_.assign(c.surface.cell_volume_m3.begin(), c.surface.cell_volume_m3.end());
  for (int cell = 0; cell < cells; ++cell) {
    const double V = c.surface.cell_volume_m3[cell];
    rho_[cell] = in_increment_ ? density_in_increment(cell, V, c.eos) : s.cavity_mass_kg[cell] / V;
    pressure_Pa_[cell] = c.eos.pressure(rho_[cell]);
  }
  power_W[kViscousLoss] = 0;
  power_W[kDensityDiffusion] = 0;
}

// Eq 11 for each cell as one particle (n_f = 1), through its own wall; the energy the water carries is its
// enthalpy (mass_transfer.hpp, at rest).
void CavityFluid::transfer_mass(State&, const FluidContext& c, EnergyValues& power_W) {
  const int cells = c.cells.count();
  dm_dt_.assign(static_cast<std::size_t>(cells), 0.0);
  power_W[kMassTransfer] = 0;
  mass_transfer_limit_s_ = INFINITY;
  if (in_increment_) return;  // the increment integrates Eq 11 itself
  const EquationOfState::Enthalpy enthalpy = c.eos.enthalpy();
  for (int cell = 0; cell < cells; ++cell) {
    const double area = c.surface.cell_area_m2[cell], V = c.surface.cell_volume_m3[cell];
    dm_dt_[cell] = mass_rate(area, c.Lp_m_per_s_Pa, rho_[cell], 1, pressure_Pa_[cell], -c.eos.turgor_Pa);
    power_W[kMassTransfer] += dm_dt_[cell] * carried_energy_J_kg(0.0, enthalpy(rho_[cell]));
    // dM'/dM at fixed V, A L_p (P - P_T + rho P'(rho)) / V: the explicit kicks follow Eq 11 for dt below
    // its inverse.
    const double rate = area * c.Lp_m_per_s_Pa *
                        (pressure_Pa_[cell] - c.eos.turgor_Pa + V * cavity_volume_stiffness_Pa_m3(rho_[cell], V, c.eos)) / V;
    if (rate > 0) mass_transfer_limit_s_ = std::min(mass_transfer_limit_s_, 1.0 / rate);
  }
}

// F_k = P dV/dx_k on each wall particle of the cell (physics/cavity_pressure.hpp); the volume spring's
// period for the time-step check: omega^2 = (-dP/dV) sum |dV/dx_k|^2 / m_w.
void CavityFluid::couple_to_wall(State& s, const FluidContext& c, bool, Eigen::Matrix3Xd& on_wall,
                                 Eigen::Matrix3Xd& backstop_on_wall, EnergyValues& power_W) {
  on_wall.resize(3, s.wall.size());
  backstop_on_wall.setZero(3, s.wall.size());
  power_W[kBackstopWork] = 0;
  volume_mode_limit_s_ = INFINITY;
  for (int cell = 0; cell < c.cells.count(); ++cell) {
    double gradient_squared = 0;
    for (Eigen::Index k = c.cells.wall[cell]; k < c.cells.wall[cell + 1]; ++k) {
      const Eigen::Vector3d dV_dx = volume_gradient(c.surface.vertex_normal.col(k));
      on_wall.col(k) = pressure_Pa_[cell] * dV_dx;
      gradient_squared += dV_dx.squaredNorm();
    }
    const double omega2 =
        cavity_volume_stiffness_Pa_m3(rho_[cell], c.surface.cell_volume_m3[cell], c.eos) * gradient_squared / s.wall.mass_kg;
    if (omega2 > 0) volume_mode_limit_s_ = std::min(volume_mode_limit_s_, 1.0 / std::sqrt(omega2));
  }
}

std::vector<double> CavityFluid::volume_stiffness_Pa_m3(const EquationOfState& eos) const {
  std::vector<double> stiffness(rho_.size());
  for (std::size_t cell = 0; cell < rho_.size(); ++cell)
    stiffness[cell] = increment_volume_stiffness_Pa_m3(rho_[cell], volume_m3_[cell],
                                                       in_increment_ ? increment_a_m3_Pa_[cell] : 0.0, eos);
  return stiffness;
}

Eigen::VectorXd CavityFluid::volume_gradients(const WallSurface& surface) const {
  return stacked_volume_gradients(surface.vertex_normal);
}

void CavityFluid::kick(State& s, double half_dt, int) {
  for (std::size_t cell = 0; cell < dm_dt_.size(); ++cell) s.cavity_mass_kg[cell] += half_dt * dm_dt_[cell];
}

std::string CavityFluid::time_step_violation(const State&, const FluidContext&) const {
  std::ostringstream msg;
  if (dt_s_ > mass_transfer_limit_s_)
    msg << "time.dt_ns = " << dt_s_ * 1e9 << " exceeds Eq 11's mass-transfer time of a closed cell ("
        << mass_transfer_limit_s_ * 1e9 << " ns at this K and L_p); use a smaller time step or time.scheme = "
        << "quasi_static";
  else if (dt_s_ > volume_mode_limit_s_)
    msg << "time.dt_ns = " << dt_s_ * 1e9 << " exceeds the period / 2 pi of a closed cell's volume spring ("
        << volume_mode_limit_s_ * 1e9 << " ns at this K); use a smaller time step or time.scheme = quasi_static";
  return msg.str();
}

// Internal energy M e(M/V) of each cell (Eq 7's, eos.hpp); no particles to move, no coupling layer.
void CavityFluid::stored_energy(const State& s, const FluidContext& c, EnergyValues& e) const {
  double internal = 0;
  for (int cell = 0; cell < c.cells.count(); ++cell) {
    const double M = s.cavity_mass_kg[cell];
    internal += M * c.eos.internal_energy_J_kg(M / c.surface.cell_volume_m3[cell]);
  }
  e[kKinetic] = 0;
  e[kInternal] = internal;
  e[kCouplingPotential] = 0;
}

// sum M (1/rho0 - 1/rho) (eos.hpp), the masses now in the volumes of the last force evaluation.
double CavityFluid::stored_energy_per_turgor_m3(const State& s, const EquationOfState& eos) const {
  double per_turgor = 0;
  for (std::size_t cell = 0; cell < volume_m3_.size(); ++cell)
    per_turgor += s.cavity_mass_kg[cell] * eos.internal_energy_per_turgor(s.cavity_mass_kg[cell] / volume_m3_[cell]);
  return per_turgor;
}

void CavityFluid::begin_increment(const State& s, const FluidContext& c, double dt_s) {
  const int cells = c.cells.count();
  increment_mass_kg_.assign(s.cavity_mass_kg.begin(), s.cavity_mass_kg.end());
  increment_volume_m3_.assign(c.surface.cell_volume_m3.begin(), c.surface.cell_volume_m3.end());
  increment_a_m3_Pa_.resize(static_cast<std::size_t>(cells));
  for (int cell = 0; cell < cells; ++cell)
    increment_a_m3_Pa_[cell] = std::isinf(dt_s) ? INFINITY : dt_s * c.surface.cell_area_m2[cell] * c.Lp_m_per_s_Pa;
  in_increment_ = true;
}

// Five-point Gauss-Legendre along the volume's path from the increment's start to volume_m3.
double CavityFluid::pressure_work_J(int cell, double volume_m3, const EquationOfState& eos) const {
  const double V0 = increment_volume_m3_[cell];
  double work = 0;
  for (std::size_t q = 0; q < kGaussNode.size(); ++q) {
    const double V = 0.5 * (V0 + volume_m3) + 0.5 * (volume_m3 - V0) * kGaussNode[q];
    work += kGaussWeight[q] * eos.pressure(density_in_increment(cell, V, eos));
  }
  return 0.5 * (volume_m3 - V0) * work;
}

double CavityFluid::increment_work_J(const FluidContext& c) const {
  if (!in_increment_) throw std::logic_error("increment_work_J outside an increment (cavity_fluid.hpp)");
  double work = 0;
  for (int cell = 0; cell < c.cells.count(); ++cell) work += pressure_work_J(cell, c.surface.cell_volume_m3[cell], c.eos);
  return work;
}

double CavityFluid::end_increment(State& s, const FluidContext& c) {
  double water_J = 0;
  for (int cell = 0; cell < c.cells.count(); ++cell) {
    const double M0 = increment_mass_kg_[cell], V0 = increment_volume_m3_[cell];
    const double V1 = c.surface.cell_volume_m3[cell];
    const double M1 = density_in_increment(cell, V1, c.eos) * V1;
    // The pressure's work along the volume's path: in the increment P is a function of V alone.
    water_J += M1 * c.eos.internal_energy_J_kg(M1 / V1) - M0 * c.eos.internal_energy_J_kg(M0 / V0) +
               pressure_work_J(cell, V1, c.eos);
    s.cavity_mass_kg[cell] = M1;
  }
  in_increment_ = false;
  return water_J;
}

}  // namespace cellsim
