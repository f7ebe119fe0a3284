"""One definition per engine type: two headers of the engine (filter_quasidev/core/*/) that define
a struct or class of the same name in namespace qd break C++'s one-definition rule once both are
linked into one binary, and nothing warns: the linker keeps one of their inline members for both
(the segmentation's and the flattening's FaceGeometry did exactly that, and AddressSanitizer
caught the flattening freeing Eigen storage with operator delete). Nested types (indented) and
types in .cpp files (anonymous namespaces) are not at risk and not listed."""
import collections
import pathlib
import re

CORE = pathlib.Path(__file__).resolve().parents[2] / "filter_quasidev" / "core"
TOP_LEVEL_TYPE = re.compile(r"^(?:struct|class)\s+([A-Za-z_]\w*)\s*(?:final\s*)?[:{]", re.M)


def type_definitions():
    found = collections.defaultdict(list)
    for header in sorted(CORE.rglob("*.h")):
        for name in TOP_LEVEL_TYPE.findall(header.read_text(encoding="utf-8")):
            found[name].append(str(header.relative_to(CORE)))
    return found


def test_the_scan_finds_the_engine_types():
    found = type_definitions()
    assert "Params" in found and "SegmentParams" in found and "FlatTriangles" in found, sorted(found)


def test_no_two_engine_headers_define_the_same_type():
    clashes = {name: files for name, files in type_definitions().items() if len(files) > 1}
    assert not clashes, f"rename one of each: {clashes}"
