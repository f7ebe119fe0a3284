// The names of the three jobs in every front end: the command's subcommand, the MeshLab filter
// (menu text and .mlx name) and pymeshlab's name for it.
#pragma once

namespace qd::params {

struct JobNames {
  const char* command;
  const char* filter;
  const char* python;
};

inline constexpr JobNames kApproximateJob{"approximate", "Quasi-Developable Approximation",
                                          "apply_coord_quasi_developable_approximation"};
inline constexpr JobNames kSegmentJob{"segment", "Quasi-Developable Segmentation",
                                      "compute_segmentation_quasi_developable"};
inline constexpr JobNames kFlattenJob{"flatten", "Quasi-Developable Flattening",
                                      "compute_texcoord_quasi_developable_flattening"};

}  // namespace qd::params
