// The options of `quasidev flatten`, with their defaults from qd::FlattenParams.
#include <CLI/CLI.hpp>

#include "option_values.h"
#include "subcommand_options.h"

namespace qd::cli {

void add_flatten_options(CLI::App& job, FlattenOptions& o) {
  FlattenParams& p = o.params;
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
  valued(job, "--svg", "FILE.svg",
         "write the cutting pattern as SVG: outlines, piece labels,\nnotches at seam vertices, a "
         "scale bar",
         [&o](const std::string& v) { o.svg = v; });
  valued(job, "--dxf", "FILE.dxf",
         "write the cutting pattern as DXF (AutoCAD R12 polylines, one\nlayer per patch, "
         "notches on layers of their own)",
         [&o](const std::string& v) { o.dxf = v; });
  choices(job, "--unit", "U",
          "the model's length unit, written on the SVG's scale bar; mm,\ncm or in also make the "
          "SVG print at 1:1",
          kPatternUnits, o.unit);
  valued(job, "--max-iter", "N",
         "at most N ARAP iterations per piece; 0 = the initial layout\nonly" + by_default(p.max_iterations),
         [&p](const std::string& v) {
           p.max_iterations = whole_number("--max-iter", v, 0, 100000, "0");
         });
  valued(job, "--tolerance", "T",
         "stop a piece's ARAP iterations when its energy changes by\nless than T, relatively, "
         "0 <= T < 1" + by_default(p.tolerance),
         [&p](const std::string& v) {
           p.tolerance = non_negative("--tolerance", v);
           if (p.tolerance >= 1) usage("--tolerance must be below 1, got " + v);
         });
  valued(job, "--gap", "G",
         "space between pieces on the sheet, model units; 0 = 5 %\nof the largest piece's longer side" + by_default(p.gap),
         [&p](const std::string& v) { p.gap = non_negative("--gap", v); });
  valued(job, "--notch-spacing", "S",
         "a notch every S model units along the seams and at their\nends; 0 = an eighth of the "
         "largest piece's longer side" + by_default(p.notch_spacing),
         [&p](const std::string& v) { p.notch_spacing = non_negative("--notch-spacing", v); });
  choices(job, "--solver", "S",
          "sparse Cholesky of each piece's ARAP system: auto, cholmod,\neigen-llt or eigen-ldlt; "
          "same result",
          kSolverKinds, p.solver);
  valued(job, "--threads", "N",
         "pieces flattened at once; 0 = all cores; the result does not\ndepend on it" +
             by_default(p.threads),
         [&p](const std::string& v) { p.threads = whole_number("--threads", v, 0, 1024, "0 (all cores)"); });
}

}  // namespace qd::cli
