#pragma once
// Wall-clock time spent in each phase of the step, for `cellsim bench` (a few clock reads per
// step: negligible next to the work they measure).
#include <array>
#include <chrono>

namespace cellsim {

enum class Phase : int {
  Geometry, Neighbours, DensityDrift, FluidPairs, MassTransfer, WallBonds, Bending, CellContact, WallFluid, Plates, Integration,
  Recording, Count
};
inline constexpr const char* kPhaseNames[] = {"geometry (area, volume, h)", "neighbour lists",
                                              "density in the drift (continuity pass)",
                                              "fluid pairs (continuity, pressure, viscous)", "mass transfer",
                                              "wall bonds (stiff, contraction, damping)", "bending",
                                              "between cells (contact, middle lamella)",
                                              "wall-fluid (coupling)", "plates", "integration and checks",
                                              "recording (measures, containment)"};

class PhaseTimer {
 public:
  using Clock = std::chrono::steady_clock;
  void start() { last_ = Clock::now(); }
  void lap(Phase p) {
    const auto now = Clock::now();
    seconds_[static_cast<int>(p)] += std::chrono::duration<double>(now - last_).count();
    last_ = now;
  }
  double seconds(Phase p) const { return seconds_[static_cast<int>(p)]; }
  void reset() { seconds_.fill(0.0); }

 private:
  std::array<double, static_cast<int>(Phase::Count)> seconds_{};
  Clock::time_point last_;
};

}  // namespace cellsim
