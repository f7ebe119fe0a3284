// quasidev._engine: the engine and the mesh files for the quasidev Python package
// (python/quasidev/). Its job functions take arrays the package has already converted
// (C-contiguous float64 positions, int64 indices and ids, bool flags) and the keyword parameters
// as numbers or strings; they copy the inputs, release the GIL while the engine runs and return
// new arrays owned by Python. qd::common::Error (the engine's refusals, bad parameters, unreadable
// files) becomes ValueError.
#include <nanobind/nanobind.h>
#include <nanobind/stl/map.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/variant.h>

#include <algorithm>
#include <optional>

#include "approximate/quasidev.h"
#include "approximate_params.h"
#include "approximate_problem.h"
#include "approximate_report_json.h"
#include "flatten/flatten.h"
#include "flatten_params.h"
#include "flatten_report_json.h"
#include "io/pattern_files.h"
#include "mesh_files.h"
#include "numpy_arrays.h"
#include "params_json.h"
#include "python_progress.h"
#include "python_settings.h"
#include "segment/segment.h"
#include "segment_params.h"
#include "segment_report_json.h"

namespace nb = nanobind;
using namespace qd;

namespace {

// The declaration of the parameters of `declared` that Python takes.
template <typename S>
params::Json python_declaration(const std::vector<params::Param<S>>& declared) {
  std::vector<params::ParamInfo> kept;
  for (const params::ParamInfo& p : params::infos(declared))
    if (python::in_python(p)) kept.push_back(p);
  return params::declaration_json(kept);
}

// The parameters Python takes, per job, as JSON text.
std::string declaration() {
  return params::Json{{"approximate", python_declaration(params::approximate_params())},
                      {"segment", python_declaration(params::segment_params())},
                      {"flatten", python_declaration(params::flatten_params())}}
      .dump();
}

nb::dict run_approximate(const python::VertexArray& V, const python::FaceArray& F,
                         std::optional<python::IdArray> patches,
                         std::optional<python::FlagArray> fixed, const python::Given& given,
                         nb::object progress) {
  const params::ApproximateSettings settings =
      python::settings_from(params::approximate_params(), given);
  const size_t n = V.shape(0);
  approximate::Problem problem = frontend::approximate_problem(
      python::positions_of(V), python::triangles_of(F, n),
      patches ? python::ids_of(*patches) : std::vector<int>{},
      fixed ? python::flags_of(*fixed) : std::vector<char>{}, settings);
  approximate::Result result = python::run_without_gil(
      std::move(progress),
      [&problem](const common::Progress& p) { return approximate::approximate(problem, p); });
  const int constrained =
      static_cast<int>(std::count(problem.constrained.begin(), problem.constrained.end(), char{1}));
  const std::string none;
  const std::vector<std::string> notes;
  const frontend::ReportContext context{none,
                                        none,
                                        settings,
                                        static_cast<int>(n),
                                        static_cast<int>(F.shape(0)),
                                        patches.has_value(),
                                        constrained,
                                        notes};
  nb::dict out;
  out["report"] = frontend::report_json(result, context);
  out["positions"] = python::numpy_positions(result.V);
  out["k_before"] = python::numpy_array(std::move(result.k_before), {n});
  out["k_after"] = python::numpy_array(std::move(result.k_after), {n});
  out["displacement"] = python::numpy_array(std::move(result.displacement), {n});
  const size_t segmented = result.segmented_patch.size();
  if (segmented > 0)
    out["patches"] = python::numpy_array(std::move(result.segmented_patch), {segmented});
  return out;
}

nb::dict run_segment(const python::VertexArray& V, const python::FaceArray& F,
                     std::optional<python::IdArray> patches,
                     std::optional<python::FlagArray> selected, const python::Given& given,
                     nb::object progress) {
  const params::SegmentSettings settings = python::settings_from(params::segment_params(), given);
  segment::SegmentProblem problem;
  problem.V = python::positions_of(V);
  problem.F = python::triangles_of(F, V.shape(0));
  if (settings.keep_patches && patches) problem.patch = python::ids_of(*patches);
  if (settings.selection_border && selected) problem.selected = python::flags_of(*selected);
  problem.params = settings.engine;
  segment::SegmentResult result = python::run_without_gil(
      std::move(progress),
      [&problem](const common::Progress& p) { return segment::segment(problem, p); });
  const int selected_faces =
      static_cast<int>(std::count(problem.selected.begin(), problem.selected.end(), char{1}));
  const std::string none;
  const std::vector<std::string> notes;
  const frontend::SegmentReportContext context{none,
                                               none,
                                               settings,
                                               static_cast<int>(V.shape(0)),
                                               static_cast<int>(F.shape(0)),
                                               patches.has_value(),
                                               selected_faces,
                                               notes};
  nb::dict out;
  out["report"] = frontend::segment_report_json(result, context);
  const size_t faces = result.patch.size();
  out["patches"] = python::numpy_array(std::move(result.patch), {faces});
  return out;
}

nb::dict run_flatten(const python::VertexArray& V, const python::FaceArray& F,
                     std::optional<python::IdArray> patches, const python::Given& given,
                     nb::object progress) {
  const params::FlattenSettings settings = python::settings_from(params::flatten_params(), given);
  flatten::FlattenProblem problem;
  problem.V = python::positions_of(V);
  problem.F = python::triangles_of(F, V.shape(0));
  if (patches) problem.patch = python::ids_of(*patches);
  problem.params = settings.engine;
  const flatten::FlattenResult result = python::run_without_gil(
      std::move(progress),
      [&problem](const common::Progress& p) { return flatten::flatten(problem, p); });
  const std::string none;
  const std::vector<std::string> notes;
  const frontend::FlattenReportContext context{
      none, none,  settings,  static_cast<int>(V.shape(0)), static_cast<int>(F.shape(0)),
      true, notes, result.log};
  const size_t m = static_cast<size_t>(result.uv.rows());
  std::vector<double> uv(6 * m);
  for (size_t f = 0; f < m; ++f)
    for (size_t k = 0; k < 6; ++k)
      uv[6 * f + k] = result.uv(static_cast<Eigen::Index>(f), static_cast<Eigen::Index>(k));
  nb::dict out;
  out["report"] = frontend::report_text(frontend::flatten_report(result, context));
  out["uv"] = python::numpy_array(std::move(uv), {m, 3, 2});
  out["stretch"] = python::numpy_array(result.stretch, {result.stretch.size()});
  params::FlattenSettings files = settings;  // the command's SVG and DXF writers, into text
  files.svg_file = "svg";
  files.dxf_file = "dxf";
  for (const auto& [kind, text] : io::pattern_files(files, result.pattern))
    out[kind.c_str()] = text;
  return out;
}

}  // namespace

NB_MODULE(_engine, m) {
  nb::register_exception_translator([](const std::exception_ptr& p, void*) {
    try {
      std::rethrow_exception(p);
    } catch (const common::Error& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  m.def("declaration", &declaration,
        "The parameters of each job as JSON text (name, type, unit, default, range, help).");
  m.def("approximate", &run_approximate, nb::arg("V"), nb::arg("F"), nb::arg("patches").none(),
        nb::arg("fixed").none(), nb::arg("params"), nb::arg("progress").none(),
        "The quasi-developable approximation of a checked mesh (see quasidev.approximate).");
  m.def("segment", &run_segment, nb::arg("V"), nb::arg("F"), nb::arg("patches").none(),
        nb::arg("selected").none(), nb::arg("params"), nb::arg("progress").none(),
        "The segmentation of a checked mesh into nearly developable patches (see "
        "quasidev.segment).");
  m.def("flatten", &run_flatten, nb::arg("V"), nb::arg("F"), nb::arg("patches").none(),
        nb::arg("params"), nb::arg("progress").none(),
        "The flattening of a checked mesh's patches (see quasidev.flatten).");
  m.def("read", &python::read_mesh_file, nb::arg("path"),
        "A PLY, OBJ or OFF file's arrays (see quasidev.read).");
  m.def("write", &python::write_mesh_file, nb::arg("path"), nb::arg("V"), nb::arg("F"),
        nb::arg("patches").none(), nb::arg("quality").none(), nb::arg("uv").none(),
        "Checked arrays as binary PLY, written atomically (see quasidev.write).");
}
