#pragma once
// The ways a run ends early, each with its exit code (see README "Exit codes").
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

// The file system refused (permissions, a full disk, a lock HDF5 cannot take): the case is fine,
// the place is not. Exit code 4; the message says what HDF5 and the system said.
struct FileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

inline constexpr int kExitInputError = 2;
inline constexpr int kExitNumericalFailure = 3;
inline constexpr int kExitFileError = 4;

}  // namespace cellsim
