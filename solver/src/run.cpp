#include "run.hpp"

#include <vector>

#include "case_file.hpp"
#include "cell.hpp"
#include "errors.hpp"
#include "measures.hpp"
#include "result_file.hpp"

namespace cellsim {
namespace {

State initial_state(const Cell& cell, const Params& p) {
  State s;
  s.fluid.x = cell.fluid_x;
  s.fluid.v = Eigen::Matrix3Xd::Zero(3, cell.fluid_x.cols());
  s.fluid.m = Eigen::VectorXd::Constant(cell.fluid_x.cols(), cell.fluid_mass_kg);
  s.fluid.rho = Eigen::VectorXd::Constant(cell.fluid_x.cols(), p.fluid_density_kg_m3);
  s.wall.x = cell.wall_x;
  s.wall.v = Eigen::Matrix3Xd::Zero(3, cell.wall_x.cols());
  s.wall.mass_kg = cell.wall_mass_kg;
  s.smoothing_length_m = *p.h0_m;
  s.initial_fluid_mass_kg = s.fluid.m.sum();
  return s;
}

}  // namespace

void run_case(Params p, const RunOptions& options) {
  const Cell cell = build_cell(p);
  if (p.drying_steps > 0 || p.compression_steps > 0)
    throw InputError("drying.steps and compression.steps must be 0 until the physics is implemented");
  ResultFile out(options.output_path);
  out.write_header(case_to_json(p));
  out.write_mesh(cell.mesh, static_cast<long>(p.n_fluid));
  State s = initial_state(cell, p);
  const EquationOfState eos{p.turgor_Pa * p.dryness, p.bulk_modulus_Pa, p.fluid_density_kg_m3, p.eos_exponent};
  std::vector<Record> records{measure(s, cell.mesh, p, eos)};
  out.write_snapshot(s, eos);
  out.complete(records, s);
}

}  // namespace cellsim
