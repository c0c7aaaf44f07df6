"""docs/derivations/references.md lists every source the derivations, the code and the README cite, and the
README links it."""

import pathlib
import re

ROOT = pathlib.Path(__file__).resolve().parents[2]
REFERENCES = (ROOT / "docs" / "derivations" / "references.md").read_text()

# The named methods and authors the sources cite; each one found in them must be in the list.
CITED_NAMES = [
    "Eberly",
    "Geometric Tools",
    "Halley",
    "Horner",
    "Estrin",
    "Brent",
    "Parlett",
    "Reinsch",
    "Cauchy",
    "Fujiwara",
    "Pellet",
    "Moré",
    "Sorensen",
    "Martinez",
    "Dekker",
    "Knuth",
    "Shewchuk",
    "Kahan",
    "hypot",
    "Casteljau",
    "Morton",
    "mpmath",
    "distance3d",
    "cKDTree",
]


def cited_sources():
    files = list((ROOT / "docs").rglob("*.md")) + [ROOT / "README.md"]
    for folder, pattern in (("cpp/include", "*.hpp"), ("src", "*.*pp"), ("python/circledist", "*.py")):
        files += (ROOT / folder).rglob(pattern)
    return {path: path.read_text() for path in files if path.name != "references.md"}


def test_every_cited_name_is_referenced():
    sources = cited_sources()
    text = "\n".join(sources.values())
    found = [name for name in CITED_NAMES if name in text]
    assert "Eberly" in found and "Brent" in found  # the scan reads the sources
    missing = [name for name in found if name.replace("Martinez", "Martínez") not in REFERENCES]
    assert not missing, f"cited but not in docs/derivations/references.md: {missing}"


def test_every_author_year_citation_is_referenced():
    """Citations written as 'Author 1997' or 'Author and Author, 1983' name listed authors."""
    citation = re.compile(r"\b([A-Z][a-zé]+)(?: and [A-Z][a-zé]+)?,? ((?:1[6-9]|20)\d\d)\b")
    for path, text in cited_sources().items():
        for author, year in citation.findall(text):
            if author in ("Debian", "Python", "Eigen", "Release", "Table"):  # not citations
                continue
            assert author.replace("Martinez", "Martínez") in REFERENCES, f"{path.name}: {author} {year}"
            assert year in REFERENCES, f"{path.name}: {author} {year}"


def test_the_two_notes_are_listed_by_title_author_and_year():
    assert "David Eberly, *Distance Between Line and Circle or Disk in 3D*" in REFERENCES
    assert "1999" in REFERENCES
    assert "**Note 001.** David Eberly" in REFERENCES


def test_linked_derivations_exist():
    for target in re.findall(r"\]\(([^)#]+\.md)\)", REFERENCES):
        assert (ROOT / "docs" / "derivations" / target).is_file(), target


def test_readme_links_the_references():
    assert "(docs/derivations/references.md)" in (ROOT / "README.md").read_text()
