#pragma once
// Where a quasi-static increment's relaxation starts (quasi_static.hpp): the last equilibrium, moved by
// the loads' move, and, with time.predictor = secant, by the last increment's motion as well.
#include <Eigen/Core>

#include "core/state.hpp"
#include "physics/plates.hpp"

namespace cellsim {

// The plates' predictor: a plate that moves at fixed particles would thrust the particles it touches k_pw
// (its travel) into its springs, hundreds of times the load they carry, and a relaxation from there may
// settle on another branch (a soft wall dimples under the thrust). So each particle of x keeps the overlap
// it had at was_x with each plate before the move (a particle the plate reaches anew sits at the edge of
// its range): the touching wall moves with the plate, as it will at equilibrium. was_x may be x itself.
void keep_plate_overlaps(Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& was_x, const PlateLaw& law,
                         const Plates& before, const Plates& after);

// The secant's motion from an increment's motion of the wall: the same, less its mean sideways (x, y)
// part. Between frictionless plates the wall's sideways translation is free, so a secant that carried it
// on would walk the cell, increment by increment, to the plates' edge, where Eq 22's footprint makes the
// potential jump and the relaxation stalls (the secant tried on 2026-11-28 ran past its cap so).
Eigen::Matrix3Xd secant_motion(const Eigen::Matrix3Xd& increment_motion_m);

}  // namespace cellsim
