// The inside-the-wall test used at every record (model.md §4).
#include <gtest/gtest.h>

#include "geometry/containment.hpp"
#include "geometry/hull.hpp"

using namespace cellsim;

TEST(Containment, FindsTheParticleOutsideTheWall) {
  const Eigen::Matrix3Xd wall = fibonacci_sphere(400, 50e-6);
  const WallMesh mesh = build_wall_mesh(wall, convex_hull_triangles(wall));
  Eigen::Matrix3Xd fluid(3, 5);
  fluid << 0, 40e-6, -30e-6, 0, 10e-6,  //
      0, 0, 20e-6, -45e-6, 10e-6,       //
      0, 10e-6, -20e-6, 0, 10e-6;
  EXPECT_EQ(first_particle_outside(fluid, wall, mesh), -1);
  fluid.col(3) << 0, -52e-6, 0;  // just beyond the wall, within its xy footprint
  EXPECT_EQ(first_particle_outside(fluid, wall, mesh), 3);
  fluid.col(3) << 0, 0, 60e-6;  // straight above the cell
  EXPECT_EQ(first_particle_outside(fluid, wall, mesh), 3);
  fluid.col(3) << 0, 0, -49e-6;  // near the bottom pole, inside
  EXPECT_EQ(first_particle_outside(fluid, wall, mesh), -1);
  // Inside the wall's bounding box but outside the wall: only the ray parity can tell. The flat
  // triangles lie within the sphere, so 0.3 um beyond R is outside and 1 um within is inside.
  const Eigen::Vector3d diagonal = Eigen::Vector3d(1, 1, 1).normalized();
  for (const Eigen::Vector3d& dir : {diagonal, Eigen::Vector3d(-0.6, 0.48, -0.64), Eigen::Vector3d(0.8, -0.6, 0.0)}) {
    fluid.col(3) = 50.3e-6 * dir;
    EXPECT_EQ(first_particle_outside(fluid, wall, mesh), 3) << dir.transpose();
    fluid.col(3) = 49e-6 * dir;
    EXPECT_EQ(first_particle_outside(fluid, wall, mesh), -1) << dir.transpose();
  }
  fluid.col(3) << 35e-6, 35e-6, 35e-6;  // a corner of the bounding box, far outside the sphere
  EXPECT_EQ(first_particle_outside(fluid, wall, mesh), 3);
}

// A ray through a wall vertex must count exactly one of the triangles around it (the tie rule), also
// where the compiler fuses the edge function's products (a fused multiply-add leaves a rounding error
// where the two products are equal, and the tie rule did not apply).
TEST(Containment, ARayThroughAWallVertexCountsItOnce) {
  const Eigen::Matrix3Xd wall = fibonacci_sphere(400, 50e-6);
  const WallMesh mesh = build_wall_mesh(wall, convex_hull_triangles(wall));
  const ClosedSurface surface(wall, mesh, 0);
  int tested = 0;
  for (Eigen::Index v = 0; v < wall.cols(); ++v) {
    if (std::abs(wall(2, v)) < 10e-6) continue;  // near the equator the ray grazes the wall
    const Eigen::Vector3d below_in(wall(0, v), wall(1, v), 0.5 * wall(2, v));  // inside, straight under or over v
    const Eigen::Vector3d below_out(wall(0, v), wall(1, v), -60e-6);           // under the whole cell
    EXPECT_TRUE(surface.contains(below_in)) << "vertex " << v;
    EXPECT_FALSE(surface.contains(below_out)) << "vertex " << v;
    ++tested;
  }
  EXPECT_GT(tested, 300);
}
