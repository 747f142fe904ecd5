#pragma once
// A periodic slab's period (model.md §10b): its lateral stress, from the virial of the pairs between
// cells that act across the period, and how the period follows zero lateral stress, each cell moving
// with it whole as its centroid maps.
#include <Eigen/Core>

#include "core/state.hpp"
#include "geometry/tissue.hpp"

namespace cellsim {

// sigma = -W / (L_x L_y H): the lateral stress (x, y; tension positive) of a slab of height H whose
// pairs across the period have the virial W (cell_contact.hpp).
Eigen::Vector2d lateral_stress_Pa(const Eigen::Vector2d& period_virial_J, const PeriodicBox& box, double height_m);

// The most a period may strain in one step: far below a cell's own strain per step, so the cells keep up.
constexpr double kLargestPeriodStrainPerStep = 1e-3;

// Strains the period by `strain` (x, y), every cell's particles moving as its centroid maps (shapes and
// velocities kept). Returns how far a pair of particles can have moved apart as the lists see it (the
// cells' moves and, for a pair across the period, the period's change).
double strain_period(State& s, const CellRanges& cells, const Eigen::Vector2d& strain);

// One step of the period following zero lateral stress: it strains by -sigma dt / eta_p along x and y,
// and every cell's particles move as its centroid maps (shapes and velocities kept); the energy the
// follower takes, sigma^2 L_x L_y H dt / eta_p for a slab of height H, joins the account's period loss. Throws
// NumericalFailure if the period would strain more than kLargestPeriodStrainPerStep.
// Returns how far a pair of particles can have moved apart as the lists see it (the cells' moves and,
// for a pair across the period, the period's change).
double follow_lateral_stress(State& s, const CellRanges& cells, double period_viscosity_Pa_s, double dt,
                             double height_m);

}  // namespace cellsim
