"""Sphinx configuration of circledist's API reference: `bash tools/run.sh docs` builds it into
build/docs (warnings are errors). The reference is read from the installed package's docstrings
(autodoc, NumPy style via numpydoc); the pages on the shelves (guide/, derivations/, design/,
reports/) are Markdown read as they are (myst-parser), so there is one copy of each."""

import pathlib

import circledist

DOCS = pathlib.Path(__file__).resolve().parent

project = "circledist"
author = "circledist contributors"
release = version = circledist.__version__

extensions = ["sphinx.ext.autodoc", "sphinx.ext.mathjax", "numpydoc", "myst_parser"]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build"]

# The signatures pybind11 writes as each docstring's first line carry the types.
autodoc_docstring_signature = True
# A class takes its signature from its __init__ (whose docstring is the signature line alone).
autoclass_content = "both"
autodoc_member_order = "bysource"
autodoc_default_options = {"members": True, "undoc-members": False}
# The classes' Attributes sections document the properties; no autosummary tables of them.
numpydoc_show_class_members = False
numpydoc_xref_param_type = False

# The derivations write math as $...$ and $$...$$.
myst_enable_extensions = ["dollarmath"]
myst_heading_anchors = 3

# The sdist leaves the pictures out (pyproject.toml's sdist.exclude): built from it, the pages
# keep the images' alt text instead of failing; from the repository every image must be there.
if not (DOCS / "derivations" / "line_disk.png").exists():
    suppress_warnings = ["image.not_readable"]

html_theme = "alabaster"
html_title = f"circledist {release}"


def _without_self(app, what, name, obj, options, signature, return_annotation):
    """pybind11's constructor signatures start with `self: circledist._core.Circle`: not an
    argument a caller passes."""
    if signature and signature.startswith("(self"):
        signature = "(" + signature.partition(", ")[2] if ", " in signature else "()"
    return signature, return_annotation


def setup(app):
    app.connect("autodoc-process-signature", _without_self)
