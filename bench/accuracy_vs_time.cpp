// accuracy_vs_time: distances and timings of every query kind x root policy x precision.
//
// Driven by bench/accuracy_vs_time.py, which writes the cases, computes 50-digit references and
// turns this program's output into docs/reports/accuracy_vs_time.md and the plots.
//
//   accuracy_vs_time CASES OUT [--min-time SECONDS] [--kinds a,b,...]
//
// CASES is a text file, one case per line:
//     <kind> <group> <count> <v1> ... <v_count>
// kind:  a name of the kind table below (e.g. "line-circle");
// group: 0 random, 1 hard, 2 sweep (sweeps are evaluated but not timed);
// values: doubles, written so that they round-trip exactly (Python's repr). The float run rounds
// them to float (to nearest), the long double run extends them exactly.
// Value layout, the first shape then the second:
//     point x y z | line, ray ox oy oz dx dy dz | segment p0 p1 |
//     circle, disk cx cy cz nx ny nz r | bezier k x0 y0 z0 ... (k control points) |
//     arc cx cy cz nx ny nz r sx sy sz angle | annulus cx cy cz nx ny nz inner outer
//
// OUT receives
//     K <kind> <compiled 0/1>                                   one line per kind of the table
//     D <case index> <policy> <precision> <distance: 21 digits> <distance: exact hexfloat>
//                                                               every case x policy x precision
//     T <kind> <group> <policy> <precision> <cases> <ns/query median> <ns/query min> <samples>
// Timing: one sample is a number of passes over every case of (kind, group), sized to take
// about 2 ms; samples are repeated for --min-time seconds (at least 5) and the median (and the
// smallest) time per query is reported. Single-threaded: one core.
//
// Built as one translation unit, or split to compile in parallel (the CMake target does, in
// bench/CMakeLists.txt): with -DCDB_PART=0, 1, 2 a unit holds the float, double, long double
// runners, with -DCDB_PART=3 the driver.
#include "bench_kinds.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace cdb {

using namespace circledist;

// One case as read: kind, group and the values as doubles.
struct Case {
  int index = 0;
  std::string kind;
  int group = 0;
  std::vector<double> values;
};

// ---------------------------------------------------------------------------------------------
// Shape readers: each takes its values from v starting at i and advances i. false when short.
// ---------------------------------------------------------------------------------------------
template <class Real> struct Reader {
  const std::vector<double>& v;
  std::size_t i = 0;
  bool ok = true;

  Real next() {
    if (i >= v.size()) {
      ok = false;
      return Real(0);
    }
    return static_cast<Real>(v[i++]);  // float: round to nearest; long double: exact
  }
  Vec3<Real> vec() {
    const Real x = next(), y = next(), z = next();
    return Vec3<Real>(x, y, z);
  }
  void read(Vec3<Real>& p) { p = vec(); }
  void read(Line3<Real>& l) {
    l.origin = vec();
    l.direction = vec();
  }
  void read(Ray3<Real>& r) {
    r.origin = vec();
    r.direction = vec();
  }
  void read(Segment3<Real>& s) {
    s.p0 = vec();
    s.p1 = vec();
  }
  void read(Circle3<Real>& c) {
    c.center = vec();
    c.normal = vec();
    c.radius = next();
  }
  void read(Disk3<Real>& d) {
    d.center = vec();
    d.normal = vec();
    d.radius = next();
  }
  void read(Arc3<Real>& a) {  // by the constructor, as a C++ caller makes an arc (Arc3::trig)
    const Vec3<Real> center = vec(), normal = vec();
    const Real radius = next();
    const Vec3<Real> start = vec();
    a = Arc3<Real>(center, normal, radius, start, next());
  }
  void read(Annulus3<Real>& a) {
    a.center = vec();
    a.normal = vec();
    a.inner_radius = next();
    a.outer_radius = next();
  }
  void read(BezierCurve3<Real>& b) {
    const int k = int(next());
    if (k < 1 || k > kMaxBezierDegree + 1) {
      ok = false;
      return;
    }
    b.control.resize(3, k);
    for (int j = 0; j < k; ++j) b.control.col(j) = vec();
  }
};

// ---------------------------------------------------------------------------------------------
// The kind table: the kinds of bench_kinds.hpp, each a pair of shape types.
// ---------------------------------------------------------------------------------------------
inline const char* policy_names[] = {"EigenCompanion", "EigenPolished", "Bracketing", "EigenPolynomialSolver"};
inline const char* precision_names[] = {"float", "double", "longdouble"};

struct Output {
  std::FILE* file;
};

inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Distances of every case of one kind, then the timing of each group.
template <class SA, class SB, class Policy> void run_one(const std::vector<const Case*>& cases, const std::string& kind,
                                                         int policy, int precision, double min_time, Output& out) {
  using Real = decltype(circledist::distance(std::declval<const SA&>(), std::declval<const SB&>()));
  struct Item {
    SA a;
    SB b;
    int index, group;
  };
  std::vector<Item> items;
  items.reserve(cases.size());
  for (const Case* c : cases) {
    Reader<Real> r{c->values};
    Item it{};
    r.read(it.a);
    r.read(it.b);
    if (!r.ok) {
      std::fprintf(stderr, "accuracy_vs_time: case %d (%s) has too few values\n", c->index, kind.c_str());
      continue;
    }
    it.index = c->index;
    it.group = c->group;
    items.push_back(it);
  }
  for (const Item& it : items) {
    const Real d = circledist::distance<Policy>(it.a, it.b);
    const long double x = static_cast<long double>(d);
    std::fprintf(out.file, "D %d %s %s %.21Lg %La\n", it.index, policy_names[policy], precision_names[precision], x, x);
  }
  for (int group = 0; group <= 1; ++group) {
    std::vector<Item> set;
    for (const Item& it : items)
      if (it.group == group) set.push_back(it);
    if (set.empty()) continue;
    volatile Real sink = 0;
    auto pass = [&]() {
      Real sum = 0;
      for (const Item& it : set) sum += circledist::distance<Policy>(it.a, it.b);
      sink = sink + sum;
    };
    // Warm-up pass, then passes per sample sized to about 2 ms.
    auto t0 = std::chrono::steady_clock::now();
    pass();
    const double one = std::max(seconds_since(t0), 1e-9);
    const int passes = std::max(1, int(std::ceil(2e-3 / one)));
    std::vector<double> per_query;
    const auto start = std::chrono::steady_clock::now();
    while (per_query.size() < 5 || (seconds_since(start) < min_time && per_query.size() < 1000)) {
      t0 = std::chrono::steady_clock::now();
      for (int p = 0; p < passes; ++p) pass();
      per_query.push_back(seconds_since(t0) * 1e9 / (double(passes) * double(set.size())));
    }
    std::sort(per_query.begin(), per_query.end());
    const std::size_t n = per_query.size();
    const double median = n % 2 ? per_query[n / 2] : (per_query[n / 2 - 1] + per_query[n / 2]) / 2;
    std::fprintf(out.file, "T %s %d %s %s %zu %.4f %.4f %zu\n", kind.c_str(), group, policy_names[policy],
                 precision_names[precision], set.size(), median, per_query.front(), n);
  }
}

template <class SA, class SB> void run_precision(const std::vector<const Case*>& cases, const std::string& kind,
                                                 int precision, double min_time, Output& out) {
  run_one<SA, SB, EigenCompanion>(cases, kind, 0, precision, min_time, out);
  run_one<SA, SB, EigenPolished>(cases, kind, 1, precision, min_time, out);
  run_one<SA, SB, Bracketing>(cases, kind, 2, precision, min_time, out);
  run_one<SA, SB, EigenPolynomialSolver>(cases, kind, 3, precision, min_time, out);
}

using Runner = void (*)(const std::vector<const Case*>&, const std::string&, int, double, Output&);

// Every kind the benchmark knows, in table order.
struct KindNames {
  std::vector<std::string>& names;
  template <class A, class B> void add(const char* name) { names.push_back(name); }
};
inline std::vector<std::string> all_kind_names() {
  std::vector<std::string> names;
  circledist::bench::for_each_kind<double>(KindNames{names});
  return names;
}

// The kind table for one precision.
struct KindAdder {
  std::map<std::string, Runner>& table;
  template <class A, class B> void add(const char* name) { table[name] = &run_precision<A, B>; }
};
template <class Real> std::map<std::string, Runner> kind_table() {
  std::map<std::string, Runner> t;
  circledist::bench::for_each_kind<Real>(KindAdder{t});
  return t;
}

// The build may split the program by precision to compile in parallel: CDB_PART = 0 (float),
// 1 (double), 2 (long double) compile one precision's runners, 3 the driver; without CDB_PART
// everything is one translation unit.
std::map<std::string, Runner> float_table();
std::map<std::string, Runner> double_table();
std::map<std::string, Runner> long_double_table();

#if !defined(CDB_PART) || CDB_PART == 0
std::map<std::string, Runner> float_table() { return kind_table<float>(); }
#endif
#if !defined(CDB_PART) || CDB_PART == 1
std::map<std::string, Runner> double_table() { return kind_table<double>(); }
#endif
#if !defined(CDB_PART) || CDB_PART == 2
std::map<std::string, Runner> long_double_table() { return kind_table<long double>(); }
#endif

#if !defined(CDB_PART) || CDB_PART == 3
std::vector<Case> read_cases(const char* path) {
  std::ifstream in(path);
  if (!in) {
    std::fprintf(stderr, "accuracy_vs_time: cannot read %s\n", path);
    std::exit(2);
  }
  std::vector<Case> out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    Case c;
    int count = 0;
    if (!(s >> c.kind >> c.group >> count)) continue;
    c.values.reserve(count);
    std::string token;
    for (int i = 0; i < count && (s >> token); ++i) c.values.push_back(std::strtod(token.c_str(), nullptr));
    c.index = int(out.size());
    out.push_back(std::move(c));
  }
  return out;
}

#endif  // the driver (read_cases)

}  // namespace cdb

#if !defined(CDB_PART) || CDB_PART == 3

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s CASES OUT [--min-time SECONDS] [--kinds a,b,...]\n", argv[0]);
    return 2;
  }
  double min_time = 0.05;
  std::vector<std::string> only;
  for (int i = 3; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--min-time" && i + 1 < argc) {
      min_time = std::atof(argv[++i]);
    } else if (arg == "--kinds" && i + 1 < argc) {
      std::stringstream s(argv[++i]);
      std::string k;
      while (std::getline(s, k, ',')) only.push_back(k);
    } else {
      std::fprintf(stderr, "accuracy_vs_time: unknown argument %s\n", arg.c_str());
      return 2;
    }
  }
  const std::vector<cdb::Case> cases = cdb::read_cases(argv[1]);
  std::FILE* file = std::fopen(argv[2], "w");
  if (!file) {
    std::fprintf(stderr, "accuracy_vs_time: cannot write %s\n", argv[2]);
    return 2;
  }
  cdb::Output out{file};
  const std::map<std::string, cdb::Runner> tables[3] = {cdb::float_table(), cdb::double_table(),
                                                        cdb::long_double_table()};
  const std::vector<std::string> names = cdb::all_kind_names();
  for (const std::string& name : names) std::fprintf(file, "K %s %d\n", name.c_str(), int(tables[1].count(name)));
  for (const auto& c : cases) {
    if (!tables[1].count(c.kind))
      std::fprintf(stderr, "accuracy_vs_time: kind %s not compiled (case %d)\n", c.kind.c_str(), c.index);
  }
  for (const std::string& name : names) {
    if (!tables[1].count(name)) continue;
    if (!only.empty() && std::find(only.begin(), only.end(), name) == only.end()) continue;
    std::vector<const cdb::Case*> mine;
    for (const auto& c : cases)
      if (c.kind == name) mine.push_back(&c);
    if (mine.empty()) continue;
    std::fprintf(stderr, "accuracy_vs_time: %s (%zu cases)\n", name.c_str(), mine.size());
    for (int precision = 0; precision < 3; ++precision)
      tables[precision].at(name)(mine, name, precision, min_time, out);
    std::fflush(file);
  }
  std::fclose(file);
  return 0;
}

#endif  // the driver
