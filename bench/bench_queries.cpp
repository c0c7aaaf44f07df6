// bench_queries: the scalar C++ path, circledist::distance(a, b) in a loop on one core in double,
// timed on exactly the inputs bench_queries.py times in Python.
//
//   bench_queries INPUT OUTPUT [--min-time SECONDS]
//
// INPUT (written by bench_queries.py), little-endian:
//     8 bytes  magic "CDBQIN01"
//     u64      number of kinds
//     per kind: u64 name length, the name (e.g. "line-disk"), u64 n (queries), u64 w (doubles per
//               query), then n * w doubles, query after query: the first shape's values, then the
//               second's.
// Value layout of one shape:
//     point x y z | line, ray: origin, direction | segment: p0, p1 |
//     circle, disk: center, normal, radius | arc: center, normal, radius, start, angle |
//     annulus: center, normal, inner radius, outer radius | bezier: its control points, x y z each (the count
//     is whatever the other shape leaves of w; two curves have half of w each).
// OUTPUT receives "CDBQOUT1", u64 number of kinds, then per kind the name (as above), u64 n and
// the n distances (0 queries for a kind this build does not know).
// stdout, one line per kind:
//     T <kind> <n> <ns/query median> <ns/query min> <samples> passes|chunks    timed
//     S <kind>                                                                unknown: skipped
// Times are the CPU time of the thread (CLOCK_THREAD_CPUTIME_ID) per query, median of samples.
// The first pass over the n queries gives the distances written and is timed in 10 chunks. If
// it took --min-time seconds (default 0.5) or more, the samples are its chunks but the first
// (warm-up); otherwise full passes are repeated for --min-time (at least 5, at most 200), one
// sample each.
//
// Adding a query kind: one line in bench_kinds.hpp (and a shape reader below if the shape is new).
#include "bench_kinds.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <time.h>  // clock_gettime (POSIX)

namespace {

using Real = double;
using circledist::Vec3;
using Point = Vec3<Real>;
using Line = circledist::Line3<Real>;
using Ray = circledist::Ray3<Real>;
using Segment = circledist::Segment3<Real>;
using Circle = circledist::Circle3<Real>;
using Disk = circledist::Disk3<Real>;
using Arc = circledist::Arc3<Real>;
using Annulus = circledist::Annulus3<Real>;

// ---- shape readers: Width<S>::value doubles per shape (0: variable, takes what is left) ------
template <class S> struct Width;
template <> struct Width<Point> {
  static constexpr int value = 3;
};
template <> struct Width<Line> {
  static constexpr int value = 6;
};
template <> struct Width<Ray> {
  static constexpr int value = 6;
};
template <> struct Width<Segment> {
  static constexpr int value = 6;
};
template <> struct Width<Circle> {
  static constexpr int value = 7;
};
template <> struct Width<Disk> {
  static constexpr int value = 7;
};
template <> struct Width<Arc> {
  static constexpr int value = 11;
};
template <> struct Width<Annulus> {
  static constexpr int value = 8;
};

Vec3<Real> vec(const double* v) { return Vec3<Real>(v[0], v[1], v[2]); }

bool read(Point& p, const double* v, int) {
  p = vec(v);
  return true;
}
bool read(Line& l, const double* v, int) {
  l = {vec(v), vec(v + 3)};
  return true;
}
bool read(Ray& r, const double* v, int) {
  r = {vec(v), vec(v + 3)};
  return true;
}
bool read(Segment& s, const double* v, int) {
  s = {vec(v), vec(v + 3)};
  return true;
}
bool read(Circle& c, const double* v, int) {
  c = {vec(v), vec(v + 3), v[6]};
  return true;
}
bool read(Disk& d, const double* v, int) {
  d = {vec(v), vec(v + 3), v[6]};
  return true;
}
bool read(Arc& a, const double* v, int) {
  a = {vec(v), vec(v + 3), v[6], vec(v + 7), v[10]};
  return true;
}
bool read(Annulus& a, const double* v, int) {
  a = {vec(v), vec(v + 3), v[6], v[7]};
  return true;
}

using Bezier = circledist::BezierCurve3<Real>;
template <> struct Width<Bezier> {
  static constexpr int value = 0;
};
bool read(Bezier& b, const double* v, int width) {
  const int points = width / 3;
  if (width % 3 != 0 || points < 1 || points > circledist::kMaxBezierDegree + 1) return false;
  b.control.resize(3, points);
  for (int j = 0; j < points; ++j) b.control.col(j) = vec(v + 3 * j);
  return true;
}

// ---- input and output files ------------------------------------------------------------------
struct KindData {
  std::string name;
  std::uint64_t n = 0, width = 0;
  std::vector<double> values;
};

[[noreturn]] void fail(const std::string& message) {
  std::fprintf(stderr, "bench_queries: %s\n", message.c_str());
  std::exit(2);
}

std::uint64_t read_u64(std::FILE* f) {
  std::uint64_t x = 0;
  if (std::fread(&x, sizeof x, 1, f) != 1) fail("truncated input");
  return x;
}

std::vector<KindData> read_input(const char* path) {
  std::FILE* f = std::fopen(path, "rb");
  if (!f) fail(std::string("cannot read ") + path);
  char magic[8];
  if (std::fread(magic, 1, 8, f) != 8 || std::memcmp(magic, "CDBQIN01", 8) != 0) fail("bad input magic");
  std::vector<KindData> out(read_u64(f));
  for (KindData& k : out) {
    k.name.resize(read_u64(f));
    if (!k.name.empty() && std::fread(&k.name[0], 1, k.name.size(), f) != k.name.size()) fail("truncated input");
    k.n = read_u64(f);
    k.width = read_u64(f);
    k.values.resize(k.n * k.width);
    if (std::fread(k.values.data(), sizeof(double), k.values.size(), f) != k.values.size()) fail("truncated input");
  }
  std::fclose(f);
  return out;
}

void write_u64(std::FILE* f, std::uint64_t x) { std::fwrite(&x, sizeof x, 1, f); }

// ---- timing ----------------------------------------------------------------------------------
// CPU time of this thread, not wall time: on a shared machine the wall clock also counts the time
// the scheduler gives to other processes. On an idle machine the two agree.
double thread_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

double median_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size();
  return m % 2 ? v[m / 2] : (v[m / 2 - 1] + v[m / 2]) / 2;
}

struct Timing {
  double median_ns = 0, min_ns = 0;
  int samples = 0;
  bool chunked = false;  // one pass, timed in chunks
};

constexpr int kChunks = 10;

template <class A, class B> Timing run(const KindData& data, double min_time, std::vector<double>& distances) {
  struct Item {
    A a;
    B b;
  };
  // A variable-width shape takes what the other leaves; two of them (two curves) share the
  // query's values equally (bench_queries.py draws both with the same number of control points).
  const int width = int(data.width);
  constexpr int fixed_a = Width<A>::value, fixed_b = Width<B>::value;
  const int wb = fixed_b > 0 ? fixed_b : fixed_a > 0 ? width - fixed_a : width / 2;
  const int wa = fixed_a > 0 ? fixed_a : width - wb;
  if (wa <= 0 || wa + wb != width) fail(data.name + ": " + std::to_string(width) + " values per query do not fit");
  const std::size_t n = data.n;
  std::vector<Item> items(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double* v = data.values.data() + i * width;
    if (!read(items[i].a, v, wa) || !read(items[i].b, v + wa, wb)) fail(data.name + ": bad query " + std::to_string(i));
  }
  Timing t;
  if (n == 0) return t;

  // First pass, timed in chunks: these are the distances written. A kind slow enough that this
  // pass alone takes min_time is timed by it (the median over its chunks, the first chunk
  // being the warm-up); faster kinds by repeated full passes.
  distances.resize(n);
  std::vector<double> chunk_ns;
  const double start = thread_seconds();
  for (int c = 0; c < kChunks; ++c) {
    const std::size_t lo = n * c / kChunks, hi = n * (c + 1) / kChunks;
    const double t0 = thread_seconds();
    for (std::size_t i = lo; i < hi; ++i) distances[i] = circledist::distance(items[i].a, items[i].b);
    if (hi > lo && c > 0) chunk_ns.push_back((thread_seconds() - t0) * 1e9 / double(hi - lo));
  }
  const double first = std::max(thread_seconds() - start, 1e-9);
  if (first >= min_time && !chunk_ns.empty()) {
    t.median_ns = median_of(chunk_ns);
    t.min_ns = *std::min_element(chunk_ns.begin(), chunk_ns.end());
    t.samples = int(chunk_ns.size());
    t.chunked = true;
    return t;
  }

  volatile Real sink = 0;
  const int passes = std::min(200, std::max(5, int(std::ceil(min_time / first))));
  std::vector<double> per_query;
  for (int p = 0; p < passes; ++p) {
    const double t0 = thread_seconds();
    Real sum = 0;
    for (const Item& it : items) sum += circledist::distance(it.a, it.b);
    per_query.push_back((thread_seconds() - t0) * 1e9 / double(n));
    sink = sink + sum;
  }
  t.median_ns = median_of(per_query);
  t.min_ns = *std::min_element(per_query.begin(), per_query.end());
  t.samples = int(per_query.size());
  return t;
}

// ---- the kind table --------------------------------------------------------------------------
using Runner = Timing (*)(const KindData&, double, std::vector<double>&);
struct KindEntry {
  const char* name;
  Runner run;
};

struct KindAdder {
  std::vector<KindEntry>& table;
  template <class A, class B> void add(const char* name) { table.push_back({name, &run<A, B>}); }
};

std::vector<KindEntry> kind_table() {
  std::vector<KindEntry> t;
  circledist::bench::for_each_kind<Real>(KindAdder{t});
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s INPUT OUTPUT [--min-time SECONDS]\n", argv[0]);
    return 2;
  }
  double min_time = 0.5;
  for (int i = 3; i < argc; ++i) {
    if (std::strcmp(argv[i], "--min-time") == 0 && i + 1 < argc) {
      min_time = std::atof(argv[++i]);
    } else {
      fail(std::string("unknown argument ") + argv[i]);
    }
  }
  const std::vector<KindData> kinds = read_input(argv[1]);
  const std::vector<KindEntry> table = kind_table();

  std::FILE* out = std::fopen(argv[2], "wb");
  if (!out) fail(std::string("cannot write ") + argv[2]);
  std::fwrite("CDBQOUT1", 1, 8, out);
  write_u64(out, kinds.size());
  for (const KindData& k : kinds) {
    const auto entry = std::find_if(table.begin(), table.end(), [&](const KindEntry& e) { return k.name == e.name; });
    std::vector<double> distances;
    if (entry == table.end()) {
      std::printf("S %s\n", k.name.c_str());
    } else {
      const Timing t = entry->run(k, min_time, distances);
      std::printf("T %s %llu %.4f %.4f %d %s\n", k.name.c_str(), static_cast<unsigned long long>(k.n), t.median_ns,
                  t.min_ns, t.samples, t.chunked ? "chunks" : "passes");
    }
    std::fflush(stdout);
    write_u64(out, k.name.size());
    std::fwrite(k.name.data(), 1, k.name.size(), out);
    write_u64(out, distances.size());
    std::fwrite(distances.data(), sizeof(double), distances.size(), out);
  }
  std::fclose(out);
  return 0;
}
