"""pymeshlab lists each filter's declared parameters (filter_quasidev/params/, as `qd_reference
--json` gives them): the same names in the same order, of the declared types, with the declared
defaults (a choice as its index, a real as a float32); and takes a choice by its name."""
from __future__ import annotations

import json
import os
import subprocess

import numpy as np
import pytest

from pymeshlab_paths import BUILD, require_file, sample

QD_REFERENCE = os.path.join(BUILD, "bin", "qd_reference")


def declarations() -> dict:
    require_file(QD_REFERENCE, "build the qd_reference target")
    return json.loads(subprocess.run([QD_REFERENCE, "--json"], capture_output=True, text=True,
                                     check=True).stdout)


def expected_default(p: dict):
    if p["type"] == "choice":
        return p["choices"].index(p["default"])
    if p["type"] == "real":
        return float(np.float32(p["default"]))
    return p["default"]


@pytest.mark.parametrize("job", ["approximate", "segment", "flatten"])
def test_pymeshlab_lists_the_declared_parameters_and_defaults(meshset, job):
    declared = declarations()[job]
    values = meshset(sample("patches.ply")).filter_parameter_values(declared["python"])
    filters = [p for p in declared["parameters"] if p["fronts"] != "command"]
    assert list(values) == [p["name"] for p in filters]
    for p in filters:
        assert values[p["name"]] == expected_default(p), p["name"]
        assert type(values[p["name"]]) is type(expected_default(p)), p["name"]


def test_a_choice_is_taken_by_its_name(meshset):
    ms = meshset(sample("patches.ply"))
    fig = ms.apply_filter(declarations()["approximate"]["python"], target_mode="fixed", max_iter=1,
                          output_quality="displacement")
    assert max(fig["patch_iterations"]) == 1
    np.testing.assert_allclose(ms.current_mesh().vertex_scalar_array().max(), fig["max_displacement"], rtol=1e-6)
