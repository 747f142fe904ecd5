#pragma once
// Running a case: build the cell, dry, compress, record, write the result file.
#include <string>

#include "core/params.hpp"

namespace cellsim {

struct RunOptions {
  std::string output_path;
  std::string from_path;  // continue from the last state in this result file, at rest or dried (--from)
  bool quiet = false;     // no progress lines on stderr
  int threads = 1;        // for the fluid pair loop (threads.hpp)
};

// Throws InputError before writing anything under the output's final name, NumericalFailure
// after leaving OUT.partial marked incomplete.
void run_case(const Params& p, const RunOptions& options);

}  // namespace cellsim
