"""The wheel ships every subpackage: pyproject lists packages explicitly, and a subpackage left out of the list
imports from a source checkout (the tests' working directory) but not from an installed package."""

import tomllib
from pathlib import Path

ROOT = Path(__file__).parent.parent


def test_every_subpackage_is_listed_in_pyproject():
    listed = set(tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]["packages"])
    found = {".".join(p.parent.relative_to(ROOT).parts) for p in (ROOT / "lagrange").rglob("__init__.py")}
    assert found - listed == set(), f"subpackages missing from [tool.setuptools] packages: {sorted(found - listed)}"


def test_wheel_metadata_files_exist():
    """py.typed (PEP 561) is shipped as package data; the license file named in pyproject exists; CITATION.cff
    and CHANGELOG.md are at the top of the repository."""
    meta = tomllib.loads((ROOT / "pyproject.toml").read_text())
    assert "py.typed" in meta["tool"]["setuptools"]["package-data"]["lagrange"]
    assert (ROOT / "lagrange" / "py.typed").is_file()
    for name in meta["project"]["license-files"]:
        assert "MIT License" in (ROOT / name).read_text()
    assert "cff-version" in (ROOT / "CITATION.cff").read_text()
    assert (ROOT / "CHANGELOG.md").read_text().startswith("# Changelog")
