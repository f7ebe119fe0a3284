// The names of the fixed-choice parameters' values, one table per parameter: the command parses
// them, the MeshLab enums list them in this order, the JSON report writes them.
#pragma once

#include <utility>
#include <vector>

#include "approximate/params.h"

namespace qd::params {

using approximate::ClampMode;
using approximate::Developability;
using approximate::SeamMode;
using approximate::SegmentFirst;
using approximate::SolveMethod;
using approximate::SolverKind;
using approximate::StopRule;
using approximate::TargetMode;
using approximate::ToleranceMode;

enum class QualityKind { Curvature, Displacement };  // what the output's vertex quality holds
enum class PatternUnit { Model, Millimetre, Centimetre, Inch };  // the model's length unit
enum class DxfStyle { Plain, Aama };  // the DXF pattern's layout: plain R12, or AAMA/ASTM D6673
enum class Paper { A4, Letter };      // the printable PDF's page size

template <typename T>
using Choices = std::vector<std::pair<const char*, T>>;

inline const Choices<ToleranceMode> kToleranceModes = {{"step", ToleranceMode::Step},
                                                       {"total", ToleranceMode::Total}};
inline const Choices<ClampMode> kClampModes = {{"scale", ClampMode::Scale},
                                               {"vertex", ClampMode::Vertex}};
inline const Choices<Developability> kDevelopability = {{"curve", Developability::Curve},
                                                        {"defect", Developability::Defect},
                                                        {"both", Developability::Both},
                                                        {"auto", Developability::Auto}};
inline const Choices<StopRule> kStopRules = {{"plateau", StopRule::Plateau},
                                             {"paper", StopRule::Paper}};
inline const Choices<SegmentFirst> kSegmentFirst = {
    {"auto", SegmentFirst::Auto}, {"never", SegmentFirst::Never}, {"always", SegmentFirst::Always}};
inline const Choices<SeamMode> kSeamModes = {{"fixed", SeamMode::Fixed}, {"free", SeamMode::Free}};
inline const Choices<TargetMode> kTargetModes = {
    {"fixed", TargetMode::Fixed},
    {"reproject", TargetMode::Reproject},
    {"refit", TargetMode::Refit},
    {"reproject-then-refit", TargetMode::ReprojectThenRefit}};
inline const Choices<SolverKind> kSolverKinds = {{"auto", SolverKind::Auto},
                                                 {"cholmod", SolverKind::Cholmod},
                                                 {"eigen-llt", SolverKind::EigenLLT},
                                                 {"eigen-ldlt", SolverKind::EigenLDLT}};
inline const Choices<SolveMethod> kSolveMethods = {{"auto", SolveMethod::Auto},
                                                   {"direct", SolveMethod::Direct},
                                                   {"iterative", SolveMethod::Iterative}};
inline const Choices<PatternUnit> kPatternUnits = {{"model", PatternUnit::Model},
                                                   {"mm", PatternUnit::Millimetre},
                                                   {"cm", PatternUnit::Centimetre},
                                                   {"in", PatternUnit::Inch}};
inline const Choices<DxfStyle> kDxfStyles = {{"plain", DxfStyle::Plain}, {"aama", DxfStyle::Aama}};
inline const Choices<Paper> kPapers = {{"a4", Paper::A4}, {"letter", Paper::Letter}};
inline const Choices<QualityKind> kQualityKinds = {{"curvature", QualityKind::Curvature},
                                                   {"displacement", QualityKind::Displacement}};

// The name of `value` in `choices` ("" if it has none).
template <typename T>
const char* name_of(const Choices<T>& choices, T value) {
  for (const auto& [name, v] : choices)
    if (v == value) return name;
  return "";
}

}  // namespace qd::params
