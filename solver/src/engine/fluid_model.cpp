#include "engine/fluid_model.hpp"

#include "engine/sph_fluid.hpp"

namespace cellsim {

std::unique_ptr<FluidModel> make_fluid_model(const Params& p, const CellRanges& cells, const PropertyFactors& factors) {
  return std::make_unique<SphFluid>(p, cells, factors);
}

}  // namespace cellsim
