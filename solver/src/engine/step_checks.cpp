#include "engine/step_checks.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "parallel/threads.hpp"
#include "physics/wall_terms.hpp"

namespace cellsim {
namespace {

// A wall particle of a tissue faces at most about this many particles of a neighbour's wall within the
// wall gap (the layers are one gap apart, their particles about one gap apart within each layer).
constexpr double kContactPartners = 3;

// The fastest fluid particle and the one with the largest acceleration (squared), for the CFL limits.
struct Fastest {
  double v2 = 0, a2 = 0;
  Eigen::Index i_v = 0, i_a = 0;
  // Folds a later block in: the first particle wins a tie, as in one pass.
  Fastest faster(const Fastest& later) const {
    Fastest f = *this;
    if (later.v2 > f.v2) f.v2 = later.v2, f.i_v = later.i_v;
    if (later.a2 > f.a2) f.a2 = later.a2, f.i_a = later.i_a;
    return f;
  }
};

Fastest fastest_fluid(const FluidParticles& f, const Eigen::Matrix3Xd& force, Eigen::Index begin, Eigen::Index end) {
  Fastest r;
  r.i_v = r.i_a = begin;
  for (Eigen::Index i = begin; i < end; ++i) {
    const double v2 = f.v.col(i).squaredNorm();
    const double a2 = force.col(i).squaredNorm() / (f.m[i] * f.m[i]);
    if (v2 > r.v2) r.v2 = v2, r.i_v = i;
    if (a2 > r.a2) r.a2 = a2, r.i_a = i;
  }
  return r;
}

}  // namespace

double wall_spring_dt_limit_s(const WallMesh& mesh, const BondLaw& bonds, const std::vector<LamellaBond>& lamella,
                              const Params& p, double wall_mass_kg, Eigen::Index wall_count) {
  const double contact = lamella.empty() ? 0.0 : kContactPartners * p.contact_stiffness_N_m;
  std::vector<double> k_sum(static_cast<std::size_t>(wall_count), contact);
  for (std::size_t i = 0; i < mesh.bonds.size(); ++i) {
    const auto& b = mesh.bonds[i];
    const double k_bond = p.contraction_stiffness_N_m + wall::stiff_stiffness_at_rest(bonds.G_t_N_m[i]);
    k_sum[static_cast<std::size_t>(b[0])] += k_bond;
    k_sum[static_cast<std::size_t>(b[1])] += k_bond;
  }
  for (const auto& b : lamella) {
    k_sum[static_cast<std::size_t>(b.a)] += p.lamella_stiffness_N_m;
    k_sum[static_cast<std::size_t>(b.b)] += p.lamella_stiffness_N_m;
  }
  double k_max = p.plate_stiffness_N_m;
  for (double k : k_sum) k_max = std::max(k_max, k + p.plate_stiffness_N_m);
  return 2.0 / std::sqrt(2.0 * k_max / wall_mass_kg);
}

// Squared speeds and accelerations are compared (one square root each), and a message is composed only
// on failure.
std::string time_step_violation(const FluidParticles& f, const Eigen::Matrix3Xd& fluid_force, double h_m,
                                 double sound_speed_m_s, double largest_viscosity_Pa_s, double rho0_kg_m3, double dt_s,
                                 int threads) {
  const Fastest fastest = reduce_blocks<Fastest>(
      threads, f.size(),
      [&](Eigen::Index begin, Eigen::Index end) { return fastest_fluid(f, fluid_force, begin, end); },
      [](const Fastest& a, const Fastest& b) { return a.faster(b); });
  const double v_max = std::sqrt(fastest.v2), a_max = std::sqrt(fastest.a2);
  const double sound_limit = 0.25 * h_m / (sound_speed_m_s + v_max);
  const double viscous_limit =
      largest_viscosity_Pa_s > 0 ? 0.125 * h_m * h_m * rho0_kg_m3 / largest_viscosity_Pa_s : INFINITY;
  const double acceleration_limit = a_max > 0 ? 0.25 * std::sqrt(h_m / a_max) : INFINITY;
  const auto exceeds = [&](double limit, const std::string& what) {
    std::ostringstream msg;
    msg << "time step " << dt_s * 1e9 << " ns exceeds " << what << " (" << limit * 1e9 << " ns); reduce time.dt_ns";
    return msg.str();
  };
  if (dt_s > sound_limit)
    return exceeds(sound_limit, "the sound-speed CFL limit 0.25 h / (c0 + |v|max), |v|max = " + std::to_string(v_max) +
                                    " m/s at fluid particle " + std::to_string(fastest.i_v));
  if (dt_s > viscous_limit) return exceeds(viscous_limit, "the viscous limit 0.125 h^2 rho0 / mu");
  if (dt_s > acceleration_limit)
    return exceeds(acceleration_limit, "the acceleration limit 0.25 sqrt(h / |a|max), |a|max = " +
                                           std::to_string(a_max) + " m/s^2 at fluid particle " +
                                           std::to_string(fastest.i_a));
  return "";
}

bool fluid_is_sound(const FluidParticles& f, Eigen::Index begin, Eigen::Index end) {
  const Eigen::Index count = end - begin;
  if (count == 0) return true;  // a closed-cell fluid has no particles
  return all_finite(f.x.middleCols(begin, count)) && all_finite(f.v.middleCols(begin, count)) &&
         all_finite(f.rho.segment(begin, count)) && all_finite(f.m.segment(begin, count)) &&
         f.rho.segment(begin, count).minCoeff() > 0 && f.m.segment(begin, count).minCoeff() > 0;
}

bool wall_is_finite(const WallParticles& w, Eigen::Index begin, Eigen::Index end) {
  return all_finite(w.x.middleCols(begin, end - begin)) && all_finite(w.v.middleCols(begin, end - begin));
}

// The common case is one packed pass per array; the particle at fault is looked up only on failure.
std::string unsound_particle(const State& s, int threads) {
  const auto both = [](bool a, bool b) { return a && b; };
  const bool fluid_sound = reduce_blocks<bool>(
      threads, s.fluid.size(), [&](Eigen::Index b, Eigen::Index e) { return fluid_is_sound(s.fluid, b, e); }, both);
  const bool wall_finite = reduce_blocks<bool>(
      threads, s.wall.size(), [&](Eigen::Index b, Eigen::Index e) { return wall_is_finite(s.wall, b, e); }, both);
  bool cavity_sound = true;
  for (double mass : s.cavity_mass_kg) cavity_sound = cavity_sound && std::isfinite(mass) && mass > 0;
  if (fluid_sound && wall_finite && cavity_sound) return "";
  // Something is wrong: find the first particle at fault, in the order of the quantities.
  const auto first_nonfinite = [](const char* kind, const Eigen::Matrix3Xd& m, const char* quantity) -> std::string {
    for (Eigen::Index i = 0; i < m.cols(); ++i)
      if (!m.col(i).allFinite())
        return std::string(kind) + " particle " + std::to_string(i) + " has a non-finite " + quantity;
    return "";
  };
  for (const std::string& found :
       {first_nonfinite("fluid", s.fluid.x, "position"), first_nonfinite("fluid", s.fluid.v, "velocity"),
        first_nonfinite("wall", s.wall.x, "position"), first_nonfinite("wall", s.wall.v, "velocity")})
    if (!found.empty()) return found;
  const auto& f = s.fluid;
  for (Eigen::Index i = 0; i < f.size(); ++i)
    if (!std::isfinite(f.rho[i]) || !(f.rho[i] > 0) || !std::isfinite(f.m[i]) || !(f.m[i] > 0)) {
      std::ostringstream msg;
      msg << "fluid particle " << i << " has density " << f.rho[i] << " kg/m^3 and mass " << f.m[i]
          << " kg (both must be positive and finite)";
      return msg.str();
    }
  for (std::size_t c = 0; c < s.cavity_mass_kg.size(); ++c)
    if (!std::isfinite(s.cavity_mass_kg[c]) || !(s.cavity_mass_kg[c] > 0)) {
      std::ostringstream msg;
      msg << "the fluid of closed cell " << c << " has mass " << s.cavity_mass_kg[c] << " kg (it must be positive)";
      return msg.str();
    }
  return "";
}

}  // namespace cellsim
