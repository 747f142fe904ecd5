// The closed cell's follower stiffness (cavity_pressure.hpp).
#include "physics/cavity_pressure.hpp"

#include <array>

namespace cellsim {
namespace {

// [v]x, the cross product with v as a matrix: [v]x w = v x w.
Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

}  // namespace

// V = sum over triangles (a, b, c) of x_a . (x_b x x_c) / 6, so d2V / dx_a dx_b = -[x_c]x / 6 (cyclic), and
// the potential's -P V gives P / 6 [x_c]x; (b, a) is its transpose. A closed surface's sum does not depend
// on the origin: each cell's is taken at its first triangle's first corner, for round-off.
void add_pressure_follower_stiffness(const Eigen::Matrix3Xd& x, const WallMesh& mesh,
                                     const std::vector<double>& cell_pressure_Pa, BlockStiffness& K) {
  for (int cell = 0; cell < mesh.cells(); ++cell) {
    const double sixth_P = cell_pressure_Pa[static_cast<std::size_t>(cell)] / 6.0;
    const Eigen::Vector3d origin = x.col(mesh.triangles[static_cast<std::size_t>(mesh.cell_triangles[cell])][0]);
    for (int t = mesh.cell_triangles[cell]; t < mesh.cell_triangles[cell + 1]; ++t) {
      const std::array<int, 3>& corner = mesh.triangles[static_cast<std::size_t>(t)];
      for (int i = 0; i < 3; ++i) {
        const int a = corner[i], b = corner[(i + 1) % 3], c = corner[(i + 2) % 3];
        const Eigen::Matrix3d block = sixth_P * cross_matrix(x.col(c) - origin);
        K.add(a, b, block);
        K.add(b, a, block.transpose());
      }
    }
  }
}

}  // namespace cellsim
