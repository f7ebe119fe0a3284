"""Generates the bad-input corpus of issue 6 (hostile and odd inputs for `quasidev`).

Each case is (name, file bytes, extra arguments, expectation); cases() are for `quasidev
approximate` and the approximation filter, flatten_cases() the same files for `quasidev flatten`
and the flattening filter, with the flattening's own bad parameters:
  "fail"  — the command must exit 1 (bad input) or 2 (bad arguments) with one stderr line;
  "odd"   — merely odd input: success, or a clean one-line failure; never a crash.
warned_cases() says which odd cases succeed with a warning and which vertices must stay put.
Usage: python3 make_bad_corpus.py DIR   writes DIR/<name>.ply and DIR/cases.json;
       python3 make_bad_corpus.py --table QUASIDEV   runs the command on every case and prints a
       Markdown table (case, exit status, message; and what `quasidev segment` does with the
       segment_cases() of the same file) for the README's "What happens on bad input".
"""
import json
import math
import pathlib
import struct
import subprocess
import sys
import tempfile


def ply_ascii(V, F, face_quality=None, vertex_flags=None):
    head = ["ply", "format ascii 1.0", f"element vertex {len(V)}",
            "property double x", "property double y", "property double z"]
    if vertex_flags is not None:
        head.append("property int flags")
    head += [f"element face {len(F)}", "property list uchar int vertex_indices"]
    if face_quality is not None:
        head.append("property float quality")
    head.append("end_header")
    rows = []
    for i, v in enumerate(V):
        row = " ".join(repr(float(c)) for c in v)
        rows.append(row + (f" {vertex_flags[i]}" if vertex_flags is not None else ""))
    for i, f in enumerate(F):
        row = f"{len(f)} " + " ".join(map(str, f))
        rows.append(row + (f" {face_quality[i]}" if face_quality is not None else ""))
    return ("\n".join(head + rows) + "\n").encode()


def ply_binary(V, F):
    head = (f"ply\nformat binary_little_endian 1.0\nelement vertex {len(V)}\n"
            "property double x\nproperty double y\nproperty double z\n"
            f"element face {len(F)}\nproperty list uchar int vertex_indices\nend_header\n")
    body = b"".join(struct.pack("<3d", *v) for v in V)
    body += b"".join(struct.pack("<B3i", 3, *f) for f in F)
    return head.encode() + body


def grid(n, height=lambda x, y: 0.1 * math.sin(2 * x) * math.cos(3 * y), scale=1.0):
    V = [(scale * x / n, scale * y / n, scale * height(x / n, y / n))
         for y in range(n + 1) for x in range(n + 1)]
    F = []
    for y in range(n):
        for x in range(n):
            a = y * (n + 1) + x
            F += [(a, a + 1, a + n + 2), (a, a + n + 2, a + n + 1)]
    return V, F


def tube(radius, n_around, n_along):
    """An open tube of height 2 along z, radius(t, z) at angle t and height fraction z, as rows
    of n_around vertices."""
    V, F = [], []
    for j in range(n_along + 1):
        for i in range(n_around):
            t, z = 2 * math.pi * i / n_around, j / n_along
            r = radius(t, z)
            V.append((r * math.cos(t), r * math.sin(t), 2 * z))
    for j in range(n_along):
        for i in range(n_around):
            a, b = j * n_around + i, j * n_around + (i + 1) % n_around
            F += [(a, b, b + n_around), (a, b + n_around, a + n_around)]
    return V, F


def cylinder(n_around=24, n_along=12, bump=0.05):
    return tube(lambda t, z: 1 + bump * math.exp(-((t - 1) ** 2 + (z - 0.5) ** 2) / 0.05),
                n_around, n_along)


def wavy_tube(n_around=24, n_along=16):
    """A tube rippled all round (no developable part), as rows of n_around vertices."""
    return tube(lambda t, z: 1 + 0.08 * math.sin(3 * t) * math.sin(2 * math.pi * z), n_around, n_along)


def polo_with_placket(n_around=24, n_along=16, column=6, seams=11):
    """A front and a back panel (patches 0, 1) with a placket (patch 2) sewn onto the front
    along `seams` edges of one column, each of which gets a third face: non-manifold edges.
    Returns V, F, patch ids and the vertices on those edges."""
    V, F = wavy_tube(n_around, n_along)
    patch = [0 if (k // 2) % n_around < n_around // 2 else 1 for k in range(len(F))]
    sewn = [j * n_around + column for j in range(seams + 1)]
    t = 2 * math.pi * (column + 0.5) / n_around
    flap = []
    for j, v in enumerate(sewn):
        flap.append(len(V))
        V.append((1.1 * math.cos(t), 1.1 * math.sin(t), V[v][2]))
    for j in range(seams):
        F += [(sewn[j], sewn[j + 1], flap[j + 1]), (sewn[j], flap[j + 1], flap[j])]
        patch += [2, 2]
    return V, F, patch, sewn


def panels_with_scraps(n_around=24, n_along=16, scraps=((5, 2), (200, 1), (400, 1), (600, 3))):
    """A tube cut into 4 × 4-cell panels, with a few scraps (first face, faces) of fewer than 4
    faces cut out as patches of their own (ids 100, 101, ...), their faces turned against the
    panel around them, so that they cannot be solved together with it (a scrap oriented like
    its panel would be). Returns V, F, patch ids and the scraps' vertices."""
    V, F = wavy_tube(n_around, n_along)
    patch = [(k // 2 % n_around) // 4 + 6 * ((k // 2 // n_around) // 4) for k in range(len(F))]
    kept = set()
    for n, (first, faces) in enumerate(scraps):
        for f in range(first, first + faces):
            patch[f] = 100 + n
            F[f] = (F[f][0], F[f][2], F[f][1])
            kept.update(F[f])
    return V, F, patch, sorted(kept)


def icosphere(levels=2):
    p = (1 + 5 ** 0.5) / 2
    V = [(-1, p, 0), (1, p, 0), (-1, -p, 0), (1, -p, 0), (0, -1, p), (0, 1, p), (0, -1, -p),
         (0, 1, -p), (p, 0, -1), (p, 0, 1), (-p, 0, -1), (-p, 0, 1)]
    F = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
         (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
         (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    V = [tuple(c / math.sqrt(sum(x * x for x in v)) for c in v) for v in V]
    for _ in range(levels):
        mid, F2 = {}, []

        def m(a, b):
            key = (min(a, b), max(a, b))
            if key not in mid:
                c = [(V[a][k] + V[b][k]) / 2 for k in range(3)]
                s = math.sqrt(sum(x * x for x in c))
                V.append(tuple(x / s for x in c))
                mid[key] = len(V) - 1
            return mid[key]
        for a, b, c in F:
            ab, bc, ca = m(a, b), m(b, c), m(c, a)
            F2 += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        F = F2
    return V, F


def cases():
    V, F = grid(12)
    good = ply_ascii(V, F)
    head = good[: good.index(b"end_header\n") + len(b"end_header\n")]
    binary = ply_binary(V, F)
    cV, cF = cylinder()
    out = [
        ("empty", b"", [], "fail"),
        ("header_only", head, [], "fail"),
        ("truncated_binary", binary[: len(binary) - 5], [], "fail"),
        ("wrong_vertex_count", good.replace(f"vertex {len(V)}".encode(),
                                            f"vertex {len(V) + 3}".encode()), [], "fail"),
        ("index_out_of_range", ply_ascii(V, F[:-1] + [(0, 1, len(V))]), [], "fail"),
        ("nan_coordinates", ply_ascii([(math.nan, 0, 0)] + V[1:], F), [], "fail"),
        ("inf_coordinates", ply_ascii(V[:-1] + [(0, math.inf, 0)], F), [], "fail"),
        ("negative_tolerance", good, ["--tolerance-ae", "-1"], "fail"),
        ("zero_iterations", good, ["--max-iter", "0"], "fail"),
        ("nan_weight", good, ["--weight", "nan"], "fail"),
        ("zero_area_faces", ply_ascii(V + [V[0], V[1]], F + [(0, 1, len(V) + 1)]), [], "odd"),
        ("duplicate_faces", ply_ascii(V, F + F[:5]), [], "odd"),
        ("inconsistent_orientation", ply_ascii(V + [(0.5, -0.5, 0.1)], F + [(0, 1, len(V))]), [],
         "odd"),
        ("non_manifold_vertex",
         ply_ascii(V + [(-1, -1, 0.3), (-1, 0, 0.2)], F + [(0, len(V), len(V) + 1)]), [], "odd"),
        ("isolated_vertices", ply_ascii(V + [(5, 5, 5), (6, 6, 6)], F), [], "odd"),
        ("single_triangle", ply_ascii([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, 2)]), [], "odd"),
        ("every_face_own_patch", ply_ascii(V, F, face_quality=list(range(len(F)))), [], "odd"),
        ("patch_all_selected", ply_ascii(cV, cF, face_quality=[0] * len(cF),
                                         vertex_flags=[0x20] * len(cV)), [], "odd"),
        ("closed_sphere", ply_ascii(*icosphere()), ["--developability", "curve"], "odd"),
        ("closed_sphere_defect_rows", ply_ascii(*icosphere()), [], "odd"),
        ("flat_patch", ply_ascii(*grid(10, height=lambda x, y: 0.0)), [], "odd"),
        ("huge_coordinates", ply_ascii(*grid(12, scale=1e12)), [], "odd"),
        ("tiny_coordinates", ply_ascii(*grid(12, scale=1e-12)), [], "odd"),
        ("bumpy_cylinder", ply_ascii(cV, cF), [], "odd"),
    ]
    for name, (data, _, _, _) in warned_cases().items():
        out.append((name, data, [], "odd"))
    bV, bF = grid(224, height=lambda x, y: 0.05 * math.sin(7 * x) * math.sin(5 * y))
    out.append(("hundred_thousand_patches", ply_binary_quality(bV, bF[:100000]), [], "odd"))
    return out


def warned_cases():
    """The cases a run completes while leaving part of the mesh as it is, by name: (file bytes,
    a regular expression its one warning must match, the vertices that must not move, vertices
    of which some must move)."""
    V, F = grid(12)
    pV, pF, pP, sewn = polo_with_placket()
    sV, sF, sP, scraps = panels_with_scraps()
    rest = lambda n, kept: sorted(set(range(n)) - set(kept))  # noqa: E731
    placket = set(range(len(pV) - len(sewn), len(pV)))
    return {
        "non_manifold_edge": (
            ply_ascii(V + [(0.5, 0.5, 1.0)], F + [(14, 0, len(V))]),
            r"1 non-manifold edge \(more than two faces; first: between vertices 0 and 14\): "
            r"their 2 vertices are kept fixed", [0, 14], rest(len(V), [0, 14])),
        "polo_placket": (
            ply_ascii(pV, pF, face_quality=pP),
            r"11 non-manifold edges \(more than two faces; first: between vertices 6 and 30\): "
            r"their 12 vertices are kept fixed", sewn, rest(len(pV), set(sewn) | placket)),
        "panels_with_scraps": (
            ply_ascii(sV, sF, face_quality=sP),
            r"4 patches have fewer than 4 faces \(first: patch 100, 2 faces\): left unchanged",
            scraps, rest(len(sV), scraps)),
    }


# What the MeshLab filter does with each case (meshlabserver 2020.09 and pymeshlab 2025.07):
# LOADER = MeshLab's own PLY importer refuses the file, so the filter never runs; None = the
# filter succeeds; otherwise a regular expression its one-line failure reason must match.
LOADER = "loader"
PLUGIN_OUTCOMES = {
    "empty": LOADER, "header_only": LOADER, "truncated_binary": LOADER,
    "wrong_vertex_count": LOADER, "index_out_of_range": LOADER,
    "nan_coordinates": r"1 vertex with NaN or infinite coordinates \(first: vertex 0\)",
    "inf_coordinates": r"1 vertex with NaN or infinite coordinates \(first: vertex 168\)",
    "negative_tolerance": r"Tolerance \(AE\) \(tolerance_ae\) must be greater than 0, got -1",
    "zero_iterations": r"Max iterations \(max_iter\) must be at least 1, got 0",
    "nan_weight": r"Developability weight \(weight\) must be a finite number, got nan",
    "zero_area_faces": r"1 zero-area face .*Remove Zero Area Faces",
    "duplicate_faces": r"5 duplicate faces \(first: faces 0 and 288 .*Remove Duplicate Faces",
    "inconsistent_orientation": r"Patch 0 is not consistently oriented .*Re-Orient",
    "non_manifold_vertex": None, "isolated_vertices": None,
    "single_triangle": r"Patch 0 has only 1 face \(1 patch has fewer than 4\)",
    "every_face_own_patch": r"Patch 0 has only 1 face \(288 patches have fewer than 4\)",
    "patch_all_selected": r"All 312 vertices are constrained",
    "closed_sphere": None,  # closed and one patch: segmented first (segment_first auto)
    "closed_sphere_defect_rows": None,
    "flat_patch": None, "huge_coordinates": None, "tiny_coordinates": None,
    "bumpy_cylinder": None,
    "hundred_thousand_patches": r"Patch 0 has only 1 face \(100000 patches have fewer than 4\)",
    "non_manifold_edge": None, "polo_placket": None, "panels_with_scraps": None,
}

# The command's options of the corpus -> the filter's parameters (the same parameters: one name
# and one meaning in every front end).
DEVELOPABILITY = ["curve", "defect", "both", "auto"]  # the filter's enum values, in order
_PLUGIN_PARAMETER = {"--tolerance-ae": ("tolerance_ae", float), "--max-iter": ("max_iter", int),
                     "--weight": ("weight", float),
                     "--developability": ("developability", DEVELOPABILITY.index)}


def plugin_parameters(args, table=None):
    """{filter parameter name: value} for a case's command-line arguments (table: option ->
    (parameter, type); default: the approximation's)."""
    out = {}
    for option, value in zip(args[::2], args[1::2]):
        name, kind = (table or _PLUGIN_PARAMETER)[option]
        out[name] = kind(value)
    return out


def flatten_cases():
    """The corpus for the flattening: every file of cases() that needs no approximation option
    (closed_sphere's file is closed_sphere_defect_rows'), then its own bad parameters on the
    good grid. Meshes the approximation refuses but that can be flattened (a single triangle,
    every face its own patch, every vertex selected, a closed sphere, which is cut open) are
    flattened, with their distortion reported."""
    good = ply_ascii(*grid(12))
    out = [(name, data, [], expect) for name, data, args, expect in cases() if not args]
    out += [("negative_tolerance", good, ["--arap-tolerance", "-1"], "fail"),
            ("tolerance_one", good, ["--arap-tolerance", "1"], "fail"),
            ("negative_iterations", good, ["--arap-max-iter", "-1"], "fail"),
            ("nan_gap", good, ["--gap", "nan"], "fail"),
            ("negative_notch_spacing", good, ["--notch-spacing", "-1"], "fail")]
    return out


# The flattening filter's parameters for the options of flatten_cases().
# The segmentation's own bad value of the same kind for each approximation option of cases()
# (None: the option only steers the approximation and is dropped), and its filter parameters.
_SEGMENT_OPTION = {("--tolerance-ae", "-1"): ["--max-error-deg", "-1"], ("--max-iter", "0"): ["--min-faces", "0"],
                   ("--weight", "nan"): ["--crease-deg", "nan"], ("--developability", "curve"): []}
SEGMENT_PARAMETERS = {"--max-error-deg": ("max_error_deg", float), "--min-faces": ("min_faces", int),
                      "--crease-deg": ("crease_deg", float)}


def segment_cases():
    """The corpus for the segmentation: every case of cases(), its options replaced by the
    segmentation's (_SEGMENT_OPTION)."""
    return [(name, data, [word for pair in zip(args[::2], args[1::2]) for word in _SEGMENT_OPTION[pair]],
             expect) for name, data, args, expect in cases()]


FLATTEN_PARAMETERS = {"--arap-tolerance": ("arap_tolerance", float), "--arap-max-iter": ("arap_max_iter", int),
                      "--gap": ("gap", float), "--notch-spacing": ("notch_spacing", float)}

# What the flattening filter does with each of flatten_cases(), as PLUGIN_OUTCOMES.
FLATTEN_PLUGIN_OUTCOMES = {
    **{name: PLUGIN_OUTCOMES[name] for name in (
        "empty", "header_only", "truncated_binary", "wrong_vertex_count", "index_out_of_range",
        "nan_coordinates", "inf_coordinates", "zero_area_faces", "duplicate_faces",
        "inconsistent_orientation")},
    **{name: None for name in (
        "non_manifold_vertex", "isolated_vertices", "single_triangle", "every_face_own_patch",
        "patch_all_selected", "closed_sphere_defect_rows", "flat_patch", "huge_coordinates",
        "tiny_coordinates", "bumpy_cylinder", "non_manifold_edge", "polo_placket",
        "panels_with_scraps", "hundred_thousand_patches")},
    "negative_tolerance": r"ARAP tolerance \(arap_tolerance\) must not be negative, got -1",
    "tolerance_one": r"ARAP tolerance \(arap_tolerance\) must be below 1, got 1",
    "negative_iterations": r"Max ARAP iterations \(arap_max_iter\) must not be negative, got -1",
    "nan_gap": r"Gap between pieces \(gap\) must be a finite number, got nan",
    "negative_notch_spacing": r"Notch spacing \(notch_spacing\) must not be negative, got -1",
}


def ply_binary_quality(V, F):
    head = (f"ply\nformat binary_little_endian 1.0\nelement vertex {len(V)}\n"
            "property double x\nproperty double y\nproperty double z\n"
            f"element face {len(F)}\nproperty list uchar int vertex_indices\n"
            "property float quality\nend_header\n")
    body = b"".join(struct.pack("<3d", *v) for v in V)
    body += b"".join(struct.pack("<B3if", 3, *f, float(i)) for i, f in enumerate(F))
    return head.encode() + body


def main(directory):
    d = pathlib.Path(directory)
    d.mkdir(parents=True, exist_ok=True)
    index = []
    for name, data, args, expect in cases():
        (d / f"{name}.ply").write_bytes(data)
        index.append({"name": name, "file": f"{name}.ply", "args": args, "expect": expect})
    (d / "cases.json").write_text(json.dumps(index, indent=1) + "\n")


def run_case(binary, directory, name, data, args, subcommand=()):
    """(exit status, what `quasidev` said on stderr: the "quasidev: error: " prefix, the file name
    and the temporary folder taken out; warnings after "success; warning: ", one after another)."""
    src = pathlib.Path(directory) / f"{name}.ply"
    src.write_bytes(data)
    r = subprocess.run([binary, *subcommand, str(src), str(pathlib.Path(directory) / "out.ply"), "--quiet", *args],
                       capture_output=True, text=True, timeout=600)
    lines = [line.removeprefix("quasidev: error: ").removeprefix(f"'{src}': ").replace(str(src), f"{name}.ply")
             for line in r.stderr.strip().splitlines()]
    said = " ".join(line.replace("quasidev: warning: ", "") for line in lines)
    if said and r.returncode == 0:
        said = "success; warning: " + said
    return r.returncode, (said or "success").replace("|", "\\|")


def table(binary):
    """Prints the README's table: each case, quasidev's exit status and its message, and in the
    last column what `quasidev segment` does with the same file and the segmentation's own bad
    option of the same kind (segment_cases(); "same" when exit status and message are those of
    the approximation)."""
    print("| input | exit | what `quasidev` says | `quasidev segment`: exit, what it says |")
    print("|---|---|---|---|")
    with tempfile.TemporaryDirectory() as d:
        for (name, data, args, _), (_, _, seg_args, _) in zip(cases(), segment_cases()):
            code, said = run_case(binary, d, name, data, args)
            seg_code, seg_said = run_case(binary, d, name, data, seg_args, ["segment"])
            label = name.replace("_", " ") + (f" (`{' '.join(args)}`)" if args else "")
            segment = "same" if (seg_code, seg_said) == (code, said) else f"{seg_code}, {seg_said}"
            if seg_args != args:
                segment = f"`{' '.join(seg_args)}`: {segment}" if seg_args else f"(the option dropped) {segment}"
            print(f"| {label} | {code} | {said} | {segment} |")


if __name__ == "__main__":
    if len(sys.argv) > 2 and sys.argv[1] == "--table":
        table(sys.argv[2])
    else:
        main(sys.argv[1] if len(sys.argv) > 1 else "bad_corpus")
