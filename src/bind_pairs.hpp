// Python bindings of the all-pairs queries: pairs_within(a, b, d) and nearest(a, b, k) over two
// batches of any kinds, and the broadphase object circledist.Scene culls with. The culling is
// cpp/include/circledist/broadphase.hpp's; the candidates it keeps are gathered into new batches
// and answered by the module's own distance kernels (the path distance() takes), so every
// distance is the one distance() gives, to the bit, and no geometry is written here.
// Included by _core.cpp after its helpers (pairs(), Argument, Choice, with_call()).
#pragma once

#include "float32.hpp"

#include <circledist/broadphase.hpp>

#include <algorithm>
#include <cmath>
#include <exception>
#include <optional>
#include <string>
#include <system_error>
#include <thread>
#include <type_traits>
#include <vector>

namespace {

using Volumes = std::vector<Volume<double>>;
using PairList = BroadPairs;

// Where each field of a shape keeps the element of a flat index of the shape's batch: fields
// broadcast within a shape (a scalar radius for a batch of centers), so a field's element is the
// flat index itself (full-size fields), 0 (one value), or a walk over the batch's dimensions.
struct FieldElements {
  enum class Mode { Full, One, Strided };
  struct Map {
    Mode mode;
    std::vector<Index> strides;  // elements per step along each batch dimension (Strided)
  };
  BatchShape batch;
  std::vector<Map> maps;

  explicit FieldElements(const Shape& s) : batch(s.batch) {
    for (const Field& f : s.fields) {
      Map m{Mode::Strided, std::vector<Index>(batch.size(), 0)};
      if (f.batch.empty()) {
        m.mode = Mode::One;
      } else if (f.batch == batch) {
        m.mode = Mode::Full;
      } else {
        Index step = 1;
        for (size_t k = 0; k < f.batch.size(); ++k) {
          const size_t d = batch.size() - 1 - k;
          const Index extent = f.batch[f.batch.size() - 1 - k];
          m.strides[d] = extent == 1 ? 0 : step;
          step *= extent;
        }
      }
      maps.push_back(std::move(m));
    }
  }

  Index of(size_t field, Index flat) const {
    const Map& m = maps[field];
    if (m.mode == Mode::Full) return flat;
    if (m.mode == Mode::One) return 0;
    Index at = 0;
    for (size_t d = batch.size(); d-- > 0;) {
      at += (flat % batch[d]) * m.strides[d];
      flat /= batch[d];
    }
    return at;
  }
};

Index flat_size(const Shape& s) {
  Index n = 1;
  for (const Index d : s.batch) n *= d;
  return n;
}

// The volumes of the elements [begin, end) of a shape's batch, in double (the float64 values of
// every field: a long-double or float32 query's shapes differ from them by far less than the
// culling margin).
template <class S> void fill_volumes(const Shape& s, const FieldElements& e, Index begin, Index end, Volume<double>* out) {
  const size_t nf = s.fields.size();
  std::array<const double*, kMaxShapeFields> ptr{};
  for (Index i = begin; i < end; ++i) {
    for (size_t f = 0; f < nf; ++f) ptr[f] = s.fields[f].data() + e.of(f, i) * s.fields[f].width;
    out[i] = circledist::volume(ShapeTraits<S>::make(ptr.data(), s.points), *ptr[nf - 1]);
  }
}

void fill_volumes(const Shape& s, Index begin, Index end, Volume<double>* out) {
  const FieldElements e(s);
  switch (s.kind) {
    case kPoint: return fill_volumes<Vec3<double>>(s, e, begin, end, out);
    case kLine: return fill_volumes<Line3<double>>(s, e, begin, end, out);
    case kRay: return fill_volumes<Ray3<double>>(s, e, begin, end, out);
    case kSegment: return fill_volumes<Segment3<double>>(s, e, begin, end, out);
    case kCircle: return fill_volumes<Circle3<double>>(s, e, begin, end, out);
    case kDisk: return fill_volumes<Disk3<double>>(s, e, begin, end, out);
    default: return fill_volumes<BezierCurve3<double>>(s, e, begin, end, out);
  }
}

// The volumes of several shapes' elements, one after the other (flat indices, in order).
Volumes volumes_of(const std::vector<const Shape*>& shapes, int workers) {
  Index total = 0;
  for (const Shape* s : shapes) total += flat_size(*s);
  Volumes out(static_cast<size_t>(total));
  Index at = 0;
  for (const Shape* s : shapes) {
    Volume<double>* base = out.data() + at;
    run_released(flat_size(*s), workers, [&](Index begin, Index end) { fill_volumes(*s, begin, end, base); });
    at += flat_size(*s);
  }
  return out;
}

// The hierarchy over a set's volumes, built without the GIL on up to `workers` threads.
BoundingVolumeHierarchy<double> tree_of(Volumes volumes, int workers) {
  py::gil_scoped_release release;
  return BoundingVolumeHierarchy<double>(std::move(volumes), 4, workers);
}

// The culling of queries a against a set b: a's volumes, their spatial order and scale, and the
// hierarchy over b's volumes. With workers to spare, a's side is made on a thread of its own
// while b's tree is built on the workers, so that each side's steps that one thread takes (the
// allocations, the tree's top, the order's last merge) run beside the other's work. Neither side
// checks for Ctrl-C: milliseconds of work.
struct Culling {
  Volumes va;
  std::vector<BroadIndex> order;
  double scale_a = 0;
  BoundingVolumeHierarchy<double> tree;

  Culling(const Shape& a, const Shape& b, int workers) {
    const auto volumes = [](const Shape& s, int threads) {
      Volumes out(static_cast<size_t>(flat_size(s)));
      run_in_chunks(flat_size(s), threads, [&](Index begin, Index end) { fill_volumes(s, begin, end, out.data()); },
                    [](Index) { return false; });
      return out;
    };
    const auto side_a = [&](int threads) {
      va = volumes(a, threads);
      order = spatial_order(va, threads);
      scale_a = scale_of(va);
    };
    py::gil_scoped_release release;
    std::thread thread;
    std::exception_ptr failure;
    if (workers > 1) {
      try {
        thread = std::thread([&] {
          try {
            side_a(1);
          } catch (...) {
            failure = std::current_exception();
          }
        });
      } catch (const std::system_error&) {  // no thread to be had: one side after the other
      }
    }
    if (!thread.joinable()) side_a(workers);
    try {
      tree = BoundingVolumeHierarchy<double>(volumes(b, workers), 4, workers);
    } catch (...) {
      if (thread.joinable()) thread.join();
      throw;
    }
    if (thread.joinable()) thread.join();
    if (failure) std::rethrow_exception(failure);
  }
};

// progress= of the all-pairs queries: the work is several stages run one after the other (the
// search for candidates over a's shapes, the candidates' exact distances, ...), each of which
// reports (done, total) of its own through run_released. The caller sees one count: `stages`
// times len(a) steps, each stage worth len(a) of them; stage(s) is the callable a stage reports
// to, which scales its count into stage s's share. Repeated values are not passed on, so the
// caller sees (total, total) once, at the end (finish()).
struct StagedProgress {
  py::object user;  // None, or progress(done, total)
  Index per_stage, total;
  std::shared_ptr<Index> last = std::make_shared<Index>(-1);

  StagedProgress(py::object progress, int stages, Index n) : user(std::move(progress)), per_stage(n), total(stages * n) {}

  // A callable progress(done, of) for stage s: it reports base + within(done, of) of `total` to
  // the caller's progress, each value once; None when the caller asked for no progress.
  template <class Within> py::object reporter(int s, Within within) const {
    if (user.is_none()) return py::none();
    return py::cpp_function([user = user, last = last, base = s * per_stage, total = total, within](Index done, Index of) {
      const Index scaled = base + within(done, of);
      if (scaled == *last) return;
      *last = scaled;
      user(scaled, total);
    });
  }
  // What stage s (0-based) reports to. Not part(s, 0, 1, 1): that rounds per_stage * (done / of)
  // where this rounds per_stage * done / of (49 * (1 / 49) < 1), and reports the stage's start,
  // not its end, for of = 0.
  py::object stage(int s) const {
    return reporter(s, [per_stage = per_stage](Index done, Index of) {
      return of > 0 ? Index(double(per_stage) * double(done) / double(of)) : per_stage;
    });
  }
  // A stage's share of a count: blocks of a stage (the candidates' distances in blocks) report
  // through a stage of their own, base offset by the blocks before.
  py::object part(int s, Index first, Index count, Index of) const {
    return reporter(s, [per_stage = per_stage, first, count, of](Index done, Index block) {
      const double fraction = of > 0 ? (double(first) + double(count) * double(done) / double(std::max<Index>(block, 1))) / double(of) : 1.0;
      return Index(double(per_stage) * fraction);
    });
  }
  void finish() const {
    if (user.is_none() || *last == total) return;
    *last = total;
    if (!report_progress(user, total, total)) throw py::error_already_set();
  }
};

// Candidate pairs (i, j), i in [0, n), found by find(begin, end, out) over chunks of [0, n) (the
// positions of a spatial order of the queries) on `workers` threads, then sorted by (i, j): the
// same list for every worker count. find's positions [begin, end) must name queries no other
// chunk names (a permutation's positions do), so that each query's pairs come from one chunk:
// each chunk then counts its queries' pairs and moves them to their place alone, and no thread
// joins the parts by itself.
template <class Find> PairList chunked_pairs(Index n, int workers, Find&& find, py::handle progress = py::none()) {
  const Index chunk = chunk_size(n, workers);
  std::vector<PairList> parts(static_cast<size_t>((n + chunk - 1) / chunk));
  std::vector<size_t> start(size_t(n) + 1, 0);  // start[i + 1]: query i's pairs, then where they end
  run_released(n, workers, [&](Index begin, Index end) {
    PairList& part = parts[size_t(begin / chunk)];
    find(begin, end, part);
    for (const auto& p : part) ++start[size_t(p.first) + 1];
  }, progress, chunk);
  py::gil_scoped_release release;
  for (size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
  PairList out(start.back());
  std::vector<size_t> at(start.begin(), start.end() - 1);
  const auto no_interrupt = [](Index) { return false; };  // milliseconds of copying and sorting
  run_in_chunks(Index(parts.size()), workers, [&](Index first, Index last) {
    for (Index k = first; k < last; ++k) {
      for (const auto& p : parts[size_t(k)]) out[at[size_t(p.first)]++] = p;
      PairList().swap(parts[size_t(k)]);
    }
  }, no_interrupt, 1);
  run_in_chunks(n, workers, [&](Index first, Index last) {
    for (Index i = first; i < last; ++i)
      if (start[size_t(i) + 1] - start[size_t(i)] > 1)
        std::sort(out.begin() + std::ptrdiff_t(start[size_t(i)]), out.begin() + std::ptrdiff_t(start[size_t(i) + 1]));
  }, no_interrupt);
  return out;
}

// The shape's elements at the flat indices rows[0, count), as a batch of shape (count,): each
// field keeps its dtype flags (float32 given, long double values), a field of one value stays
// one value. Arrays are made with the GIL held, filled without it.
Shape gather(const Shape& s, const FieldElements& e, const Index* rows, Index count, int workers) {
  std::vector<Field> fields;
  struct Copy {
    const double* from;
    double* to;
    const long double* wide_from = nullptr;
    long double* wide_to = nullptr;
    Index width;
    size_t field;
  };
  std::vector<Copy> copies;
  for (size_t k = 0; k < s.fields.size(); ++k) {
    const Field& f = s.fields[k];
    if (e.maps[k].mode == FieldElements::Mode::One) {
      fields.push_back(f);
      continue;
    }
    Field g = f;
    std::vector<Index> shape{count};
    for (Index d = Index(f.batch.size()); d < f.array.ndim(); ++d) shape.push_back(f.array.shape(d));
    g.array = decltype(f.array)(shape);
    g.batch = {count};
    g.is_widened = false;
    g.widened = Field::Wide();
    Copy c{f.data(), g.array.mutable_data(), nullptr, nullptr, f.width, k};
    if (f.is_wide) {
      g.wide = Field::Wide(shape);
      c.wide_from = f.wide.data();
      c.wide_to = g.wide.mutable_data();
    }
    copies.push_back(c);
    fields.push_back(std::move(g));
  }
  {
    py::gil_scoped_release release;
    run_in_chunks(count, workers, [&](Index begin, Index end) {
      for (const Copy& c : copies) {
        for (Index i = begin; i < end; ++i) {
          const Index at = e.of(c.field, rows[i]) * c.width;
          std::copy_n(c.from + at, c.width, c.to + i * c.width);
          if (c.wide_from) std::copy_n(c.wide_from + at, c.width, c.wide_to + i * c.width);
        }
      }
    }, [](Index) { return false; });  // a copy: over in milliseconds, no Ctrl-C check needed
  }
  return Shape(s.kind, std::move(fields));
}

// One side of a query: the argument read as a shape (its name in messages).
struct Side {
  py::object keep;
  const Shape* shape;
  Side(py::handle value, const char* owner, const char* name) {
    try {
      const Argument arg(value);
      keep = arg.keep;
      shape = arg.shape;
    } catch (py::error_already_set& error) {  // not a shape, and not an array of points either
      const std::string text = std::string(owner) + ": " + name + " must be a circledist shape or an array of points, got " +
                               Py_TYPE(value.ptr())->tp_name + " (" + py::str(error.value()).cast<std::string>() + ")";
      if (error.matches(PyExc_ValueError)) throw py::value_error(text);
      throw py::type_error(text);
    } catch (const std::exception& error) {
      throw py::type_error(std::string(owner) + ": " + name + " must be a circledist shape or an array of points (" +
                           error.what() + ")");
    }
  }
};

// The distances of the pairs (a[i], b[j]) of a list, in blocks (bounded memory), through the
// distance kernels; Real is the answers' type (float for float32, whose answers are rounded).
template <class Real> struct Evaluator {
  const Shape& a;
  const Shape& b;
  const Choice& choice;
  FieldElements ea{a}, eb{b};
  static constexpr Index kBlock = Index(1) << 20;

  // Calls block(start, count, distances) for the pairs [start, start + count) of the list, block
  // after block, distances[k] that of pair start + k; reports to `progress`'s stage `stage`.
  template <class Block> void run_blocks(const PairList& pairs, const StagedProgress& progress, int stage, Block&& block) const {
    std::vector<Index> rows_a, rows_b;
    for (Index start = 0; start < Index(pairs.size()); start += kBlock) {
      const Index count = std::min<Index>(kBlock, Index(pairs.size()) - start);
      rows_a.resize(size_t(count));
      rows_b.resize(size_t(count));
      {
        py::gil_scoped_release release;
        run_in_chunks(count, choice.workers, [&](Index first, Index last) {
          for (Index k = first; k < last; ++k) {
            rows_a[size_t(k)] = pairs[size_t(start + k)].first;
            rows_b[size_t(k)] = pairs[size_t(start + k)].second;
          }
        }, [](Index) { return false; });  // a copy: over in a millisecond
      }
      const Shape ga = gather(a, ea, rows_a.data(), count, choice.workers);
      const Shape gb = gather(b, eb, rows_b.data(), count, choice.workers);
      // Both single shapes (one element each) answer with a scalar: made an array of the block.
      const py::object answer = py::module_::import("numpy").attr("broadcast_to")(
          py::module_::import("numpy").attr("asarray")(shapes_distance(ga, gb, choice, progress.part(stage, start, count, Index(pairs.size())))).attr("reshape")(-1),
          py::make_tuple(count));
      const auto values = py::array_t<Real, py::array::c_style | py::array::forcecast>::ensure(answer);
      block(start, count, values.data());
    }
  }

  // Calls take(k, distance) for every pair k of the list, in order.
  template <class Take> void run(const PairList& pairs, const StagedProgress& progress, int stage, Take&& take) const {
    run_blocks(pairs, progress, stage, [&](Index start, Index count, const Real* d) {
      for (Index k = 0; k < count; ++k) take(start + k, d[k]);
    });
  }
};

// A distance limit: a finite real number >= 0 (bool and strings refused), named in messages.
double limit_of(const char* owner, py::handle d) {
  const py::module_ numbers = py::module_::import("numbers");
  if (PyBool_Check(d.ptr()) || py::isinstance(d, py::module_::import("numpy").attr("bool_")) ||
      !py::isinstance(d, numbers.attr("Real")))
    throw py::type_error(std::string(owner) + ": d must be a real number >= 0, got " +
                         py::repr(d).cast<std::string>());
  const double value = d.cast<double>();
  if (!(value >= 0) || !std::isfinite(value))
    throw py::value_error(std::string(owner) + ": d must be a finite number >= 0, got " +
                          py::repr(d).cast<std::string>());
  return value;
}

Index count_of(const char* owner, py::handle k) {
  if (PyBool_Check(k.ptr()) || !py::isinstance(k, py::module_::import("numbers").attr("Integral")))
    throw py::type_error(std::string(owner) + ": k must be an integer >= 1, got " + py::repr(k).cast<std::string>());
  const long long value = k.cast<long long>();
  if (value < 1) throw py::value_error(std::string(owner) + ": k must be an integer >= 1, got " + std::to_string(value));
  return Index(value);
}

// The kernel table must have the pair, whether or not any candidate reaches it: the answer may
// not depend on where the shapes lie.
void check_pair(const char* owner, const Shape& a, const Shape& b, const Choice& c) {
  const bool has = c.precision == kLongDouble ? bool(pairs().of<long double>(c.solver).distance[a.kind][b.kind])
                                              : bool(pairs().of<double>(c.solver).distance[a.kind][b.kind]);
  if (!has)
    throw py::type_error(std::string(owner) + ": circledist has no query between a " + kind_name(a.kind) +
                         " (a) and a " + kind_name(b.kind) + " (b)");
}

// The culling margin per unit of size: float32 answers are rounded to float32 (and computed on
// inputs rounded to it), so they carry float's error; the others double's or less.
double relative_margin(const Choice& c) {
  return c.single() ? std::sqrt(double(std::numeric_limits<float>::epsilon()))
                    : std::sqrt(std::numeric_limits<double>::epsilon());
}

template <class T> py::array_t<T> to_array(const std::vector<T>& v, BatchShape shape) {
  py::array_t<T> out(shape);
  std::copy(v.begin(), v.end(), out.mutable_data());
  return out;
}

// What a brute-force loop compares: distance(a[i], b[j]) <= d, with distance() a Python float
// for float64 and float32 answers (the float32 value, exactly) and a numpy.longdouble for long
// double ones, so d is compared in double, or in long double.
template <class Real> bool at_most(Real distance, double d) {
  if constexpr (std::is_same_v<Real, long double>) return distance <= (long double)d;
  else return double(distance) <= d;
}

template <class Real>
py::tuple pairs_within_as(const Shape& a, const Shape* b, double d, const Choice& c) {
  const Shape& other = b ? *b : a;
  const StagedProgress progress(c.progress, 2, flat_size(a));  // the search, the distances
  PairList candidates;
  if (b) {
    const Culling culling(a, *b, c.workers);
    const double limit = cull_limit(d, std::max(culling.tree.scale(), culling.scale_a), relative_margin(c));
    candidates = chunked_pairs(flat_size(a), c.workers, [&](Index begin, Index end, PairList& out) {
      candidate_pairs(culling.va, culling.order, culling.tree, limit, begin, end, out);
    }, progress.stage(0));
  } else {
    const BoundingVolumeHierarchy<double> tree = tree_of(volumes_of({&a}, c.workers), c.workers);
    const double limit = cull_limit(d, tree.scale(), relative_margin(c));
    candidates = chunked_pairs(tree.size(), c.workers, [&](Index begin, Index end, PairList& out) {
      candidate_pairs(tree, limit, begin, end, out);
    }, progress.stage(0));
  }
  std::vector<Index> is, js;
  std::vector<Real> distances;
  Evaluator<Real>{a, other, c}.run_blocks(candidates, progress, 1, [&](Index start, Index count, const Real* dist) {
    // The block's pairs within d, appended in order: each slice of the block counts its own, then
    // writes them at the offset the slices before it leave.
    const Index slice = 16384;
    std::vector<Index> kept(size_t((count + slice - 1) / slice) + 1, 0);
    const auto no_interrupt = [](Index) { return false; };  // a pass over the block: milliseconds
    py::gil_scoped_release release;
    run_in_chunks(count, c.workers, [&](Index first, Index last) {
      Index within = 0;
      for (Index k = first; k < last; ++k) within += at_most(dist[k], d);
      kept[size_t(first / slice) + 1] = within;
    }, no_interrupt, slice);
    for (size_t s = 1; s < kept.size(); ++s) kept[s] += kept[s - 1];
    const size_t base = is.size();
    is.resize(base + size_t(kept.back()));
    js.resize(is.size());
    distances.resize(is.size());
    run_in_chunks(count, c.workers, [&](Index first, Index last) {
      size_t at = base + size_t(kept[size_t(first / slice)]);
      for (Index k = first; k < last; ++k) {
        if (!at_most(dist[k], d)) continue;
        is[at] = candidates[size_t(start + k)].first;
        js[at] = candidates[size_t(start + k)].second;
        distances[at++] = dist[k];
      }
    }, no_interrupt, slice);
  });
  stats().culled += std::uint64_t(std::max<Index>(
      0, (b ? flat_size(a) * flat_size(*b) : flat_size(a) * (flat_size(a) - 1) / 2) - Index(candidates.size())));
  progress.finish();
  const Index m = Index(is.size());
  return py::make_tuple(to_array(is, {m}), to_array(js, {m}), to_array(distances, {m}));
}

template <class Real> py::tuple nearest_as(const Shape& a, const Shape& b, Index k, const Choice& c) {
  const Culling culling(a, b, c.workers);
  const Volumes& va = culling.va;
  const std::vector<BroadIndex>& order = culling.order;
  const BoundingVolumeHierarchy<double>& tree = culling.tree;
  const Index n = Index(va.size()), nb = tree.size(), kk = std::min(k, nb);
  const double scale = std::max(tree.scale(), culling.scale_a);
  const Evaluator<Real> evaluate{a, b, c};
  // Four stages: the first search and its distances, the second search and its distances.
  const StagedProgress progress(c.progress, 4, n);
  // 1. The kk shapes of smallest lower bound: their largest exact distance, tau, bounds the
  //    kk-th nearest distance from above.
  const PairList first = chunked_pairs(n, c.workers, [&](Index begin, Index end, PairList& out) {
    for (Index p = begin; p < end; ++p) {
      const Index i = order[size_t(p)];
      for (const auto& entry : tree.nearest_by_bound(va[size_t(i)], kk)) out.emplace_back(i, entry.second);
    }
  }, progress.stage(0));
  // Per query, its (distance, index) found so far.
  std::vector<std::vector<std::pair<Real, Index>>> found(static_cast<size_t>(n));
  std::vector<double> tau(static_cast<size_t>(n), -std::numeric_limits<double>::infinity());
  evaluate.run(first, progress, 1, [&](Index p, Real distance) {
    const auto [i, j] = first[size_t(p)];
    found[size_t(i)].emplace_back(distance, j);
    tau[size_t(i)] = std::max(tau[size_t(i)], double(distance));
  });
  // 2. Every other shape whose bound is within tau (and the margin): the nearest are among them.
  if (kk < nb) {
    const PairList second = chunked_pairs(n, c.workers, [&](Index begin, Index end, PairList& out) {
      for (Index p = begin; p < end; ++p) {
        const Index i = order[size_t(p)];
        const auto& known = found[size_t(i)];
        tree.visit_within(va[size_t(i)], cull_limit(tau[size_t(i)], scale, relative_margin(c)), [&](BroadIndex j, double) {
          for (const auto& e : known)
            if (e.second == j) return;
          out.emplace_back(i, j);
        });
      }
    }, progress.stage(2));
    evaluate.run(second, progress, 3, [&](Index p, Real distance) {
      const auto [i, j] = second[size_t(p)];
      found[size_t(i)].emplace_back(distance, j);
    });
    stats().culled += std::uint64_t(std::max<Index>(0, n * nb - Index(first.size() + second.size())));
  }
  progress.finish();
  // 3. The k smallest (distance, index) of each query; -1 and inf past the end of b.
  std::vector<Index> indices(static_cast<size_t>(n * k), -1);
  std::vector<Real> distances(static_cast<size_t>(n * k), std::numeric_limits<Real>::infinity());
  for (Index i = 0; i < n; ++i) {
    auto& f = found[size_t(i)];
    const Index take = std::min<Index>(k, Index(f.size()));
    std::partial_sort(f.begin(), f.begin() + take, f.end());
    for (Index r = 0; r < take; ++r) {
      distances[size_t(i * k + r)] = f[size_t(r)].first;
      indices[size_t(i * k + r)] = f[size_t(r)].second;
    }
  }
  return py::make_tuple(to_array(indices, {n, k}), to_array(distances, {n, k}));
}

// Runs body.template operator()<Real>() with Real the answers' type of the choice's precision.
template <class Body> py::tuple with_answer_type(const Choice& c, Body&& body) {
  if (c.precision == kLongDouble) return body(static_cast<long double*>(nullptr));
  if (c.precision == kFloat) return body(static_cast<float*>(nullptr));
  return body(static_cast<double*>(nullptr));
}

py::tuple run_pairs_within(py::handle a, py::handle b, py::handle d, const py::object& precision,
                           const py::object& solver, int workers, const py::object& progress) {
  const Side x(a, "pairs_within", "a");
  const std::optional<Side> y = b.is_none() ? std::nullopt : std::optional<Side>(Side(b, "pairs_within", "b"));
  const Shape& other = y ? *y->shape : *x.shape;
  const double limit = limit_of("pairs_within", d);
  const Choice c(precision, solver, *x.shape, other, workers, progress);
  check_pair("pairs_within", *x.shape, other, c);
  const Shape* second = y ? y->shape : nullptr;
  return with_answer_type(c, [&](auto* tag) {
    using Real = std::remove_pointer_t<decltype(tag)>;
    return pairs_within_as<Real>(*x.shape, second, limit, c);
  });
}

py::tuple run_nearest(py::handle a, py::handle b, py::handle k, const py::object& precision, const py::object& solver,
                      int workers, const py::object& progress) {
  const Side x(a, "nearest", "a"), y(b, "nearest", "b");
  const Index count = count_of("nearest", k);
  const Choice c(precision, solver, *x.shape, *y.shape, workers, progress);
  check_pair("nearest", *x.shape, *y.shape, c);
  return with_answer_type(c, [&](auto* tag) {
    using Real = std::remove_pointer_t<decltype(tag)>;
    return nearest_as<Real>(*x.shape, *y.shape, count, c);
  });
}

// circledist.Scene's broadphase: the elements of several shapes (a scene's groups), numbered one
// after the other.
struct SceneBroadphase {
  BoundingVolumeHierarchy<double> tree;

  static SceneBroadphase make(const py::list& shapes, int workers) {
    std::vector<const Shape*> read;
    for (py::handle s : shapes) read.push_back(&constructed(s));
    return {tree_of(volumes_of(read, workers), workers)};
  }

  Volume<double> query(py::handle shape) const {
    const Shape& s = constructed(shape);
    if (!s.batch.empty()) throw py::value_error("a broadphase query takes a single shape");
    Volume<double> v;
    fill_volumes(s, 0, 1, &v);
    return v;
  }

  // cull_limit(d) for a query shape: the set's scale or the shape's reach, the larger.
  double limit(py::handle shape, double d) const {
    return cull_limit(d, std::max(tree.scale(), query(shape).reach()));
  }

  // The elements whose lower bound to `shape` is within cull_limit(d), with their bounds; sorted.
  py::tuple within(py::handle shape, double d) const {
    const Volume<double> q = query(shape);
    std::vector<std::pair<Index, double>> found;
    tree.visit_within(q, cull_limit(d, std::max(tree.scale(), q.reach())), [&](BroadIndex j, double bound) { found.emplace_back(j, bound); });
    std::sort(found.begin(), found.end());
    std::vector<Index> idx;
    std::vector<double> bounds;
    for (const auto& [j, bound] : found) idx.push_back(j), bounds.push_back(bound);
    return py::make_tuple(to_array(idx, {Index(idx.size())}), to_array(bounds, {Index(bounds.size())}));
  }

  py::tuple nearest_by_bound(py::handle shape, Index k) const {
    const auto best = tree.nearest_by_bound(query(shape), k);
    std::vector<Index> idx;
    std::vector<double> bounds;
    for (const auto& [bound, j] : best) idx.push_back(j), bounds.push_back(bound);
    return py::make_tuple(to_array(idx, {Index(idx.size())}), to_array(bounds, {Index(bounds.size())}));
  }

  // Candidate pairs i < j of the set within cull_limit(d).
  py::tuple pairs(double d, int workers) const {
    const double limit = cull_limit(d, tree.scale());
    const PairList found = chunked_pairs(tree.size(), workers, [&](Index begin, Index end, PairList& out) {
      candidate_pairs(tree, limit, begin, end, out);
    });
    std::vector<Index> is(found.size());
    std::vector<Index> js(found.size());
    for (size_t p = 0; p < found.size(); ++p) is[p] = found[p].first, js[p] = found[p].second;
    return py::make_tuple(to_array(is, {Index(is.size())}), to_array(js, {Index(js.size())}));
  }
};

}  // namespace

inline void bind_pairs(py::module_& m) {
  m.def(
      "pairs_within",
      [](ShapeLike a, OptionalShapeLike b, Number d, PrecisionName precision, SolverName solver, int workers,
         ProgressLike progress) { return PairsResult(run_pairs_within(a, b, d, precision, solver, workers, progress)); },
      py::arg("a"), py::arg("b"), py::arg("d"), py::kw_only(), py::arg("precision") = py::none(),
      py::arg("solver") = py::none(), py::arg("workers") = 1, py::arg("progress") = py::none(), doc::kPairsWithin());
  m.def(
      "nearest",
      [](ShapeLike a, ShapeLike b, Count k, PrecisionName precision, SolverName solver, int workers,
         ProgressLike progress) { return NearestResult(run_nearest(a, b, k, precision, solver, workers, progress)); },
      py::arg("a"), py::arg("b"), py::arg("k") = 1, py::kw_only(), py::arg("precision") = py::none(),
      py::arg("solver") = py::none(), py::arg("workers") = 1, py::arg("progress") = py::none(), doc::kNearest());

  py::class_<SceneBroadphase>(m, "_Broadphase",
                              "The broadphase over a list of shapes' elements, numbered one after the other "
                              "(used by circledist.Scene).")
      .def(py::init(&SceneBroadphase::make), py::arg("shapes"), py::arg("workers") = 1)
      .def("__len__", [](const SceneBroadphase& s) { return s.tree.size(); })
      .def_property_readonly("scale", [](const SceneBroadphase& s) { return s.tree.scale(); })
      .def("limit", &SceneBroadphase::limit, py::arg("shape"), py::arg("d"),
           "cull_limit(d) for a single shape: bounds above it are beyond d.")
      .def("within", &SceneBroadphase::within, py::arg("shape"), py::arg("d"),
           "(indices, lower bounds) of the elements within cull_limit(d) of a single shape, sorted.")
      .def("nearest_by_bound", &SceneBroadphase::nearest_by_bound, py::arg("shape"), py::arg("k"),
           "(indices, lower bounds) of the k elements of smallest lower bound, by bound.")
      .def("pairs", &SceneBroadphase::pairs, py::arg("d"), py::arg("workers") = 1,
           "(i, j), i < j: the candidate pairs within cull_limit(d), sorted.");
}
