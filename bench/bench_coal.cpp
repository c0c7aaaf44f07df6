// bench_coal: disk-disk in C++, circledist::distance against coal::distance (GJK) on the same
// disk pairs, timed alternately in one process. Built and run by bench_coal.py (which finds
// coal's headers and library in the coal wheel's prefix); not part of the CMake build.
//
//   bench_coal INPUT OUTPUT REPEATS TOLERANCE...
//
// INPUT, little-endian: u64 n, then n pairs of 14 doubles (disk A: center, normal, radius; disk
// B: the same). A TOLERANCE of 0 is the DistanceRequest's default gjk_tolerance.
// OUTPUT: per row (circledist, then each tolerance) the n distances as doubles.
// stdout, one line per row: "<row> <ns per pair>" (the least over REPEATS passes of a full pass's
// thread CPU time, over the n pairs; the rows' passes alternate within each repeat), then
// "default_tolerance <value>".
// A disk in coal is a Cylinder of radius r and height 0, placed by a Transform3s whose rotation
// takes z to the disk's normal (bench_coal.py, rotation_to: the same construction).
#include <circledist/disk_disk.hpp>
#include <circledist/query.hpp>

#include <coal/distance.h>
#include <coal/shape/geometric_shapes.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include <time.h>  // clock_gettime (POSIX)

namespace {

using V = Eigen::Vector3d;

double thread_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

Eigen::Matrix3d rotation_to(const V& normal) {
  const V w = normal.normalized();
  const V helper = std::abs(w.x()) < 0.9 ? V(1, 0, 0) : V(0, 1, 0);
  const V u = helper.cross(w).normalized();
  Eigen::Matrix3d r;
  r.col(0) = u;
  r.col(1) = w.cross(u);
  r.col(2) = w;
  return r;
}

[[noreturn]] void fail(const char* message) {
  std::fprintf(stderr, "bench_coal: %s\n", message);
  std::exit(2);
}

struct CoalDisk {
  std::shared_ptr<coal::Cylinder> shape;
  coal::Transform3s placement;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 5) fail("usage: bench_coal INPUT OUTPUT REPEATS TOLERANCE...");
  const int repeats = std::max(1, std::atoi(argv[3]));
  std::vector<double> tolerances;
  for (int i = 4; i < argc; ++i) tolerances.push_back(std::atof(argv[i]));

  std::FILE* in = std::fopen(argv[1], "rb");
  if (!in) fail("cannot read the input");
  std::uint64_t n = 0;
  if (std::fread(&n, sizeof n, 1, in) != 1) fail("truncated input");
  std::vector<double> values(n * 14);
  if (std::fread(values.data(), sizeof(double), values.size(), in) != values.size()) fail("truncated input");
  std::fclose(in);

  std::vector<circledist::Disk3<double>> a(n), b(n);
  std::vector<CoalDisk> ca(n), cb(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double* v = values.data() + 14 * i;
    for (int k = 0; k < 2; ++k, v += 7) {
      const V center(v[0], v[1], v[2]), normal(v[3], v[4], v[5]);
      (k ? b : a)[i] = {center, normal, v[6]};
      (k ? cb : ca)[i] = {std::make_shared<coal::Cylinder>(v[6], 0.0), coal::Transform3s(rotation_to(normal), center)};
    }
  }

  const double default_tolerance = coal::DistanceRequest().gjk_tolerance;
  const std::size_t rows = 1 + tolerances.size();
  std::vector<std::vector<double>> out(rows, std::vector<double>(n));
  std::vector<double> best(rows, 1e300);
  std::vector<coal::DistanceRequest> requests(tolerances.size());
  for (std::size_t j = 0; j < tolerances.size(); ++j)
    if (tolerances[j] > 0) requests[j].gjk_tolerance = tolerances[j];
  coal::DistanceResult result;
  for (int rep = 0; rep < repeats; ++rep) {
    double t0 = thread_seconds();
    for (std::size_t i = 0; i < n; ++i) out[0][i] = circledist::distance(a[i], b[i]);
    best[0] = std::min(best[0], thread_seconds() - t0);
    for (std::size_t j = 0; j < tolerances.size(); ++j) {
      t0 = thread_seconds();
      for (std::size_t i = 0; i < n; ++i) {
        result.clear();
        out[j + 1][i] =
            coal::distance(ca[i].shape.get(), ca[i].placement, cb[i].shape.get(), cb[i].placement, requests[j], result);
      }
      best[j + 1] = std::min(best[j + 1], thread_seconds() - t0);
    }
  }

  std::FILE* o = std::fopen(argv[2], "wb");
  if (!o) fail("cannot write the output");
  for (const auto& row : out) std::fwrite(row.data(), sizeof(double), row.size(), o);
  std::fclose(o);
  std::printf("circledist %.3f\n", 1e9 * best[0] / double(n));
  for (std::size_t j = 0; j < tolerances.size(); ++j) std::printf("coal %.3f\n", 1e9 * best[j + 1] / double(n));
  std::printf("default_tolerance %.17g\n", default_tolerance);
  return 0;
}
