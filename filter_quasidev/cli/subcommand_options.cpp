// The options of each subcommand: the files every job has (option_values.h), with what INPUT
// and OUTPUT hold for this job, and the options of its declared parameters (declared_options.h).
#include "subcommand_options.h"

#include <CLI/CLI.hpp>

#include "approximate_params.h"
#include "declared_options.h"
#include "flatten_params.h"
#include "segment_params.h"

namespace qd::cli {

void add_approximate_options(CLI::App& job, ApproximateOptions& o) {
  add_job_options(job, o,
                  std::string(kInputHelp) +
                      " PLY\nvertices whose `flags` have the selection bit 0x20 are\n"
                      "constrained (never move). Polygons are fan-triangulated (said on\n"
                      "stderr).",
                  "binary little-endian PLY: same vertex and face order, x y z as\n"
                  "double, every other input property and element unchanged\n"
                  "(texture coordinates, face quality, flags, ...; vertex normals\n"
                  "are recomputed), plus vertex `quality` and a `red green blue\n"
                  "alpha` colour ramp (red = low, blue = high, range = the 2nd to\n"
                  "98th percentile). Written to a temporary file and renamed into\n"
                  "place only on success; an existing OUTPUT is left untouched on\n"
                  "error.",
                  "write every figure (per patch and per iteration) as JSON");
  add_declared_options(job, params::approximate_params(), o.settings);
}

void add_segment_options(CLI::App& job, SegmentOptions& o) {
  add_job_options(
      job, o,
      "PLY (ascii or binary), OBJ or OFF. With --keep-patches, the\n"
      "PLY face `quality` (rounded; else an integer face `patch`) or\n"
      "OBJ `g`/`o` groups are the existing patches. PLY faces whose\n"
      "`flags` have the selection bit 0x20 are selected: the border\n"
      "between selected and other faces is kept. Polygons are\n"
      "fan-triangulated (said on stderr).",
      "binary little-endian PLY: the input unchanged (same vertices,\n"
      "faces, order and every property) except the face `quality` =\n"
      "patch id 0..k-1 and a face `red green blue alpha` colour per\n"
      "patch, which replace the input's. Written atomically: an\n"
      "existing OUTPUT is left untouched on error.",
      "write every patch's figures (faces, area, proxy, fit error,\nboundary loops, disk) as JSON");
  add_declared_options(job, params::segment_params(), o.settings);
}

void add_flatten_options(CLI::App& job, FlattenOptions& o) {
  add_job_options(job, o, kInputHelp,
                  "binary little-endian PLY: the input unchanged (same vertices,\n"
                  "faces, order and every property, bit for bit) plus per face\n"
                  "`texcoord` (u v of each corner, in model units: 1 unit on the\n"
                  "pattern is 1 unit on the mesh; pieces side by side, not\n"
                  "overlapping), `quality` = signed stretch (largest singular\n"
                  "value of the 3D-to-2D map minus 1, negative where compression\n"
                  "is larger) and a `red green blue alpha` ramp on it (green = no\n"
                  "stretch, blue = stretched, red = compressed); these replace\n"
                  "the input's face texcoord, quality and colour. Written\n"
                  "atomically, as every other file.",
                  "write every piece's figures (distortion, area and boundary\nchange, flips, "
                  "overlaps, cut, iterations) as JSON");
  add_declared_options(job, params::flatten_params(), o.settings);
}

}  // namespace qd::cli
