#pragma once
// The two schemes that advance a run (time.scheme), peers over the same forces: the leapfrog
// (Simulation::step, model.md §7) and the quasi-static scheme (quasi_static.hpp, model.md §11).
// `cellsim run` and `cellsim bench` both make theirs here, so a bench times the scheme its case asks for.
#include <memory>

namespace cellsim {

class Simulation;

class Scheme {
 public:
  virtual ~Scheme() = default;
  // One step of time.dt_ns.
  virtual void step() = 0;
  // Starts the compression (Simulation::start_compression) and what the scheme holds from there.
  virtual void start_compression() = 0;
};

// The scheme of sim's case (time.scheme), stepping sim.
std::unique_ptr<Scheme> make_scheme(Simulation& sim);

}  // namespace cellsim
