// The Python types that the compiled module's signatures name: help(), the Sphinx reference and
// the generated stubs (python/circledist/_core.pyi) show the arguments and results by them.
#pragma once

#include <pybind11/pybind11.h>
#include <pybind11/typing.h>

namespace circledist::python {

namespace py = pybind11;

inline bool accepts_any_object(PyObject*) { return true; }

// py::object under another name in signatures: the bindings take and return Python objects
// (array-likes, None, strings; floats or arrays depending on the batch), which pybind11 would
// show as `object`. Each alias accepts every object; the checks stay where they were.
#define CIRCLEDIST_TYPED_OBJECT(NAME, PYTHON_TYPE)                \
  class NAME : public py::object {                                \
   public:                                                        \
    PYBIND11_OBJECT_DEFAULT(NAME, py::object, accepts_any_object) \
  };                                                              \
  }                                                               \
  namespace pybind11::detail {                                    \
  template <> struct handle_type_name<circledist::python::NAME> { \
    static constexpr auto name = const_name(PYTHON_TYPE);         \
  };                                                              \
  }                                                               \
  namespace circledist::python {

CIRCLEDIST_TYPED_OBJECT(ShapeLike, "circledist._core.Shape | numpy.typing.ArrayLike")
CIRCLEDIST_TYPED_OBJECT(ArrayLike, "numpy.typing.ArrayLike")
CIRCLEDIST_TYPED_OBJECT(OptionalArrayLike, "numpy.typing.ArrayLike | None")
CIRCLEDIST_TYPED_OBJECT(PrecisionName, "typing.Literal['float32', 'float64', 'longdouble'] | None")
CIRCLEDIST_TYPED_OBJECT(SolverName, "typing.Literal['default', 'bracketing', 'companion', 'polished', 'eigen'] | None")
CIRCLEDIST_TYPED_OBJECT(ProgressLike, "bool | collections.abc.Callable[[int, int], object] | None")
CIRCLEDIST_TYPED_OBJECT(Array, "numpy.ndarray")
CIRCLEDIST_TYPED_OBJECT(Distances, "float | numpy.longdouble | numpy.ndarray")
CIRCLEDIST_TYPED_OBJECT(Flags, "bool | numpy.ndarray")
CIRCLEDIST_TYPED_OBJECT(OptionalShapeLike, "circledist._core.Shape | numpy.typing.ArrayLike | None")
CIRCLEDIST_TYPED_OBJECT(Number, "float")
CIRCLEDIST_TYPED_OBJECT(Count, "int")
CIRCLEDIST_TYPED_OBJECT(OptionalCount, "int | None")
CIRCLEDIST_TYPED_OBJECT(PairsResult, "tuple[numpy.ndarray, numpy.ndarray, numpy.ndarray]")
CIRCLEDIST_TYPED_OBJECT(NearestResult, "tuple[numpy.ndarray, numpy.ndarray]")
CIRCLEDIST_TYPED_OBJECT(MotionObject, "circledist._core.Motion")
CIRCLEDIST_TYPED_OBJECT(OptionalMotion, "circledist._core.Motion | None")
CIRCLEDIST_TYPED_OBJECT(ShapeObject, "circledist._core.Shape")

#undef CIRCLEDIST_TYPED_OBJECT

}  // namespace circledist::python
