"""The .mlx files of sample_meshes/ (shared with meshlabserver 2020.09) run through pymeshlab's
load_filter_script/apply_filter_script and give what apply_filter gives with the same values."""
from __future__ import annotations

import xml.etree.ElementTree as ET

import numpy as np
import pytest

from pymeshlab_paths import FILTER, sample

# script -> the sample mesh it is written for
SCRIPTS = {"default.mlx": "bumpy_cylinder.ply", "patches_fixed_seams.mlx": "patches.ply",
           "free_seams.mlx": "patches.ply", "keep_selected.mlx": "selected.ply",
           "whole_mesh.mlx": "patches.ply"}


def keyword_arguments(script: str, declared: dict) -> dict:
    """The script's parameter values as apply_filter keywords (enums by index, as pymeshlab
    accepts)."""
    params = ET.parse(sample(script)).getroot().find("filter").findall("Param")
    kwargs = {}
    for p in params:
        name, kind, value = p.get("name"), p.get("type"), p.get("value")
        assert name in declared, f"{script}: parameter {name} is not declared by the plugin"
        kwargs[name] = {"RichBool": lambda v: v == "true", "RichInt": int, "RichEnum": int,
                        "RichFloat": float, "RichString": str}[kind](value)
    return kwargs


@pytest.mark.parametrize("script", sorted(SCRIPTS))
def test_script_equals_apply_filter(meshset, script):
    ms = meshset(sample(SCRIPTS[script]))
    assert ET.parse(sample(script)).getroot().find("filter").get("name") == "Quasi-Developable Approximation"
    V0 = ms.current_mesh().vertex_matrix().copy()
    ms.load_filter_script(sample(script))
    ms.apply_filter_script()
    by_script = ms.current_mesh()
    ref = meshset(sample(SCRIPTS[script]))
    ref.apply_filter(FILTER, **keyword_arguments(script, ref.filter_parameter_values(FILTER)))
    np.testing.assert_allclose(by_script.vertex_matrix(), ref.current_mesh().vertex_matrix(),
                               rtol=0, atol=1e-12)
    np.testing.assert_allclose(by_script.vertex_scalar_array(), ref.current_mesh().vertex_scalar_array(),
                               rtol=1e-12, atol=1e-12)
    assert not np.array_equal(by_script.vertex_matrix(), V0)
