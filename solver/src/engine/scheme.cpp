// The scheme of a case (scheme.hpp).
#include "engine/scheme.hpp"

#include "engine/quasi_static.hpp"
#include "engine/simulation.hpp"

namespace cellsim {
namespace {

// Kick-drift-kick of time.dt_ns (model.md §7).
class Leapfrog final : public Scheme {
 public:
  explicit Leapfrog(Simulation& sim) : sim_(sim) {}
  void step() override { sim_.step(); }
  void start_compression() override { sim_.start_compression(); }

 private:
  Simulation& sim_;
};

}  // namespace

std::unique_ptr<Scheme> make_scheme(Simulation& sim) {
  if (sim.params().time_scheme == kQuasiStatic) return std::make_unique<QuasiStaticScheme>(sim);
  return std::make_unique<Leapfrog>(sim);
}

}  // namespace cellsim
