#include <circledist/line_circle.hpp>

#include <cstdio>

int main() {
  using V = circledist::Vec3<double>;
  const circledist::Circle3<double> ring{V(0, 0, 0), V(0, 0, 1), 1.0};
  const circledist::Line3<double> line{V(-3, 1, 0.5), V(1, 0, 0)};  // passes 0.5 above the rim

  std::printf("distance %.6f\n", circledist::distance(line, ring));
  const auto r = circledist::closest_points(line, ring);
  std::printf("on the line (%.3f, %.3f, %.3f), on the circle (%.3f, %.3f, %.3f), unique %d\n", r.point_a.x(),
              r.point_a.y(), r.point_a.z(), r.point_b.x(), r.point_b.y(), r.point_b.z(), int(r.unique));
  return r.distance > 0.49 && r.distance < 0.51 ? 0 : 1;
}
