#pragma once
// The two ways a run ends early, each with its exit code (see README "Exit codes").
#include <stdexcept>
#include <string>

namespace cellsim {

// Bad input: the case, an override, a file or an output path. Exit code 2, nothing written.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The simulation blew up or broke a model invariant. Exit code 3, output marked incomplete.
struct NumericalFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

inline constexpr int kExitInputError = 2;
inline constexpr int kExitNumericalFailure = 3;

}  // namespace cellsim
