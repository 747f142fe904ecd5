#pragma once
// XDMF sidecars so ParaView (and meshio) open the HDF5 snapshots: one file for the wall
// (triangles) and one for the fluid (points), each a temporal collection of snapshots.
#include <string>
#include <vector>

namespace cellsim {

struct SnapshotInfo {
  std::string group;  // e.g. "/snapshots/000100"
  double time_s;
};

// XML text of the sidecar for particle `kind` ("wall" or "fluid"); h5_name is the HDF5 file's
// name relative to the sidecar.
std::string xdmf_text(const std::string& kind, const std::string& h5_name, const std::vector<SnapshotInfo>& snapshots,
                      long n_particles, long n_triangles);

}  // namespace cellsim
