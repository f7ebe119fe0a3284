// The builders a declaration list is written with: one call per parameter, bound to a field of
// the job's settings struct S, either field(&S::x) or field(&S::engine, &EngineParams::x). The
// default is the field's value in S{}, so the engine's structs stay the one place of defaults.
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>

#include "choices.h"
#include "param.h"

namespace qd::params {

template <typename S, typename T>
struct Field {
  std::function<const T&(const S&)> read;
  std::function<T&(S&)> write;
};

template <typename S, typename T>
Field<S, T> field(T S::*m) {
  return {[m](const S& s) -> const T& { return s.*m; }, [m](S& s) -> T& { return s.*m; }};
}

template <typename S, typename E, typename T>
Field<S, T> field(E S::*outer, T E::*inner) {
  return {[outer, inner](const S& s) -> const T& { return s.*outer.*inner; },
          [outer, inner](S& s) -> T& { return s.*outer.*inner; }};
}

// Ranges.
inline Range greater_than(double lo) {
  return {lo, std::numeric_limits<double>::infinity(), true, false};
}
inline Range at_least(double lo) {
  return {lo, std::numeric_limits<double>::infinity(), false, false};
}
inline Range closed(double lo, double hi) { return {lo, hi, false, false}; }
inline Range below(double lo, double hi) { return {lo, hi, false, true}; }     // [lo, hi)
inline Range above_to(double lo, double hi) { return {lo, hi, true, false}; }  // (lo, hi]

// Why the speed-only parameters (threads, solver, method) are the command's alone.
inline const char* const kSpeedOnly =
    "It changes only the speed (the result does not depend on it, or only within the solver's "
    "tolerance), so the MeshLab filters choose it themselves (auto, all cores) and keep their "
    "dialog short: MeshLab 2020.09's dialog has no section for advanced parameters and must fit a "
    "laptop screen.";

namespace detail {

template <typename S>
Param<S> param(std::string name, Type type, Unit unit, std::string label, std::string help) {
  Param<S> p;
  p.name = std::move(name);
  p.type = type;
  p.unit = unit;
  p.label = std::move(label);
  p.help = std::move(help);
  return p;
}

template <typename S>
Param<S> with_default(Param<S> p) {
  p.default_value = p.get(S{});
  return p;
}

}  // namespace detail

namespace detail {

// A Real (T = double) or Integer (T = int) parameter.
template <typename S, typename T>
Param<S> number(Type type, std::string name, Field<S, T> f, Unit unit, Range range,
                std::string label, std::string help) {
  Param<S> p = param<S>(std::move(name), type, unit, std::move(label), std::move(help));
  p.range = range;
  p.get = [f](const S& s) { return Value(static_cast<double>(f.read(s))); };
  p.set = [f](S& s, const Value& v) {
    const double x = std::get<double>(v);
    f.write(s) = std::is_integral_v<T> ? static_cast<T>(std::lround(x)) : static_cast<T>(x);
  };
  return with_default(std::move(p));
}

}  // namespace detail

template <typename S>
Param<S> real(std::string name, Field<S, double> f, Unit unit, Range range, std::string label,
              std::string help) {
  return detail::number(Type::Real, std::move(name), f, unit, range, std::move(label),
                        std::move(help));
}

template <typename S>
Param<S> integer(std::string name, Field<S, int> f, Unit unit, Range range, std::string label,
                 std::string help) {
  return detail::number(Type::Integer, std::move(name), f, unit, range, std::move(label),
                        std::move(help));
}

// The number of threads, a speed-only parameter the command alone has (kSpeedOnly).
template <typename S>
Param<S> threads(Field<S, int> f, std::string help) {
  return integer("threads", f, Unit::Threads, closed(0, 1024), "Threads", std::move(help))
      .only(kCommand, kSpeedOnly);
}

template <typename S>
Param<S> boolean(std::string name, Field<S, bool> f, std::string label, std::string help) {
  Param<S> p = detail::param<S>(std::move(name), Type::Boolean, Unit::None, std::move(label),
                                std::move(help));
  p.get = [f](const S& s) { return Value(f.read(s) ? 1.0 : 0.0); };
  p.set = [f](S& s, const Value& v) { f.write(s) = std::get<double>(v) != 0; };
  return detail::with_default(std::move(p));
}

template <typename S, typename E>
Param<S> choice(std::string name, Field<S, E> f, const Choices<E>& table, std::string label,
                std::string help) {
  Param<S> p = detail::param<S>(std::move(name), Type::Choice, Unit::None, std::move(label),
                                std::move(help));
  for (const auto& entry : table) p.choices.emplace_back(entry.first);
  p.get = [f, &table](const S& s) { return Value(std::string(name_of(table, f.read(s)))); };
  p.set = [f, &table](S& s, const Value& v) {
    for (const auto& [text, value] : table)
      if (std::get<std::string>(v) == text) f.write(s) = value;
  };
  return detail::with_default(std::move(p));
}

template <typename S>
Param<S> save_file(std::string name, Field<S, std::string> f, std::string extension,
                   std::string label, std::string help) {
  Param<S> p = detail::param<S>(std::move(name), Type::SaveFile, Unit::None, std::move(label),
                                std::move(help));
  p.extension = std::move(extension);
  p.value_name = "FILE" + p.extension;
  p.get = [f](const S& s) { return Value(f.read(s)); };
  p.set = [f](S& s, const Value& v) { f.write(s) = std::get<std::string>(v); };
  return detail::with_default(std::move(p));
}

// A parameter written as text (value_name shows how): read gives the text of the settings'
// value, parse_into stores a text in the settings (a list adds its entries, so a repeated
// command option adds up) and throws ParamError on bad syntax.
template <typename S>
Param<S> text(std::string name, std::string value_name, Unit unit,
              std::function<std::string(const S&)> read,
              std::function<void(S&, const std::string&)> parse_into, std::string label,
              std::string help) {
  Param<S> p =
      detail::param<S>(std::move(name), Type::Text, unit, std::move(label), std::move(help));
  p.value_name = std::move(value_name);
  p.get = [read](const S& s) { return Value(read(s)); };
  p.set = [parse_into](S& s, const Value& v) { parse_into(s, std::get<std::string>(v)); };
  return detail::with_default(std::move(p));
}

}  // namespace qd::params
