// One user parameter of a job, declared once (approximate_params.cpp, segment_params.cpp,
// flatten_params.cpp): its name, type, unit, default, range, help and the older spellings the
// command still accepts, and how it is read from and written into the job's settings. The
// command's options (cli/declared_options.h), the MeshLab parameter lists of both generations
// (meshlab/declared_parameters.h), the JSON report's parameter block (cli/parameters_json.h) and
// docs/reference/ (qd_reference) are made from these declarations; tests check the .mlx samples
// and pymeshlab against them. Adding a parameter is one entry in its job's list.
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "common/error.h"

namespace qd::params {

using common::Error;

// A value a parameter refuses (Text: bad syntax); the message says what is wrong but not the
// parameter's name, which each front end writes in its own spelling.
struct ParamError : Error {
  using Error::Error;
};

enum class Type { Real, Integer, Boolean, Choice, Text, SaveFile };

// What a value measures. Lengths are in model units or in AE (the input's average edge length),
// and the parameter's name says which (suffix _ae).
enum class Unit {
  None,
  ModelUnits,
  AverageEdge,
  Degrees,
  Percent,
  Fraction,
  Faces,
  Iterations,
  Threads,
  Patches
};

// The interval a Real or Integer value must lie in.
struct Range {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;  // true: min itself is excluded
  bool max_open = false;
};

// Which front ends have a parameter; one that lacks it says why in ParamInfo::why_not.
enum Fronts : unsigned { kCommand = 1, kFilters = 2, kBoth = 3 };

// A value: the number of a Real, Integer or Boolean (0/1); the name of a Choice; the text of a
// Text or SaveFile.
using Value = std::variant<double, std::string>;

// Everything about a parameter but how it binds to a settings struct.
struct ParamInfo {
  std::string name;  // snake_case: the .mlx and pymeshlab name and the report's key; the
                     // command's option is --name with '-' for '_' (option_name())
  Type type = Type::Real;
  Unit unit = Unit::None;
  Range range;                       // Real and Integer
  std::vector<std::string> choices;  // Choice: the value names, in the MeshLab enum's order
  std::string label;                 // the MeshLab dialog's label
  std::string help;                  // one paragraph: the --help text, the tooltip, the docs
  Value default_value;
  std::vector<std::string> aliases;      // older command spellings ("--tolerance"); Boolean:
                                         // of the option that sets it
  std::vector<std::string> off_aliases;  // Boolean: older spellings of the --no- option
  std::string value_name;                // Text: how the value is written, e.g. "ID=X[,ID=X]"
  std::string extension;                 // SaveFile: the file type, e.g. ".svg"
  unsigned fronts = kBoth;
  std::string why_not;  // when fronts is not kBoth: why the other front end lacks it
};

// A parameter bound to the settings struct S of its job.
template <typename S>
struct Param : ParamInfo {
  std::function<Value(const S&)> get;
  // Stores a value of the parameter's type that lies in its range (Choice: one of its names).
  // Text: parses it and throws ParamError (a qd::common::Error) on bad syntax.
  std::function<void(S&, const Value&)> set;

  // Builders for a declaration list.
  Param alias(std::string spelling) && {
    aliases.push_back(std::move(spelling));
    return std::move(*this);
  }
  Param off_alias(std::string spelling) && {
    off_aliases.push_back(std::move(spelling));
    return std::move(*this);
  }
  Param only(Fronts where, std::string why) && {
    fronts = where;
    why_not = std::move(why);
    return std::move(*this);
  }
};

// The command's spelling of a parameter: "--" + name with '-' for '_'.
std::string option_name(const std::string& name);

// "" when v lies in r, else what v must be ("must be greater than 0", "must be a finite
// number", ...), for a message that names the parameter and v.
std::string range_violation(const Range& r, double v);

// r in words for --help, tooltips and the docs ("> 0", "0 to 90", "at least 1", ...); "" for
// an unbounded range.
std::string range_text(const Range& r);

// The unit's name ("model units", "AE", "degrees", ...); "" for Unit::None.
std::string unit_name(Unit u);

// v in its shortest form ("0.03", "1e-05", "30").
std::string number_text(double v);

// A value as the docs and --help show it: a number in shortest form, a Boolean as on/off, a
// text as itself ("" shown as "none").
std::string value_text(const ParamInfo& p, const Value& v);

// The ParamInfo part of each of params, in order.
template <typename S>
std::vector<ParamInfo> infos(const std::vector<Param<S>>& params) {
  return {params.begin(), params.end()};
}

}  // namespace qd::params
