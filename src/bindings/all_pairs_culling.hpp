// The culling machinery of the all-pairs queries (all_pairs.cpp, its only includer): the
// shapes' bounding volumes, the hierarchy and spatial order built without the GIL and stopped
// by Ctrl-C, staged progress, the candidate pairs found in chunks, and the gathering of
// candidates into batches for the distance kernels.
#pragma once

#include "module.hpp"
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

using Volumes = std::vector<Volume<double>>;
using PairList = BroadPairs;

Index flat_size(const Shape& s) {
  Index n = 1;
  for (const Index d : s.batch) n *= d;
  return n;
}

// The volumes of the elements [begin, end) of a shape's batch, in double (the float64 values of
// every field: a long-double or float32 query's shapes differ from them by far less than the
// culling margin).
template <class S>
void fill_volumes(const Shape& s, const FieldElements& e, Index begin, Index end, Volume<double>* out) {
  const size_t nf = s.fields.size();
  std::array<const double*, kMaxShapeFields> ptr{};
  for (Index i = begin; i < end; ++i) {
    for (size_t f = 0; f < nf; ++f) ptr[f] = s.fields[f].data() + e.of(f, i) * s.fields[f].width;
    out[i] = circledist::volume(ShapeTraits<S>::make(ptr.data(), s.points), *ptr[nf - 1]);
  }
}

void fill_volumes(const Shape& s, Index begin, Index end, Volume<double>* out) {
  const FieldElements e(s);
  visit_kind<double>(s.kind, [&](auto tag) { fill_volumes<typename decltype(tag)::type>(s, e, begin, end, out); });
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

// Runs build(interrupted) without the GIL, `interrupted` asking for Ctrl-C (SignalCheck) now and
// then: a build it stopped (BuildInterrupted) raises KeyboardInterrupt here.
template <class Build> auto interruptible(Build&& build) {
  SignalCheck signals;
  const Interrupted interrupted = std::ref(signals);
  try {
    py::gil_scoped_release release;
    return build(interrupted);
  } catch (const BuildInterrupted&) {
    signals.raise_if_seen();
    throw;
  }
}

// The hierarchy over a set's volumes, built without the GIL on up to `workers` threads.
BoundingVolumeHierarchy<double> tree_of(Volumes volumes, int workers) {
  return interruptible([&](const Interrupted& interrupted) {
    return BoundingVolumeHierarchy<double>(std::move(volumes), 4, workers, interrupted);
  });
}

// The culling of queries a against a set b: a's volumes, their spatial order, and the
// hierarchy over b's volumes. With workers to spare, a's side is made on a thread of its own
// while b's tree is built on the workers, so that each side's steps that one thread takes (the
// allocations, the tree's top, the order's last merge) run beside the other's work. The volumes
// and the tree's build stop on Ctrl-C (interruptible).
struct Culling {
  Volumes va;
  std::vector<BroadIndex> order;
  BoundingVolumeHierarchy<double> tree;

  Culling(const Shape& a, const Shape& b, int workers) {
    interruptible([&](const Interrupted& interrupted) {
      build(a, b, workers, interrupted);
      return 0;
    });
  }

 private:
  void build(const Shape& a, const Shape& b, int workers, const Interrupted& interrupted) {
    const auto volumes = [&](const Shape& s, int threads) {
      Volumes out(static_cast<size_t>(flat_size(s)));
      if (!run_in_chunks(
              flat_size(s), threads, [&](Index begin, Index end) { fill_volumes(s, begin, end, out.data()); },
              [&](Index) { return interrupted(); }))
        throw BuildInterrupted();
      return out;
    };
    const auto side_a = [&](int threads) {
      va = volumes(a, threads);
      order = spatial_order(va, threads);
    };
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
      tree = BoundingVolumeHierarchy<double>(volumes(b, workers), 4, workers, interrupted);
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

  StagedProgress(py::object progress, int stages, Index n)
      : user(std::move(progress)), per_stage(n), total(stages * n) {}

  // A callable progress(done, of) for stage s: it reports base + within(done, of) of `total` to
  // the caller's progress, each value once; None when the caller asked for no progress.
  template <class Within> py::object reporter(int s, Within within) const {
    if (user.is_none()) return py::none();
    return py::cpp_function(
        [user = user, last = last, base = s * per_stage, total = total, within](Index done, Index of) {
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
      const double fraction =
          of > 0 ? (double(first) + double(count) * double(done) / double(std::max<Index>(block, 1))) / double(of)
                 : 1.0;
      return Index(double(per_stage) * fraction);
    });
  }
  void finish() const {
    if (user.is_none() || *last == total) return;
    *last = total;
    if (!report_progress(user, total, total)) throw py::error_already_set();
  }
};

// The most candidate pairs pairs_within stores by default (16 bytes each, twice while they are
// sorted, and the answers' 24 bytes a pair on top): beyond them it refuses (max_pairs).
constexpr Index kDefaultMaxPairs = 100000000;

// A count with thousands separators, for messages.
std::string grouped(Index n) {
  std::string digits = std::to_string(n), out;
  for (size_t k = 0; k < digits.size(); ++k) {
    if (k > 0 && (digits.size() - k) % 3 == 0) out += ',';
    out += digits[k];
  }
  return out;
}

// max_pairs= of the pairs queries: None (no limit) or an integer >= 0; -1 stands for None.
Index max_pairs_of(const char* owner, py::handle max_pairs) {
  if (max_pairs.is_none()) return -1;
  constexpr const char* wanted = "an integer >= 0 or None";
  const long long value = integer_of(owner, "max_pairs", max_pairs, wanted);
  if (value < 0)
    throw py::value_error(std::string(owner) + ": max_pairs must be " + wanted + ", got " + std::to_string(value));
  return Index(value);
}

// Candidate pairs (i, j), i in [0, n), found by find(begin, end, out) over chunks of [0, n) (the
// positions of a spatial order of the queries) on `workers` threads, then sorted by (i, j): the
// same list for every worker count. find's positions [begin, end) must name queries no other
// chunk names (a permutation's positions do), so that each query's pairs come from one chunk:
// each chunk then counts its queries' pairs and moves them to their place alone, and no thread
// joins the parts by itself.
// max_pairs >= 0: the candidates are counted as they are found, query by query, and once more
// than max_pairs are, the search stops and MemoryError is raised (owner's name in its message):
// no more than max_pairs (and the last query's pairs on each thread) are ever held.
// `find` is type-erased: one copy of this function serves every caller (a template copy per
// caller's lambda cost the module 8 kB each), and a call per chunk or per query is nothing
// against the tree walk it makes.
using FindPairs = std::function<void(Index, Index, PairList&)>;
PairList chunked_pairs(Index n, int workers, const FindPairs& find, py::handle progress = py::none(),
                       Index max_pairs = -1, const char* owner = "pairs_within") {
  const Index chunk = chunk_size(n, workers);
  std::vector<PairList> parts(static_cast<size_t>((n + chunk - 1) / chunk));
  std::vector<size_t> start(size_t(n) + 1, 0);  // start[i + 1]: query i's pairs, then where they end
  std::atomic<Index> found{0};
  std::atomic<bool> over{false};
  run_released(
      n, workers,
      [&](Index begin, Index end) {
        PairList& part = parts[size_t(begin / chunk)];
        if (max_pairs < 0) {
          find(begin, end, part);
        } else {
          for (Index k = begin; k < end && !over.load(std::memory_order_relaxed); ++k) {
            const Index before = Index(part.size());
            find(k, k + 1, part);
            const Index added = Index(part.size()) - before;
            if (found.fetch_add(added, std::memory_order_relaxed) + added > max_pairs)
              over.store(true, std::memory_order_relaxed);
          }
          if (over.load(std::memory_order_relaxed)) {
            PairList().swap(part);
            return;
          }
        }
        for (const auto& p : part) ++start[size_t(p.first) + 1];
      },
      progress, chunk);
  if (over) {
    const std::string text =
        std::string(owner) + ": more than max_pairs=" + grouped(max_pairs) +
        " candidate pairs to test (pairs whose bounds put them within d, and the margin, of each "
        "other; every one would be held in memory): pass a smaller d, or a larger max_pairs (None: "
        "no limit)";
    PyErr_SetString(PyExc_MemoryError, text.c_str());
    throw py::error_already_set();
  }
  PairList out;
  std::vector<size_t> at;
  {
    py::gil_scoped_release release;
    for (size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
    out.resize(start.back());
    at.assign(start.begin(), start.end() - 1);
  }
  // Copying and sorting a large list takes a good part of a second: Ctrl-C is heard between chunks.
  run_released(
      Index(parts.size()), workers,
      [&](Index first, Index last) {
        for (Index k = first; k < last; ++k) {
          for (const auto& p : parts[size_t(k)]) out[at[size_t(p.first)]++] = p;
          PairList().swap(parts[size_t(k)]);
        }
      },
      py::none(), 1);
  run_released(n, workers, [&](Index first, Index last) {
    for (Index i = first; i < last; ++i)
      if (start[size_t(i) + 1] - start[size_t(i)] > 1)
        std::sort(out.begin() + std::ptrdiff_t(start[size_t(i)]), out.begin() + std::ptrdiff_t(start[size_t(i) + 1]));
  });
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
    g.widened = no_array<Field::Wide>();
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
    run_in_chunks(
        count, workers,
        [&](Index begin, Index end) {
          for (const Copy& c : copies) {
            for (Index i = begin; i < end; ++i) {
              const Index at = e.of(c.field, rows[i]) * c.width;
              std::copy_n(c.from + at, c.width, c.to + i * c.width);
              if (c.wide_from) std::copy_n(c.wide_from + at, c.width, c.wide_to + i * c.width);
            }
          }
        },
        [](Index) { return false; });  // a copy: over in milliseconds, no Ctrl-C check needed
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
      const std::string text = std::string(owner) + ": " + name +
                               " must be a circledist shape or an array of points, got " +
                               Py_TYPE(value.ptr())->tp_name + " (" + py::str(error.value()).cast<std::string>() + ")";
      if (error.matches(PyExc_ValueError)) throw py::value_error(text);
      throw py::type_error(text);
    } catch (const std::exception& error) {
      throw py::type_error(std::string(owner) + ": " + name + " must be a circledist shape or an array of points (" +
                           error.what() + ")");
    }
  }
};
}  // namespace
}  // namespace circledist::python
