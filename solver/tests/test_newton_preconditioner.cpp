// The quasi-static Newton steps' preconditioner (engine/newton_preconditioner.hpp) and the stiffness it
// factors beyond the springs (physics/wall_stiffness.hpp, physics/cavity_pressure.hpp): the pressure's
// follower stiffness is minus the derivative of P dV/dx at fixed P, a cell's volume spring within an
// increment is minus the derivative of its pressure along V, and the solve is the inverse of the sparse
// part plus each cell's rank-one volume spring, shifted where the sparse part is not positive definite.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include <Eigen/Dense>

#include "engine/cavity_fluid.hpp"
#include "engine/newton_preconditioner.hpp"
#include "engine/simulation.hpp"
#include "geometry/block_stiffness.hpp"
#include "geometry/heterogeneity.hpp"
#include "geometry/surface.hpp"
#include "geometry/tissue.hpp"
#include "physics/cavity_pressure.hpp"
#include "physics/wall_bonds.hpp"
#include "physics/wall_stiffness.hpp"
#include "small_cell.hpp"

using namespace cellsim;
using cellsim::testing::small_cell_case;

namespace {

const EquationOfState kEos{200e3, 20e6, 1000, 7};

// The small cell's wall moved off its sphere, so that no symmetry hides an error.
Eigen::Matrix3Xd rough_wall(const Tissue& tissue) {
  Eigen::Matrix3Xd x = tissue.wall_x;
  for (Eigen::Index k = 0; k < x.cols(); ++k) x.col(k) *= 1.0 + 0.05 * std::sin(3.0 * k);
  return x;
}

Eigen::VectorXd pressure_forces(const Eigen::Matrix3Xd& x, const WallMesh& mesh, double P) {
  return P * stacked_volume_gradients(wall_surface(x, mesh).vertex_normal);
}

// The preconditioner's matrix, dense: the factored sparse part, its shift, and each cell's volume spring
// k_c g_c g_c^T (g_c: g on the cell's rows).
Eigen::MatrixXd dense_with_volume_springs(const Eigen::SparseMatrix<double>& factored, double shift_N_m,
                                          const Eigen::VectorXd& g, const CellRanges& cells, const std::vector<double>& k_c) {
  const Eigen::Index n = factored.rows();
  Eigen::MatrixXd dense = Eigen::MatrixXd(factored) + shift_N_m * Eigen::MatrixXd::Identity(n, n);
  for (int c = 0; c < cells.count(); ++c) {
    Eigen::VectorXd gc = Eigen::VectorXd::Zero(n);
    const Eigen::Index first = 3 * cells.wall[c], size = 3 * cells.wall_count(c);
    gc.segment(first, size) = g.segment(first, size);
    dense += k_c[static_cast<std::size_t>(c)] * gc * gc.transpose();
  }
  return dense;
}

void add_diagonal_shift(double shift_N_m, BlockStiffness& K) {
  for (Eigen::Index k = 0; k < K.matrix().rows() / 3; ++k)
    K.add(static_cast<int>(k), static_cast<int>(k), shift_N_m * Eigen::Matrix3d::Identity());
}

}  // namespace

// K e_j = -(F(x + h e_j) - F(x - h e_j)) / 2h for F = P dV/dx at fixed P (central differences, to 1e-6
// of the column's size), and K is symmetric.
TEST(PressureFollowerStiffness, IsMinusTheDerivativeOfThePressuresForceAtFixedPressure) {
  const Params p = small_cell_case();
  const Tissue tissue = build_tissue(p);
  const Eigen::Matrix3Xd x = rough_wall(tissue);
  const double P = 3.0e5;
  BlockStiffness follower(x.cols(), tissue.mesh.bonds);
  add_pressure_follower_stiffness(x, tissue.mesh, {P}, follower);
  const Eigen::MatrixXd K = Eigen::MatrixXd(follower.matrix());
  EXPECT_LT((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-12 * K.cwiseAbs().maxCoeff());
  const double h = 1e-10;
  for (Eigen::Index j : {0, 5, 100, 241, 480}) {
    Eigen::Matrix3Xd plus = x, minus = x;
    plus(j % 3, j / 3) += h;
    minus(j % 3, j / 3) -= h;
    const Eigen::VectorXd fd = -(pressure_forces(plus, tissue.mesh, P) - pressure_forces(minus, tissue.mesh, P)) / (2 * h);
    EXPECT_LT((K.col(j) - fd).cwiseAbs().maxCoeff(), 1e-6 * fd.cwiseAbs().maxCoeff()) << "column " << j;
    EXPECT_GT(fd.cwiseAbs().maxCoeff(), 0.0);
  }
}

// The springs' stiffness (Eqs 15 and 21) is minus the central difference of their forces at a fixed history,
// to 1e-6 of the column's size: on a rough wall part in tension, part in compression (its bonds' untensioned
// sides have no geometric term, so the test's wall is stretched by 10 % on average), mid-drying at X/X0 = 0.5
// (L_ref shortened), with plastic elongations on a third of the bonds (the springs see l - delta_p).
TEST(WallSpringStiffness, IsMinusTheDerivativeOfTheSpringsForceWithAPlasticElongation) {
  const Params p = small_cell_case({{"drying", {{"dryness", 0.5}}}});
  const Tissue tissue = build_tissue(p);
  const Eigen::Matrix3Xd x = 1.10 * rough_wall(tissue);
  const BondLaw law = make_bond_law(p, draw_property_factors({}, tissue.wall_x, tissue.mesh,
                                                             tissue.cells.cell_of_wall(), tissue.cells.count()));
  std::vector<double> plastic(tissue.mesh.bonds.size(), 0.0);
  for (std::size_t b = 0; b < plastic.size(); b += 3) plastic[b] = 0.02 * tissue.mesh.rest_length_m[b];
  const double ramp = 0.6;
  const auto forces = [&](const Eigen::Matrix3Xd& at) {
    WallParticles w{at, Eigen::Matrix3Xd::Zero(3, at.cols()), tissue.wall_mass_kg};
    Eigen::Matrix3Xd f = Eigen::Matrix3Xd::Zero(3, at.cols());
    std::vector<double> history = plastic;  // an elastic law: the sliders stay where they are
    BondScratch scratch;
    add_bond_forces(w, tissue.mesh, law, ramp, 1, history, f, scratch);
    return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(f.data(), f.size()));
  };
  BlockStiffness springs(x.cols(), tissue.mesh.bonds);
  add_wall_spring_stiffness(x, tissue.mesh, law, ramp, plastic, springs);
  const Eigen::MatrixXd K = Eigen::MatrixXd(springs.matrix());
  EXPECT_LT((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-12 * K.cwiseAbs().maxCoeff());
  const double h = 1e-12;
  for (Eigen::Index j : {0, 7, 100, 241, 302, 480}) {
    Eigen::Matrix3Xd plus = x, minus = x;
    plus(j % 3, j / 3) += h;
    minus(j % 3, j / 3) -= h;
    const Eigen::VectorXd fd = -(forces(plus) - forces(minus)) / (2 * h);
    EXPECT_LT((K.col(j) - fd).cwiseAbs().maxCoeff(), 1e-6 * fd.cwiseAbs().maxCoeff()) << "column " << j;
    EXPECT_GT(fd.cwiseAbs().maxCoeff(), 0.0);
  }
  // Without the sliders the stiffness is another: the test sees the plastic elongation.
  BlockStiffness elastic(x.cols(), tissue.mesh.bonds);
  add_wall_spring_stiffness(x, tissue.mesh, law, ramp, std::vector<double>(plastic.size(), 0.0), elastic);
  EXPECT_GT((Eigen::MatrixXd(elastic.matrix()) - K).cwiseAbs().maxCoeff(), 1e-3 * K.cwiseAbs().maxCoeff());
}

// -dP/dV of a cell whose density is Eq 11's backward Euler (implicit_cavity_density) at fixed M_n and a:
// central differences to 1e-5; a = 0 is the sealed value, a drained cell has none.
TEST(CavityPressure, TheIncrementsVolumeStiffnessIsMinusTheDerivativeOfItsPressure) {
  const double V = 1.7e-12, h = 1e-4 * V;  // above the density solve's round-off, far below V
  for (double mass_over_rho0V : {0.98, 1.0, 1.01})
    for (double a : {0.0, 1e-19, 1e-17, 1e-15}) {
      const double M = mass_over_rho0V * 1000 * V;
      const auto P = [&](double volume) { return kEos.pressure(implicit_cavity_density(M, volume, a, kEos)); };
      const double fd = -(P(V + h) - P(V - h)) / (2 * h);
      const double rho = implicit_cavity_density(M, V, a, kEos);
      EXPECT_NEAR(increment_volume_stiffness_Pa_m3(rho, V, a, kEos), fd, 1e-5 * std::abs(fd))
          << "M/(rho0 V) " << mass_over_rho0V << ", a " << a;
      if (a == 0) EXPECT_DOUBLE_EQ(increment_volume_stiffness_Pa_m3(rho, V, a, kEos), cavity_volume_stiffness_Pa_m3(rho, V, kEos));
    }
  EXPECT_EQ(increment_volume_stiffness_Pa_m3(1000, V, INFINITY, kEos), 0.0);
}

// For two cells: solve(r) = (A + s I + sum_c k_c g_c g_c^T)^-1 r to 1e-9, with A the springs' and the
// pressures' stiffness moved by a multiple of I: raised, A is positive definite and s = 0; lowered, the
// cell's free motions and its bonds' untensioned sides are negative, and the shift s > 0 that made it
// factor enters as stated.
TEST(NewtonPreconditioner, SolvesWithTheSparsePartAndEachCellsVolumeSpring) {
  const Params p = small_cell_case({{"fluid", {{"model", "cavity"}}}, {"tissue", {{"cells_x", 2}}}});
  const Tissue tissue = build_tissue(p);
  Simulation sim(p, tissue);
  const Eigen::Matrix3Xd& x = sim.state().wall.x;
  const Eigen::Index n = x.size();
  BlockStiffness stiffness(x.cols(), sim.mesh().bonds);
  add_wall_spring_stiffness(x, sim.mesh(), sim.bond_law(), 1.0, sim.state().bond_plastic_elongation_m, stiffness);
  add_diagonal_shift(1e-2, stiffness);
  add_pressure_follower_stiffness(x, sim.mesh(), {2e5, 3e5}, stiffness);
  const Eigen::SparseMatrix<double>& A = stiffness.matrix();
  const Eigen::VectorXd g = stacked_volume_gradients(sim.surface().vertex_normal);
  const std::vector<double> k_c = {7 * 20e6 / sim.surface().cell_volume_m3[0], 0.0};  // the second cell drained
  const Eigen::VectorXd r = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0).array().sin();

  Eigen::SparseMatrix<double> identity(n, n);
  identity.setIdentity();
  for (double lowered_N_m : {-1e3, 1e3}) {
    const Eigen::SparseMatrix<double> factored = A - lowered_N_m * identity;
    NewtonPreconditioner preconditioner;
    preconditioner.factor(factored, g, sim.cells(), k_c);
    if (lowered_N_m < 0) EXPECT_EQ(preconditioner.shift_N_m(), 0.0);
    else EXPECT_GT(preconditioner.shift_N_m(), 0.0);
    const Eigen::VectorXd expected =
        dense_with_volume_springs(factored, preconditioner.shift_N_m(), g, sim.cells(), k_c).ldlt().solve(r);
    EXPECT_LT((preconditioner.solve(r) - expected).norm(), 1e-9 * expected.norm()) << "lowered by " << lowered_N_m;
  }
}

// Cells joined by a tissue's contacts (a block between a particle of each): solve(r) = (A + sum_c k_c g_c
// g_c^T)^-1 r to 1e-9 through the rank-C update, where the per-cell update no longer holds; and on cells
// that nothing joins, the rank-C update gives the per-cell one's answer.
TEST(NewtonPreconditioner, SolvesWithEveryCellsVolumeSpringWhereContactsJoinTheCells) {
  const Params p = small_cell_case({{"fluid", {{"model", "cavity"}}}, {"tissue", {{"cells_x", 2}}}});
  const Tissue tissue = build_tissue(p);
  Simulation sim(p, tissue);
  const Eigen::Matrix3Xd& x = sim.state().wall.x;
  const Eigen::Index n = x.size();
  const int a = sim.cells().wall[0], b = sim.cells().wall[1] + 7;  // one particle of each cell
  std::vector<std::array<int, 2>> pairs = sim.mesh().bonds;
  pairs.push_back({a, b});
  const Eigen::VectorXd g = stacked_volume_gradients(sim.surface().vertex_normal);
  const std::vector<double> k_c = {7 * 20e6 / sim.surface().cell_volume_m3[0], 3 * 20e6 / sim.surface().cell_volume_m3[1]};
  const Eigen::VectorXd r = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0).array().sin();
  for (double joining_N_m : {0.0, 1e3}) {
    BlockStiffness stiffness(x.cols(), pairs);
    add_wall_spring_stiffness(x, sim.mesh(), sim.bond_law(), 1.0, sim.state().bond_plastic_elongation_m, stiffness);
    add_diagonal_shift(1e2, stiffness);
    add_pressure_follower_stiffness(x, sim.mesh(), {2e5, 3e5}, stiffness);
    const Eigen::Vector3d line = (x.col(b) - x.col(a)).normalized();
    const Eigen::Matrix3d block = joining_N_m * line * line.transpose();
    stiffness.add_pair(a, b, block);
    NewtonPreconditioner joined;
    joined.factor(stiffness.matrix(), g, sim.cells(), k_c, true);
    const Eigen::VectorXd expected =
        dense_with_volume_springs(stiffness.matrix(), joined.shift_N_m(), g, sim.cells(), k_c).ldlt().solve(r);
    EXPECT_LT((joined.solve(r) - expected).norm(), 1e-9 * expected.norm()) << "joined by " << joining_N_m << " N/m";
    if (joining_N_m == 0) {
      NewtonPreconditioner per_cell;
      per_cell.factor(stiffness.matrix(), g, sim.cells(), k_c, false);
      EXPECT_LT((per_cell.solve(r) - joined.solve(r)).norm(), 1e-9 * expected.norm());
    } else {
      NewtonPreconditioner per_cell;  // the per-cell update is not the inverse once the cells are joined
      per_cell.factor(stiffness.matrix(), g, sim.cells(), k_c, false);
      EXPECT_GT((per_cell.solve(r) - expected).norm(), 1e-6 * expected.norm());
    }
  }
}
