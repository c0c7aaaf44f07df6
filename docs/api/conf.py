"""Sphinx configuration of circledist's API reference: `bash tools/run.sh docs` builds it into
build/docs (warnings are errors). The reference is read from the installed package's docstrings
(autodoc, NumPy style via numpydoc); the derivations in docs/*.md are included as they are
(myst-parser), so there is one copy of each."""

import pathlib

import circledist

DOCS = pathlib.Path(__file__).resolve().parent.parent

project = "circledist"
author = "circledist contributors"
release = version = circledist.__version__

extensions = ["sphinx.ext.autodoc", "sphinx.ext.mathjax", "numpydoc", "myst_parser"]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build"]

# The signatures pybind11 writes as each docstring's first line carry the types.
autodoc_docstring_signature = True
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
if not (DOCS / "line_disk.png").exists():
    suppress_warnings = ["image.not_readable"]

html_theme = "alabaster"
html_title = f"circledist {release}"
