"""The installed type stub and the docstrings are made from the engine's parameter declaration:
the stub is current, and it and the docstrings list every parameter the command declares
(qd_reference --json) except those about files (the pattern files' by their type, and seven
named ones), which arrays replace."""

import ast
import json
import pathlib
import subprocess

import pytest
import quasidev
from quasidev import _stub
from conftest import BUILD

FILE_ONLY = {"constraints_file", "output_quality", "colorize", "dxf_style", "unit", "paper",
             "marker_width"}


@pytest.fixture(scope="module")
def declared():
    text = subprocess.run([str(BUILD / "bin" / "qd_reference"), "--json"], check=True,
                          capture_output=True, text=True).stdout
    return {job: [p["name"] for p in d["parameters"]] for job, d in json.loads(text).items()}


def stub_functions():
    path = pathlib.Path(quasidev.__file__).with_name("__init__.pyi")
    tree = ast.parse(path.read_text())
    return path, {f.name: f for f in tree.body if isinstance(f, ast.FunctionDef)}


def test_the_installed_stub_is_current():
    path, _ = stub_functions()
    assert path.read_text() == _stub.stub_text()


@pytest.mark.parametrize("job", ["approximate", "segment", "flatten"])
def test_stub_and_docstring_list_every_declared_parameter(declared, job):
    _, functions = stub_functions()
    keywords = [a.arg for a in functions[job].args.kwonlyargs]
    expected = [name for name in declared[job]
                if name not in FILE_ONLY and not name.endswith("_file")]
    assert keywords == expected
    assert [p["name"] for p in quasidev.DECLARATION[job]] == expected
    doc = getattr(quasidev, job).__doc__
    for name in expected:
        assert f"\n    {name} : " in doc
