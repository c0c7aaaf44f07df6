// The all-pairs queries: pairs_within(a, b, d) and nearest(a, b, k) over two batches of any
// kinds, and the broadphase object circledist.Scene culls with. The culling is
// cpp/include/circledist/broadphase.hpp's; the candidates it keeps are gathered into new batches
// and answered by the module's own distance kernels (the path distance() takes), so every
// distance is the one distance() gives, to the bit, and no geometry is written here.
#include "all_pairs_doc.hpp"
#include "module.hpp"
#include "all_pairs_culling.hpp"

#include <circledist/broadphase.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <system_error>
#include <thread>
#include <type_traits>
#include <vector>

namespace circledist::python {
namespace {

// The distances of the pairs (a[i], b[j]) of a list, in blocks (bounded memory), through the
// distance kernels; Real is the answers' type (float for float32, whose answers are rounded).
// Given a `limit` (a scene's pairs), within(a[i], b[j], limit) instead, through the within
// kernels: Real is then bool.
template <class Real> struct Evaluator {
  const Shape& a;
  const Shape& b;
  const Choice& choice;
  const Shape* limit = nullptr;
  FieldElements ea{a}, eb{b};
  static constexpr Index kBlock = Index(1) << 20;

  // Calls block(start, count, distances) for the pairs [start, start + count) of the list, block
  // after block, distances[k] that of pair start + k; reports to `progress`'s stage `stage`.
  template <class Block>
  void run_blocks(const PairList& pairs, const StagedProgress& progress, int stage, Block&& block) const {
    std::vector<Index> rows_a, rows_b;
    for (Index start = 0; start < Index(pairs.size()); start += kBlock) {
      const Index count = std::min<Index>(kBlock, Index(pairs.size()) - start);
      rows_a.resize(size_t(count));
      rows_b.resize(size_t(count));
      {
        py::gil_scoped_release release;
        run_in_chunks(
            count, choice.workers,
            [&](Index first, Index last) {
              for (Index k = first; k < last; ++k) {
                rows_a[size_t(k)] = pairs[size_t(start + k)].first;
                rows_b[size_t(k)] = pairs[size_t(start + k)].second;
              }
            },
            [](Index) { return false; });  // a copy: over in a millisecond
      }
      const Shape ga = gather(a, ea, rows_a.data(), count, choice.workers);
      const Shape gb = gather(b, eb, rows_b.data(), count, choice.workers);
      // Both single shapes (one element each) answer with a scalar: made an array of the block.
      const py::object part = progress.part(stage, start, count, Index(pairs.size()));
      const py::object answer = py::module_::import("numpy").attr("broadcast_to")(
          py::module_::import("numpy")
              .attr("asarray")(limit ? shapes_within(ga, gb, *limit, false, choice, part)
                                     : shapes_distance(ga, gb, choice, part))
              .attr("reshape")(-1),
          py::make_tuple(count));
      const auto values = py::array_t < Real, py::array::c_style | py::array::forcecast > ::ensure(answer);
      block(start, count, values.data());
    }
  }

  // Calls take(k, answer) for every pair k of the list, on the workers (the GIL released): take
  // must be safe to call for distinct k side by side.
  template <class Take> void run(const PairList& pairs, const StagedProgress& progress, int stage, Take&& take) const {
    run_blocks(pairs, progress, stage, [&](Index start, Index count, const Real* d) {
      py::gil_scoped_release release;
      run_in_chunks(
          count, choice.workers,
          [&](Index first, Index last) {
            for (Index k = first; k < last; ++k) take(start + k, d[k]);
          },
          [](Index) { return false; });  // a pass over the block: milliseconds
    });
  }
};

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
  if constexpr (std::is_same_v<Real, long double>)
    return distance <= (long double)d;
  else
    return double(distance) <= d;
}

// The elements k of [0, count) for which keep(k) holds, in order, on `workers` threads (the GIL
// released): each slice counts its own, make_room(total) is called once, then each slice calls
// put(k, at) for its kept elements, `at` their rank among all kept ones.
template <class Keep, class Room, class Put>
void keep_in_order(Index count, int workers, Keep&& keep, Room&& make_room, Put&& put) {
  const Index slice = 16384;
  std::vector<Index> kept(size_t((count + slice - 1) / slice) + 1, 0);
  const auto no_interrupt = [](Index) { return false; };  // a pass over the elements: milliseconds
  py::gil_scoped_release release;
  run_in_chunks(
      count, workers,
      [&](Index first, Index last) {
        Index within = 0;
        for (Index k = first; k < last; ++k) within += keep(k) ? 1 : 0;
        kept[size_t(first / slice) + 1] = within;
      },
      no_interrupt, slice);
  for (size_t s = 1; s < kept.size(); ++s) kept[s] += kept[s - 1];
  make_room(kept.back());
  run_in_chunks(
      count, workers,
      [&](Index first, Index last) {
        Index at = kept[size_t(first / slice)];
        for (Index k = first; k < last; ++k)
          if (keep(k)) put(k, at++);
      },
      no_interrupt, slice);
}

template <class Real>
py::tuple pairs_within_as(const Shape& a, const Shape* b, double d, Index max_pairs, const Choice& c) {
  const Shape& other = b ? *b : a;
  const StagedProgress progress(c.progress, 2, flat_size(a));  // the search, the distances
  PairList candidates;
  if (b) {
    const Culling culling(a, *b, c.workers);
    const PairLimit<double> limit{d, relative_margin(c)};
    candidates = chunked_pairs(
        flat_size(a), c.workers,
        [&](Index begin, Index end, PairList& out) {
          candidate_pairs(culling.va, culling.order, culling.tree, limit, begin, end, out);
        },
        progress.stage(0), max_pairs);
  } else {
    const BoundingVolumeHierarchy<double> tree = tree_of(volumes_of({&a}, c.workers), c.workers);
    const PairLimit<double> limit{d, relative_margin(c)};
    candidates = chunked_pairs(
        tree.size(), c.workers,
        [&](Index begin, Index end, PairList& out) { candidate_pairs(tree, limit, begin, end, out); },
        progress.stage(0), max_pairs);
  }
  std::vector<Index> is, js;
  std::vector<Real> distances;
  Evaluator<Real>{a, other, c}.run_blocks(candidates, progress, 1, [&](Index start, Index count, const Real* dist) {
    // The block's pairs within d, appended in order.
    const size_t base = is.size();
    keep_in_order(
        count, c.workers, [&](Index k) { return at_most(dist[k], d); },
        [&](Index total) {
          is.resize(base + size_t(total));
          js.resize(is.size());
          distances.resize(is.size());
        },
        [&](Index k, Index at) {
          is[base + size_t(at)] = candidates[size_t(start + k)].first;
          js[base + size_t(at)] = candidates[size_t(start + k)].second;
          distances[base + size_t(at)] = dist[k];
        });
  });
  stats().culled += std::uint64_t(std::max<Index>(
      0, (b ? flat_size(a) * flat_size(*b) : flat_size(a) * (flat_size(a) - 1) / 2) - Index(candidates.size())));
  progress.finish();
  const Index m = Index(is.size());
  return py::make_tuple(to_array(is, {m}), to_array(js, {m}), to_array(distances, {m}));
}

// Where each query's pairs start in a list sorted by query: start[i] for i in [0, n], start[n] the
// list's end; the chunks of queries find theirs side by side.
std::vector<size_t> starts_of(const PairList& pairs, Index n, int workers) {
  std::vector<size_t> start(size_t(n) + 1, pairs.size());
  py::gil_scoped_release release;
  run_in_chunks(
      n, workers,
      [&](Index first, Index last) {
        size_t at = size_t(
            std::lower_bound(pairs.begin(), pairs.end(), first, [](const auto& p, Index i) { return p.first < i; }) -
            pairs.begin());
        for (Index i = first; i < last; ++i) {
          while (at < pairs.size() && pairs[at].first < i) ++at;
          start[size_t(i)] = at;
        }
      },
      [](Index) { return false; });  // bisections and a pass: milliseconds
  return start;
}

// nearest's answers for n queries, (indices, distances) of shape (n, k) each, made before any work:
// a k whose answers memory cannot hold (the size beyond 64 bits, or the allocation refused) is a
// MemoryError naming k and the size at once (n * k wrapped around 64 bits was a small buffer the
// answers overran). The columns past len(b) are -1 and inf, which no query computes: k itself
// costs only this memory.
template <class Real> std::pair<py::array_t<Index>, py::array_t<Real>> nearest_answers(Index n, Index k, Index nb) {
  constexpr Index per_entry = Index(sizeof(Index) + sizeof(Real));
  const auto refuse = [&] {
    std::ostringstream text;
    text.precision(3);
    text << "nearest: k=" << k << " asks for answers of shape (" << n << ", " << k << "), more than memory can hold ("
         << double(std::max<Index>(n, 1)) * double(k) * per_entry << " bytes" << (n == 0 ? " per query" : "")
         << "; the columns past len(b) = " << nb << " are only -1 and inf)";
    PyErr_SetString(PyExc_MemoryError, text.str().c_str());
    throw py::error_already_set();
  };
  // NumPy refuses a shape whose size in bytes, zero rows aside, passes 2**63 - 1: (0, k) too.
  if (k > std::numeric_limits<Index>::max() / per_entry / std::max<Index>(n, 1)) refuse();
  try {
    return {py::array_t<Index>({n, k}), py::array_t<Real>({n, k})};
  } catch (py::error_already_set& error) {
    if (!error.matches(PyExc_MemoryError)) throw;
  }
  refuse();
  return {};
}

template <class Real> py::tuple nearest_as(const Shape& a, const Shape& b, Index k, const Choice& c) {
  auto [index_out, distance_out] = nearest_answers<Real>(flat_size(a), k, flat_size(b));
  const Culling culling(a, b, c.workers);
  const Volumes& va = culling.va;
  const std::vector<BroadIndex>& order = culling.order;
  const BoundingVolumeHierarchy<double>& tree = culling.tree;
  const Index n = Index(va.size()), nb = tree.size(), kk = std::min(k, nb), seeds = std::min(k + 2, nb);
  const Evaluator<Real> evaluate{a, b, c};
  const auto no_interrupt = [](Index) { return false; };  // passes over the queries: milliseconds
  // Four stages: the first search and its distances, the second search and its distances.
  const StagedProgress progress(c.progress, 4, n);
  // 1. The kk + 2 shapes of smallest lower bound (as Scene.nearest seeds its search): the kk-th
  //    smallest of their exact distances, tau, bounds the kk-th nearest distance from above. The
  //    two spare seeds keep a huge shape, whose bound is small and distance large (a ring around
  //    the set), from setting tau for every query.
  const PairList first = chunked_pairs(
      n, c.workers,
      [&](Index begin, Index end, PairList& out) {
        for (Index p = begin; p < end; ++p) {
          const Index i = order[size_t(p)];
          for (const auto& entry : tree.nearest_by_bound(va[size_t(i)], seeds)) out.emplace_back(i, entry.second);
        }
      },
      progress.stage(0));
  // The lists' distances by position, and where each query's pairs start: every step below is a
  // pass over the queries, on the workers.
  std::vector<Real> first_distances(first.size());
  evaluate.run(first, progress, 1, [&](Index p, Real distance) { first_distances[size_t(p)] = distance; });
  const std::vector<size_t> first_start = starts_of(first, n, c.workers);
  // tau: the kk-th smallest (distance, index) of the seeds, its distance in tau and its index in
  // tie. Where that distance is 0 no shape after `tie` can come before it (no distance is below
  // 0): the second search looks at the shapes numbered below `tie` only, which keeps a set of
  // coincident shapes from making every pair a candidate.
  std::vector<double> tau(static_cast<size_t>(n), -std::numeric_limits<double>::infinity());
  std::vector<BroadIndex> tie(static_cast<size_t>(n), std::numeric_limits<BroadIndex>::max());
  {
    py::gil_scoped_release release;
    run_in_chunks(
        n, c.workers,
        [&](Index begin, Index end) {
          std::vector<std::pair<Real, BroadIndex>> known;
          for (Index i = begin; i < end; ++i) {
            known.clear();
            for (size_t p = first_start[size_t(i)]; p < first_start[size_t(i) + 1]; ++p)
              known.emplace_back(first_distances[p], first[p].second);
            if (Index(known.size()) < kk || kk == 0) continue;
            std::nth_element(known.begin(), known.begin() + (kk - 1), known.end());
            tau[size_t(i)] = double(known[size_t(kk - 1)].first);
            if (known[size_t(kk - 1)].first <= 0) tie[size_t(i)] = known[size_t(kk - 1)].second;
          }
        },
        no_interrupt);
  }
  // 2. Every other shape whose bound is within tau (and the margin): the nearest are among them.
  PairList second;
  std::vector<Real> second_distances;
  if (seeds < nb) {
    second = chunked_pairs(
        n, c.workers,
        [&](Index begin, Index end, PairList& out) {
          for (Index p = begin; p < end; ++p) {
            const Index i = order[size_t(p)];
            const size_t known = first_start[size_t(i)], known_end = first_start[size_t(i) + 1];
            tree.visit_within(
                va[size_t(i)], PairLimit<double>{tau[size_t(i)], relative_margin(c)},
                [&](BroadIndex j, double) {
                  for (size_t q = known; q < known_end; ++q)
                    if (first[q].second == j) return;
                  out.emplace_back(i, j);
                },
                tie[size_t(i)]);
          }
        },
        progress.stage(2));
    second_distances.resize(second.size());
    evaluate.run(second, progress, 3, [&](Index p, Real distance) { second_distances[size_t(p)] = distance; });
    stats().culled += std::uint64_t(std::max<Index>(0, n * nb - Index(first.size() + second.size())));
  }
  progress.finish();
  const std::vector<size_t> second_start = starts_of(second, n, c.workers);
  // 3. The k smallest (distance, index) of each query's candidates; -1 and inf past the end of b.
  Index* indices = index_out.mutable_data();
  Real* distances = distance_out.mutable_data();
  {
    py::gil_scoped_release release;
    run_in_chunks(
        n, c.workers,
        [&](Index begin, Index end) {
          std::vector<std::pair<Real, Index>> found;
          for (Index i = begin; i < end; ++i) {
            found.clear();
            for (size_t p = first_start[size_t(i)]; p < first_start[size_t(i) + 1]; ++p)
              found.emplace_back(first_distances[p], first[p].second);
            for (size_t p = second_start[size_t(i)]; p < second_start[size_t(i) + 1]; ++p)
              found.emplace_back(second_distances[p], second[p].second);
            const Index take = std::min<Index>(k, Index(found.size()));
            std::partial_sort(found.begin(), found.begin() + take, found.end());
            Index* row_indices = indices + i * k;
            Real* row_distances = distances + i * k;
            for (Index r = 0; r < take; ++r) {
              row_distances[r] = found[size_t(r)].first;
              row_indices[r] = found[size_t(r)].second;
            }
            std::fill(row_indices + take, row_indices + k, Index(-1));
            std::fill(row_distances + take, row_distances + k, std::numeric_limits<Real>::infinity());
          }
        },
        no_interrupt);
  }
  return py::make_tuple(std::move(index_out), std::move(distance_out));
}

// Runs body.template operator()<Real>() with Real the answers' type of the choice's precision.
template <class Body> py::tuple with_answer_type(const Choice& c, Body&& body) {
  if (c.precision == kLongDouble) return body(static_cast<long double*>(nullptr));
  if (c.precision == kFloat) return body(static_cast<float*>(nullptr));
  return body(static_cast<double*>(nullptr));
}

py::tuple run_pairs_within(py::handle a, py::handle b, py::handle d, const py::object& precision,
                           const py::object& solver, py::handle workers, const py::object& progress,
                           py::handle max_pairs) {
  const Side x(a, "pairs_within", "a");
  const std::optional<Side> y = b.is_none() ? std::nullopt : std::optional<Side>(Side(b, "pairs_within", "b"));
  const Shape& other = y ? *y->shape : *x.shape;
  const double limit = limit_of("pairs_within", d);
  const Index most = max_pairs_of("pairs_within", max_pairs);
  const Choice c(precision, solver, *x.shape, other, workers, progress);
  check_pair("pairs_within", *x.shape, other, c);
  const Shape* second = y ? y->shape : nullptr;
  return with_answer_type(c, [&](auto* tag) {
    using Real = std::remove_pointer_t<decltype(tag)>;
    return pairs_within_as<Real>(*x.shape, second, limit, most, c);
  });
}

py::tuple run_nearest(py::handle a, py::handle b, py::handle k, const py::object& precision, const py::object& solver,
                      py::handle workers, const py::object& progress) {
  const Side x(a, "nearest", "a"), y(b, "nearest", "b");
  const Index count = count_of("nearest", k);
  const Choice c(precision, solver, *x.shape, *y.shape, workers, progress);
  check_pair("nearest", *x.shape, *y.shape, c);
  return with_answer_type(c, [&](auto* tag) {
    using Real = std::remove_pointer_t<decltype(tag)>;
    return nearest_as<Real>(*x.shape, *y.shape, count, c);
  });
}

// circledist.Scene's broadphase: the scene's items (single shapes, numbered in the order they were
// added) in a GrowingHierarchy, so that adds between queries cost the new shapes' share and not a
// rebuild; and each item's group (the scene's batch of its kind and dtypes) and row there, which
// the pairs query gathers its exact tests from.
struct SceneBroadphase {
  GrowingHierarchy<double> tree;
  std::vector<Index> group, row;

  // Adds the items numbered on from len(self): parts are (shape, items, group, first row), element
  // k of the shape (flat) being item items[k], at row first + k of its group; the parts' items
  // together are the new numbers, each once.
  void add(const py::list& parts, Count workers_given) {
    const int workers = workers_of(workers_given, "Scene.pairs_within");
    struct Part {
      const Shape* shape;
      py::array_t<Index, py::array::c_style | py::array::forcecast> items;
      Index group, first;
    };
    std::vector<Part> read;
    const Index start = tree.size();
    Index total = 0;
    for (py::handle p : parts) {
      const py::tuple t = py::reinterpret_borrow<py::tuple>(p);
      Part part{&constructed(t[0]), py::array_t < Index, py::array::c_style | py::array::forcecast > ::ensure(t[1]),
                t[2].cast<Index>(), t[3].cast<Index>()};
      if (!part.items || part.items.size() != flat_size(*part.shape))
        throw py::value_error("_Broadphase.add: one item number per element of a part's shape");
      total += part.items.size();
      read.push_back(std::move(part));
    }
    Volumes volumes(static_cast<size_t>(total));
    // On any failure (a bad part, Ctrl-C in the volumes or the tree's build) the broadphase is
    // left as it was: its trees untouched (GrowingHierarchy::add), the new items' entries dropped.
    try {
      group.resize(size_t(start + total));
      row.resize(group.size());
      for (const Part& part : read) {
        const Index count = flat_size(*part.shape);
        const Index* items = part.items.data();
        for (Index k = 0; k < count; ++k)
          if (items[k] < start || items[k] >= start + total)
            throw py::value_error("_Broadphase.add: item numbers must be the new ones, from len(self) on");
        // Items in a run (a batch of one kind, or a group's adds alone) are filled in place;
        // others (a file's mixed kinds) through a buffer.
        bool run = true;
        for (Index k = 1; k < count && run; ++k) run = items[k] == items[0] + k;
        Volumes own(static_cast<size_t>(run ? 0 : count));
        Volume<double>* to = run && count > 0 ? volumes.data() + (items[0] - start) : own.data();
        run_released(count, workers, [&](Index begin, Index end) { fill_volumes(*part.shape, begin, end, to); });
        for (Index k = 0; k < count; ++k) {
          if (!run) volumes[size_t(items[k] - start)] = own[size_t(k)];
          group[size_t(items[k])] = part.group;
          row[size_t(items[k])] = part.first + k;
        }
      }
      interruptible([&](const Interrupted& interrupted) {
        tree.add(std::move(volumes), workers, interrupted);
        return 0;
      });
    } catch (...) {
      group.resize(size_t(start));
      row.resize(size_t(start));
      throw;
    }
  }

  // The trees merged into one, as pairs_within reads it: circledist.Scene merges them while it
  // holds its write lock, so that queries reading the tree side by side find nothing to change.
  void merge(Count workers_given) {
    const int workers = workers_of(workers_given, "Scene.pairs_within");
    interruptible([&](const Interrupted& interrupted) {
      tree.merged(workers, interrupted);
      return 0;
    });
  }

  // The groups and rows of items (numbers below len(self)).
  py::tuple locate(const py::array_t<Index, py::array::c_style | py::array::forcecast>& items) const {
    const Index n = items.size();
    py::array_t<Index> groups(n), rows(n);
    for (Index k = 0; k < n; ++k) {
      const Index i = items.data()[k];
      if (i < 0 || i >= tree.size()) throw py::index_error("_Broadphase.locate: no item " + std::to_string(i));
      groups.mutable_data()[k] = group[size_t(i)];
      rows.mutable_data()[k] = row[size_t(i)];
    }
    return py::make_tuple(groups, rows);
  }

  Volume<double> query(py::handle shape) const {
    const Shape& s = constructed(shape);
    if (!s.batch.empty()) throw py::value_error("a broadphase query takes a single shape");
    Volume<double> v;
    fill_volumes(s, 0, 1, &v);
    return v;
  }

  // The culling limit of d for a query shape: bounds above it are beyond d. Without items, one
  // limit at least every item's (the set's largest reach or the shape's); with items, each one's
  // (PairLimit's: the larger of the shape's reach and the item's), as within() culls.
  py::object limit(py::handle shape, double d, const py::object& items) const {
    const double reach = query(shape).reach();
    const PairLimit<double> limit{d};
    if (items.is_none()) return py::float_(limit(reach, tree.scale()));
    const auto at = py::array_t < Index, py::array::c_style | py::array::forcecast > ::ensure(items);
    if (!at) throw py::type_error("_Broadphase.limit: items must be an array of item numbers");
    py::array_t<double> out(at.size());
    for (Index k = 0; k < at.size(); ++k) {
      const Index i = at.data()[k];
      if (i < 0 || i >= tree.size()) throw py::index_error("_Broadphase.limit: no item " + std::to_string(i));
      out.mutable_data()[k] = limit(reach, tree.volume(i).reach());
    }
    return out;
  }

  // The elements whose lower bound to `shape` is within their PairLimit of d, with their bounds;
  // sorted.
  py::tuple within(py::handle shape, double d) const {
    const Volume<double> q = query(shape);
    std::vector<std::pair<Index, double>> found;
    tree.visit_within(q, PairLimit<double>{d}, [&](BroadIndex j, double bound) { found.emplace_back(j, bound); });
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

  // The pairs (names[i], names[j]) of items i < j for which within(i, j, d) holds, sorted by
  // (i, j), and how many candidates were tested: the candidates of the merged tree, grouped by
  // their groups' pair and tested through the within kernels (the path circledist.within takes),
  // every step on the workers but the list's making (Python objects: the GIL's, here in C, a
  // fraction of what a Python loop over the pairs took). `groups`: the scene's groups as whole
  // batches, in the numbering add() was given; `names`: the items' names.
  py::tuple pairs_within(const py::list& groups, const py::list& names, double d, Count workers_given,
                         py::handle max_pairs) {
    const int workers = workers_of(workers_given, "Scene.pairs_within");
    const Index most = max_pairs_of("Scene.pairs_within", max_pairs);
    if (Index(names.size()) != tree.size()) throw py::value_error("_Broadphase.pairs_within: one name per item");
    std::vector<const Shape*> shapes;
    for (py::handle g : groups) shapes.push_back(&constructed(g));
    const Index G = Index(shapes.size());
    for (size_t i = 0; i < group.size(); ++i)
      if (group[i] < 0 || group[i] >= G || row[i] < 0 || row[i] >= flat_size(*shapes[size_t(group[i])]))
        throw py::value_error("_Broadphase.pairs_within: the groups do not hold the items added");
    // Every pass below over the candidates (which may take a good part of a second) hears Ctrl-C
    // (run_released, interruptible).
    const BoundingVolumeHierarchy<double>* all =
        interruptible([&](const Interrupted& interrupted) { return &tree.merged(workers, interrupted); });
    const PairLimit<double> limit{d};
    const PairList candidates = chunked_pairs(
        all->size(), workers,
        [&](Index begin, Index end, PairList& out) { candidate_pairs(*all, limit, begin, end, out); }, py::none(), most,
        "Scene.pairs_within");
    // The candidates' positions, bucket after bucket (a bucket per pair of groups), in list order
    // within each: each slice of the list counts its pairs per bucket, then places them at the
    // offsets the slices before it leave.
    const Index m = Index(candidates.size()), buckets = G * G, slice = 65536, slices = (m + slice - 1) / slice;
    const auto bucket = [&](Index p) {
      return group[size_t(candidates[size_t(p)].first)] * G + group[size_t(candidates[size_t(p)].second)];
    };
    std::vector<Index> at(size_t(slices * buckets), 0), bucket_start(size_t(buckets) + 1, 0);
    std::vector<Index> placed(static_cast<size_t>(m));
    run_released(
        m, workers,
        [&](Index first, Index last) {
          Index* count = at.data() + (first / slice) * buckets;
          for (Index p = first; p < last; ++p) ++count[bucket(p)];
        },
        py::none(), slice);
    {
      py::gil_scoped_release release;
      Index total = 0;
      for (Index b = 0; b < buckets; ++b) {
        bucket_start[size_t(b)] = total;
        for (Index s = 0; s < slices; ++s) {
          const Index count = at[size_t(s * buckets + b)];
          at[size_t(s * buckets + b)] = total;
          total += count;
        }
      }
      bucket_start[size_t(buckets)] = total;
    }
    run_released(
        m, workers,
        [&](Index first, Index last) {
          Index* next = at.data() + (first / slice) * buckets;
          for (Index p = first; p < last; ++p) placed[size_t(next[bucket(p)]++)] = p;
        },
        py::none(), slice);
    std::vector<char> hit(size_t(m), 0);
    const Shape limit_d = limit_shape("pairs_within", py::float_(d));
    const StagedProgress progress(py::none(), 1, m);
    for (Index b = 0; b < buckets; ++b) {
      const Index first = bucket_start[size_t(b)], count = bucket_start[size_t(b) + 1] - first;
      if (count == 0) continue;
      const Shape &A = *shapes[size_t(b / G)], &B = *shapes[size_t(b % G)];
      PairList rows(static_cast<size_t>(count));
      run_released(count, workers, [&](Index begin, Index end) {
        for (Index k = begin; k < end; ++k) {
          const auto& [i, j] = candidates[size_t(placed[size_t(first + k)])];
          rows[size_t(k)] = {row[size_t(i)], row[size_t(j)]};
        }
      });
      const Choice choice(py::none(), py::none(), A, B, py::int_(workers), py::none());
      Evaluator<bool>{A, B, choice, &limit_d}.run(
          rows, progress, 0, [&](Index k, bool within) { hit[size_t(placed[size_t(first + k)])] = within; });
    }
    PairList kept;
    keep_in_order(
        m, workers, [&](Index p) { return hit[size_t(p)] != 0; }, [&](Index total) { kept.resize(size_t(total)); },
        [&](Index p, Index at) { kept[size_t(at)] = candidates[size_t(p)]; });
    py::list out(kept.size());
    for (size_t k = 0; k < kept.size(); ++k) {
      if (k % 65536 == 65535 && PyErr_CheckSignals() != 0) throw py::error_already_set();  // millions: a second
      PyObject* pair =
          PyTuple_Pack(2, PyList_GET_ITEM(names.ptr(), kept[k].first), PyList_GET_ITEM(names.ptr(), kept[k].second));
      if (!pair) throw py::error_already_set();
      // A pair of strings is in no cycle: left out of the collector's lists (CPython untracks
      // such tuples itself, lazily, in its collections, which 210k new tuples would set off).
      PyObject_GC_UnTrack(pair);
      PyList_SET_ITEM(out.ptr(), Py_ssize_t(k), pair);
    }
    return py::make_tuple(out, m);
  }
};

}  // namespace

void bind_all_pairs(py::module_& m) {
  m.def(
      "pairs_within",
      [](ShapeLike a, OptionalShapeLike b, Number d, PrecisionName precision, SolverName solver, Count workers,
         ProgressLike progress, OptionalCount max_pairs) {
        return PairsResult(run_pairs_within(a, b, d, precision, solver, workers, progress, max_pairs));
      },
      py::arg("a"), py::arg("b"), py::arg("d"), py::kw_only(), py::arg("precision") = py::none(),
      py::arg("solver") = py::none(), py::arg("workers") = 1, py::arg("progress") = py::none(),
      py::arg("max_pairs") = kDefaultMaxPairs, doc::kPairsWithin());
  m.def(
      "nearest",
      [](ShapeLike a, ShapeLike b, Count k, PrecisionName precision, SolverName solver, Count workers,
         ProgressLike progress) { return NearestResult(run_nearest(a, b, k, precision, solver, workers, progress)); },
      py::arg("a"), py::arg("b"), py::arg("k") = 1, py::kw_only(), py::arg("precision") = py::none(),
      py::arg("solver") = py::none(), py::arg("workers") = 1, py::arg("progress") = py::none(), doc::kNearest());

  py::class_<SceneBroadphase>(m, "_Broadphase",
                              "The broadphase over a scene's items, numbered in the order added, which can grow "
                              "between queries (used by circledist.Scene).")
      .def(py::init<>())
      .def("add", &SceneBroadphase::add, py::arg("parts"), py::arg("workers") = 1,
           "Adds items numbered on from len(self): parts are (shape, item numbers, group, first row).")
      .def("__len__", [](const SceneBroadphase& s) { return s.tree.size(); })
      .def_property_readonly("scale", [](const SceneBroadphase& s) { return s.tree.scale(); })
      .def_property_readonly(
          "trees", [](const SceneBroadphase& s) { return s.tree.trees(); },
          "How many trees hold the items (at most log2(len) + 1).")
      .def("merge", &SceneBroadphase::merge, py::arg("workers") = 1,
           "Merges the trees into one (pairs_within's tree), the GIL released.")
      .def("locate", &SceneBroadphase::locate, py::arg("items"), "(groups, rows) of items.")
      .def("limit", &SceneBroadphase::limit, py::arg("shape"), py::arg("d"), py::arg("items") = py::none(),
           "The culling limit of d for a single shape: one above every item's, or each of items' own.")
      .def("within", &SceneBroadphase::within, py::arg("shape"), py::arg("d"),
           "(indices, lower bounds) of the elements within their culling limit of d of a single shape, sorted.")
      .def("nearest_by_bound", &SceneBroadphase::nearest_by_bound, py::arg("shape"), py::arg("k"),
           "(indices, lower bounds) of the k elements of smallest lower bound, by bound.")
      .def(
          "pairs_within", &SceneBroadphase::pairs_within, py::arg("groups"), py::arg("names"), py::arg("d"),
          py::arg("workers") = 1, py::arg("max_pairs") = kDefaultMaxPairs,
          "(pairs, candidates): (names[i], names[j]) for the items i < j within d, sorted, and how many pairs were tested.");
}

}  // namespace circledist::python
