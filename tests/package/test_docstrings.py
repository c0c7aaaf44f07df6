"""The help that help() and the API reference show: every public object of circledist (its
__all__, and the public methods and properties of its classes) has a NumPy-style docstring
whose examples run as doctests, and the compiled functions' signatures name real types."""

import doctest
import inspect
import re

import pytest

import circledist

PUBLIC = [name for name in circledist.__all__ if name != "__version__"]
SHAPE_CLASSES = ["Point", "Line", "Ray", "Segment", "Circle", "Disk", "Bezier", "Arc", "Annulus"]
QUERIES = ["distance", "closest_points", "within", "distance_if_within", "intersects"]


def sections(doc):
    """The NumPy-style section titles of a docstring (a title line underlined by dashes)."""
    lines = inspect.cleandoc(doc).splitlines()
    return {title.strip() for title, rule in zip(lines, lines[1:]) if rule.strip() and set(rule.strip()) == {"-"}}


def documented_parameters(doc):
    """The names the Parameters section lists ('a, b : ...' lists two)."""
    text = inspect.cleandoc(doc)
    match = re.search(r"^Parameters\n-+\n(.*?)(?:\n\n\w[\w ]*\n-+\n|\Z)", text, flags=re.S | re.M)
    if not match:
        return []
    names = []
    for line in match.group(1).splitlines():
        entry = re.match(r"^(\w+(?:, \w+)*) :", line)
        if entry:
            names += entry.group(1).split(", ")
    return names


def signature_parameters(obj):
    """The parameter names of a function, method or class constructor, in order. pybind11's
    objects carry their signature as the docstring's first line: name(a: type, *, b: type = x)."""
    target = obj.__init__ if inspect.isclass(obj) else obj
    try:
        parameters = inspect.signature(target).parameters
        return [name for name in parameters if name != "self"]
    except ValueError:  # a pybind11 function: read its signature line
        line = target.__doc__.splitlines()[0]
        inside = line[line.index("(") + 1 : line.rindex(") ->")]
        names, depth, start = [], 0, 0
        for i, char in enumerate(inside + ","):
            depth += char in "[(" and 1 or char in "])" and -1 or 0
            if char == "," and depth == 0:
                name = inside[start:i].split(":")[0].strip()
                if name not in ("self", "*", ""):
                    names.append(name)
                start = i + 1
        return names


def public_methods(cls):
    """Methods and properties defined on cls itself whose names do not start with '_'."""
    return [
        name
        for name, value in vars(cls).items()
        if not name.startswith("_") and (callable(value) or isinstance(value, (property, classmethod)))
    ]


def test_every_public_object_is_listed():
    """The test below covers every object of __all__: a new name must come with help."""
    assert set(PUBLIC) == set(SHAPE_CLASSES) | set(QUERIES) | {
        "Shape",
        "ClosestPoints",
        "Contact",
        "Motion",
        "Scene",
        "stats",
        "reset_stats",
        "SceneFileError",
        "read_scene",
        "write_scene",
        "pairs_within",
        "nearest",
        "figure",
        "first_contact",
        "closest_approach",
        "Approach",
    }


@pytest.mark.parametrize("name", PUBLIC)
def test_docstring_examples_run(name):
    """Each public object's examples (and those of its methods) pass as doctests."""
    obj = getattr(circledist, name)
    tests = [t for t in doctest.DocTestFinder(recurse=True).find(obj, name, globs={}) if t.examples]
    assert tests, f"{name} has no examples"
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
    for test in tests:
        runner.run(test)
    assert runner.failures == 0, f"{runner.failures} failing example(s) in {name}'s docstrings"


@pytest.mark.parametrize("name", PUBLIC)
def test_numpy_style_sections(name):
    """Functions and methods document Parameters (when they take any), Returns and Examples;
    classes built from arguments document Parameters and Examples."""
    obj = getattr(circledist, name)
    found = sections(obj.__doc__)
    assert "Examples" in found, name
    if inspect.isclass(obj):
        if name not in ("Shape", "ClosestPoints", "Contact", "Approach"):  # not built by users
            assert "Parameters" in found, name
        assert "Attributes" in found, name
        for method in public_methods(obj):
            member = getattr(obj, method)
            if isinstance(vars(obj)[method], property):
                assert vars(obj)[method].__doc__, f"{name}.{method}"
                continue
            found = sections(member.__doc__ or "")
            needed = {"Returns", "Examples"} | ({"Parameters"} if signature_parameters(member) else set())
            assert needed <= found, f"{name}.{method}: {sorted(found)}"
    else:
        assert "Returns" in found, name
        takes_arguments = name not in ("stats", "reset_stats")
        assert ("Parameters" in found) == takes_arguments, name


@pytest.mark.parametrize("name", SHAPE_CLASSES + ["Shape", "ClosestPoints", "Contact", "Approach"])
def test_properties_have_docstrings(name):
    cls = getattr(circledist, name)
    for attribute, value in inspect.getmembers(cls, lambda v: isinstance(v, property)):
        if not attribute.startswith("_"):
            assert value.__doc__ and value.__doc__.strip(), f"{name}.{attribute}"


@pytest.mark.parametrize("name", QUERIES)
def test_query_signatures_name_types(name):
    """pybind11 writes the signature as the docstring's first line; every argument has a type
    other than `object` (what a py::handle argument would show)."""
    signature = getattr(circledist, name).__doc__.splitlines()[0]
    assert signature.startswith(name + "(")
    assert ": object" not in signature and "-> object" not in signature, signature
    assert "a: circledist._core.Shape | numpy.typing.ArrayLike" in signature
    assert "precision: typing.Literal['float32', 'float64', 'longdouble'] | None = None" in signature


@pytest.mark.parametrize("name, answer", [("first_contact", "Contact"), ("closest_approach", "Approach")])
def test_motion_query_signatures_name_types(name, answer):
    signature = getattr(circledist, name).__doc__.splitlines()[0]
    assert ": object" not in signature and "-> object" not in signature, signature
    assert "motion_a: circledist._core.Motion | None = None" in signature
    assert "precision: typing.Literal['float32', 'float64', 'longdouble'] | None = None" in signature
    assert signature.endswith(f"-> circledist._core.{answer}")


@pytest.mark.parametrize("name", QUERIES)
def test_documented_choices_are_the_accepted_ones(name):
    """The precision and solver names in the docstrings are exactly those the module accepts
    (the ValueError text lists them)."""
    doc = getattr(circledist, name).__doc__
    precisions = re.search(r"precision : \{None, (.*?)\}", doc).group(1)
    solvers = re.search(r"solver : \{None, (.*?)\}", doc).group(1)
    with pytest.raises(ValueError, match="precision must be None, 'float32', 'float64' or 'longdouble'"):
        circledist.distance([0, 0, 0], [1, 0, 0], precision="half")
    assert precisions == "'float32', 'float64', 'longdouble'"
    with pytest.raises(ValueError) as error:
        circledist.distance([0, 0, 0], [1, 0, 0], solver="newton")
    accepted = set(re.findall(r"'(\w+)'", str(error.value).split(", got")[0]))
    assert set(re.findall(r"'(\w+)'", solvers)) == accepted
    for solver in accepted:
        assert circledist.distance([0, 0, 0], [1, 0, 0], solver=solver) == 1.0


def documented_callables():
    for name in PUBLIC:
        obj = getattr(circledist, name)
        if name in ("Shape", "ClosestPoints", "Contact", "Approach"):
            continue  # not built by users: no constructor parameters to document
        yield name, obj
        if inspect.isclass(obj):
            for method in public_methods(obj):
                if not isinstance(vars(obj)[method], property):
                    yield f"{name}.{method}", getattr(obj, method)


@pytest.mark.parametrize("name, obj", list(documented_callables()), ids=lambda v: v if isinstance(v, str) else "")
def test_documented_parameters_are_the_signature(name, obj):
    """The Parameters section lists exactly the parameters the signature has, in order."""
    assert documented_parameters(obj.__doc__) == signature_parameters(obj), name
