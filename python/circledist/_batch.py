"""The batch axes of a shape's fields, in one place for the shapes of `circledist`, `Scene` and
`circledist.dask`: how many trailing (per-element) axes each constructor argument has, and how
an index of the leading (batch) axes applies to every field."""

import operator

import numpy as np

from . import _core

# Trailing dimensions of a field per element, by the field's role (src/shapes.hpp's table, read
# through _core._shape_fields): a vector (3,), a number (), control points (k + 1, 3).
ROLE_TRAILING_DIMS = {"vector": 1, "direction": 1, "length": 0, "angle": 0, "control_points": 2}
TRAILING_DIMS = {
    name: ROLE_TRAILING_DIMS[role]
    for fields in [*_core._shape_fields().values(), (_core._sweep_field(),)]
    for name, role in fields
}


def _not_an_index(kind, item, fancy):
    allowed = "integers, slices, ... and integer or boolean arrays" if fancy else "integers, slices and ..."
    return f"{kind}: only {allowed} index a batch, got {item!r}"


def batch_key(key, batch_shape, kind, *, fancy):
    """`key` as a tuple with one entry per batch axis (Ellipsis expanded, the missing trailing
    axes taken whole), to be followed by the fields' own axes. Integers, slices and one Ellipsis
    always; with `fancy`, integer and boolean arrays (and lists) too, as NumPy takes them.
    TypeError for other entries (None, which is not supported, floats), IndexError for more
    indices than batch axes, or an integer beyond int64 (out of bounds of any batch)."""
    items = list(key) if isinstance(key, tuple) else [key]
    out, given = [], 0
    for item in items:
        if item is Ellipsis or isinstance(item, slice):
            out.append(item)
            given += item is not Ellipsis
            continue
        if item is None:
            raise TypeError(
                f"{kind}: None (numpy.newaxis) is not supported in a batch index: a batch gains "
                "no new axes by indexing (give the fields of to_arrays() new axes and rebuild "
                "the shape with from_arrays())"
            )
        if isinstance(item, (bool, np.bool_)):
            raise TypeError(_not_an_index(kind, item, fancy))
        try:
            out.append(operator.index(item))
            given += 1
            continue
        except TypeError:
            pass
        array = np.asarray(item) if fancy and not isinstance(item, (str, bytes)) else None
        if array is not None and array.size == 0 and isinstance(item, (list, tuple)):
            array = array.astype(np.intp)  # [] selects nothing, as in NumPy
        if array is None or not (array.dtype == bool or np.issubdtype(array.dtype, np.integer)):
            raise TypeError(_not_an_index(kind, item, fancy))
        out.append(array)
        given += array.ndim if array.dtype == bool else 1
    ellipses = [i for i, item in enumerate(out) if item is Ellipsis]  # `is`: arrays compare elementwise
    if len(ellipses) > 1:
        raise IndexError(f"{kind}: an index can only have a single ellipsis ('...')")
    ndim = len(batch_shape)
    if given > ndim:
        raise IndexError(f"{kind}: too many indices for a batch of {ndim} dimension(s): {given} were given")
    fill = [slice(None)] * (ndim - given)
    out = out[: ellipses[0]] + fill + out[ellipses[0] + 1 :] if ellipses else out + fill
    _check_wide_integers(out, batch_shape, kind)
    return tuple(out)


_INT64 = np.iinfo(np.int64)


def _check_wide_integers(index, batch_shape, kind):
    """An integer index beyond int64 is out of bounds of every batch: NumPy would raise an
    OverflowError converting it (or call it no integer), so it is refused here, with NumPy's words
    for an index out of bounds. Integers within int64 are left to NumPy."""
    axis = 0
    for item in index:
        if isinstance(item, int) and not _INT64.min <= item <= _INT64.max:
            raise IndexError(f"{kind}: index {item} is out of bounds for axis {axis} with size {batch_shape[axis]}")
        axis += item.ndim if isinstance(item, np.ndarray) and item.dtype == bool else 1


def index_fields(fields, batch_shape, key, kind, broadcast_to, *, fancy):
    """Each field (name -> array) broadcast to the batch shape and indexed by `key` on the batch
    axes, its own axes kept."""
    index = batch_key(key, tuple(batch_shape), kind, fancy=fancy)
    out = {}
    for name, value in fields.items():
        core = TRAILING_DIMS[name]
        value = broadcast_to(value, tuple(batch_shape) + tuple(value.shape[value.ndim - core :]))
        out[name] = value[index + (slice(None),) * core]
    return out


def index_shape(shape, key):
    """shape[key] for a shape of `circledist` (Shape.__getitem__): a shape of the same kind whose
    fields are the batch's fields indexed as NumPy indexes an array of its batch shape (its own
    copy, as every shape holds its values)."""
    if not shape.batch_shape:
        raise TypeError(f"a single {shape.kind} (batch shape ()) cannot be indexed")
    fields = index_fields(shape.to_arrays(), shape.batch_shape, key, shape.kind, np.broadcast_to, fancy=True)
    return type(shape).from_arrays(fields)


def iterate_shape(shape):
    """iter(shape) (Shape.__iter__): the shapes along the first batch axis."""
    if not shape.batch_shape:
        raise TypeError(f"iteration over a single {shape.kind} (batch shape ())")
    return (index_shape(shape, i) for i in range(shape.batch_shape[0]))
