// The options of `quasidev segment`, with their defaults from qd::SegmentParams.
#include <CLI/CLI.hpp>

#include "option_values.h"
#include "subcommand_options.h"

namespace qd::cli {

namespace {

// An angle in degrees in (0, hi].
double angle(const std::string& option, const std::string& text, double hi) {
  const double v = positive(option, text);
  if (v > hi)
    usage(option + " must be at most " + std::to_string(static_cast<int>(hi)) + " degrees, got " + text);
  return v;
}

}  // namespace

void add_segment_options(CLI::App& job, SegmentOptions& o) {
  SegmentParams& p = o.params;
  add_job_options(job, o,
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
  valued(job, "--max-error", "DEG",
         "largest angle between a face normal and its patch's fitted\ncone, degrees, in (0, 90]" +
             by_default(p.max_error_deg),
         [&p](const std::string& v) { p.max_error_deg = angle("--max-error", v, 90); });
  valued(job, "--min-faces", "N", "smallest patch, in faces, N >= 1" + by_default(p.min_faces),
         [&p](const std::string& v) { p.min_faces = whole_number("--min-faces", v, 1, 1000000000, "1"); });
  valued(job, "--min-area", "A",
         "smallest patch as a fraction of the mesh area, 0 <= A < 1\n" + by_default(p.min_area),
         [&p](const std::string& v) {
           p.min_area = non_negative("--min-area", v);
           if (p.min_area >= 1) usage("--min-area must be below 1, got " + v);
         });
  valued(job, "--target", "N",
         "number of patches wanted; 0 = as many as the fit needs\n" + by_default(p.target_patches),
         [&p](const std::string& v) { p.target_patches = whole_number("--target", v, 0, 1000000000, "0"); });
  flag(job, "--keep-patches",
       "keep the input's patches: each is kept whole where it fits\nwithin --max-error; only the "
       "others are split",
       [&o] { o.keep_patches = true; });
  valued(job, "--crease", "DEG",
         "where the mesh is split, edges whose faces' normals differ\nby more than DEG degrees are "
         "kept as borders; 180 = none" + by_default(p.crease_deg),
         [&p](const std::string& v) { p.crease_deg = angle("--crease", v, 180); });
  valued(job, "--threads", "N",
         "threads; 0 = all cores; the result does not depend on it\n" + by_default(p.threads),
         [&p](const std::string& v) { p.threads = whole_number("--threads", v, 0, 1024, "0 (all cores)"); });
}

}  // namespace qd::cli
