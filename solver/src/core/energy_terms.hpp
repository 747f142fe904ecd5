#pragma once
// The energy account's terms (docs/model.md §8), one row each: its time series, how it is obtained and
// how it enters the residual. The residual, the time series, the saved state, the docs and the
// workflow's aggregation (config/schema/energy_terms.json, `cellsim energy-terms`) read this table; a
// new term is one row here and the law that produces its energy or power.
#include <array>
#include <cstddef>

namespace cellsim {

// Stored: energy the particles hold, a function of the state. Flow: energy a non-conservative term put
// in since t = 0 (+ in the residual's sum of what was put in). Loss: energy a term took out since t = 0,
// positive (- in that sum).
enum class EnergyRole { Stored, Flow, Loss };

// How a term's value is had: from the state at the record (every stored energy, and a loss that is a
// function of the state such as the lamella's damage); or as a running integral kept with the state
// (EnergyFlows, state.hpp) of a power over each half kick, of a power the density update carries (the
// kicks, or the density's own drift step), or of jumps at fixed positions (closures, plastic flow).
enum class EnergySource { State, Power, DensityPower, Jump };

enum EnergyTermId : std::size_t {
  kKinetic, kInternal, kWallStiff, kWallContraction, kWallBending, kCouplingPotential, kPlateSprings, kContact,
  kLamella, kPlateWork, kViscousLoss, kDampingLoss, kMassTransfer, kPressureClosure, kDrive, kDensityDiffusion,
  kBackstopWork, kVolumeClosure, kPlasticLoss, kLamellaLoss, kRelaxationLoss, kPeriodLoss, kEnergyTermCount
};

struct EnergyTerm {
  EnergyTermId id;
  // The time series (J) under /timeseries; null for the kinetic energy, written as its fluid and wall parts
  // beside the speeds (measures.cpp).
  const char* column;
  const char* state_key;  // a running integral's attribute in a saved state (null if not integrated)
  EnergyRole role;
  EnergySource source;
  const char* label;       // a few words, for the stored energy's and the residual's definitions
  const char* definition;  // of the time series (docs/output-reference.md)
};

// In the order of the time series and of the sums (a stored energy's total and the residual add them in
// this order).
inline constexpr std::array<EnergyTerm, kEnergyTermCount> kEnergyTerms{{
    {kKinetic, nullptr, nullptr, EnergyRole::Stored, EnergySource::State, "kinetic", "sum of m v^2 / 2"},
    {kInternal, "internal_energy_J", nullptr, EnergyRole::Stored, EnergySource::State, "internal",
     "fluid internal energy, sum of m e(rho), de = P / rho^2 drho with Eq 7's P"},
    {kWallStiff, "wall_stiff_energy_J", nullptr, EnergyRole::Stored, EnergySource::State, "wall stiff",
     "energy of Eq 15's springs, (G t0 l0^2 / sqrt 3)((lambda^2 - 1)/2 - ln lambda) per bond"},
    {kWallContraction, "wall_contraction_energy_J", nullptr, EnergyRole::Stored, EnergySource::State,
     "wall contraction", "energy of Eq 21's springs, k_wc (l - L_ref)^2 / 2 per bond"},
    {kWallBending, "wall_bending_energy_J", nullptr, EnergyRole::Stored, EnergySource::State, "wall bending",
     "Eq 20's bending energy E_b"},
    {kCouplingPotential, "coupling_energy_J", nullptr, EnergyRole::Stored, EnergySource::State, "coupling",
     "potential of the LJ wall-fluid forces, zero at r_c (0 for the pressure coupling)"},
    {kPlateSprings, "plate_energy_J", nullptr, EnergyRole::Stored, EnergySource::State, "plate",
     "energy of Eq 22's plate springs, k_pw overlap^2 / 2"},
    {kContact, "contact_energy_J", nullptr, EnergyRole::Stored, EnergySource::State, "contact",
     "a tissue's wall contacts between cells, k_c (g - r)^2 / 2 per pair closer than g"},
    {kLamella, "lamella_energy_J", nullptr, EnergyRole::Stored, EnergySource::State, "lamella",
     "energy its intact middle-lamella bonds store (F delta / 2 on the bond's branch)"},
    {kPlateWork, "plate_work_J", "energy_plate_work_J", EnergyRole::Flow, EnergySource::Power, "plate work",
     "work of the top plate on the wall since t = 0, integral of F_top x plate speed"},
    {kViscousLoss, "viscous_loss_J", "energy_viscous_loss_J", EnergyRole::Loss, EnergySource::Power, "viscous loss",
     "energy dissipated by the viscous forces (Eq 4) since t = 0"},
    {kDampingLoss, "damping_loss_J", "energy_damping_loss_J", EnergyRole::Loss, EnergySource::Power, "damping loss",
     "energy dissipated by the wall damping (Eq 16) since t = 0"},
    {kMassTransfer, "mass_transfer_energy_J", "energy_mass_transfer_J", EnergyRole::Flow, EnergySource::DensityPower,
     "mass transfer",
     "energy Eq 11's water brought in since t = 0, integral of dm/dt (v^2/2 + e + P/rho) (negative: it left)"},
    {kPressureClosure, "closure_energy_J", "energy_closure_J", EnergyRole::Flow, EnergySource::Jump, "closure",
     "energy the wall-pressure closure's mass scaling added since t = 0 (drying only)"},
    {kDrive, "drive_energy_J", "energy_drive_J", EnergyRole::Flow, EnergySource::Power, "drive",
     "energy the drying ramp of P_T and L_ref added at fixed particles since t = 0"},
    {kDensityDiffusion, "density_diffusion_energy_J", "energy_density_diffusion_J", EnergyRole::Flow,
     EnergySource::DensityPower, "density diffusion",
     "internal energy the delta-SPH density diffusion (fluid.density_diffusion) added since t = 0"},
    {kBackstopWork, "backstop_work_J", "energy_backstop_work_J", EnergyRole::Flow, EnergySource::Power,
     "backstop work", "work of the pressure coupling's backstop on fluid and wall since t = 0 (0 for LJ)"},
    {kVolumeClosure, "volume_closure_energy_J", "energy_volume_closure_J", EnergyRole::Flow, EnergySource::Jump,
     "volume closure", "internal energy the volume closure's density scaling added since t = 0 (compression only)"},
    {kPlasticLoss, "plastic_loss_J", "energy_plastic_loss_J", EnergyRole::Loss, EnergySource::Jump, "plastic loss",
     "energy the wall's plastic flow dissipated since t = 0 (0 for an elastic wall)"},
    {kLamellaLoss, "lamella_loss_J", nullptr, EnergyRole::Loss, EnergySource::State, "lamella loss",
     "energy the middle lamella's softening and breaking took since t = 0 (its bonds' largest openings; G_f a_w "
     "for each bond separated)"},
    {kRelaxationLoss, "relaxation_loss_J", "energy_relaxation_loss_J", EnergyRole::Loss, EnergySource::Jump,
     "relaxation loss",
     "energy the quasi-static relaxations released since t = 0 beyond the loads' work (time.scheme = quasi_static: "
     "the trapezoid of the plate's force over its travel and of the drying ramp's power): the snaps of a wall that "
     "folds, and the trapezoid's error, which shrinks as dt^2; 0 for a dynamic run"},
    {kPeriodLoss, "period_loss_J", "energy_period_loss_J", EnergyRole::Loss, EnergySource::Jump, "period loss",
     "energy a periodic slab's period took as it followed zero lateral stress since t = 0 (the dynamic scheme's "
     "viscous follower, model.md §10b: minus the lateral stress times the slab's face area over the period's "
     "travel, sigma^2 L_x L_y H dt / eta_p a step); 0 for a held period, a cluster or one cell, and in the "
     "quasi-static scheme, whose period moves within its relaxations"},
}};

// A stage's account closes while its residual stays within this share of the energy that went through it:
// a drying's flows and losses from t = 0 (their magnitudes summed), a compression's plate work. Past it the
// run's warning says so (io/drying_summary.hpp, io/compression_summary.hpp).
constexpr double kEnergyResidualTolerance = 0.02;  // the LJ coupling's compressions leave up to 1.6 %

// One value per term, indexed by EnergyTermId.
using EnergyValues = std::array<double, kEnergyTermCount>;

// The term's sign in the sum of what the non-stored terms put in (0 for a stored energy).
constexpr double residual_sign(EnergyRole role) {
  return role == EnergyRole::Flow ? 1.0 : role == EnergyRole::Loss ? -1.0 : 0.0;
}

constexpr bool integrated(const EnergyTerm& term) { return term.source != EnergySource::State; }

// The table's rows sit at their own ids (checked when compiled).
// The table's rows sit at their own ids, and exactly the integrated terms have a key in the saved state
// (checked when compiled).
constexpr bool rows_consistent() {
  for (std::size_t i = 0; i < kEnergyTerms.size(); ++i)
    if (kEnergyTerms[i].id != i || integrated(kEnergyTerms[i]) != (kEnergyTerms[i].state_key != nullptr) ||
        (kEnergyTerms[i].role == EnergyRole::Stored && integrated(kEnergyTerms[i])))
      return false;
  return true;
}
static_assert(rows_consistent(), "kEnergyTerms: each row at its id; a state key for each integrated term only");

}  // namespace cellsim
