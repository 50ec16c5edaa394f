// The table behind the parameters of mapper_params.h: one row per parameter, in declaration
// order, with what ParamTable() lists, the MapperParams member it names and its allowed values
// (bounds, or the names of a choice's values), and the check of one row's value. One table serves
// the listing, validation and access by name, so they cannot disagree; the rest of the code goes
// through mapper_params.h.
#pragma once

#include <limits>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "slamtune/slam/params/mapper_params.h"

namespace slamtune::slam {

// The member of MapperParams a row names.
using ParamMember =
    std::variant<bool MapperParams::*, int MapperParams::*, double MapperParams::*, RangeThresholdRule MapperParams::*,
                 NodeMode MapperParams::*, SolverKind MapperParams::*, CeresLoss MapperParams::*,
                 CeresLinearSolver MapperParams::*, CeresPreconditioner MapperParams::*,
                 CeresTrustStrategy MapperParams::*, CeresDoglegType MapperParams::*>;

// Allowed interval of a numeric parameter; open ends are strict.
struct ParamBounds {
  double lo = -std::numeric_limits<double>::infinity();
  bool lo_open = false;
  double hi = std::numeric_limits<double>::infinity();
  bool hi_open = false;
};

struct ParamRow {
  ParamInfo info;
  ParamMember member;
  ParamBounds bounds;
  std::vector<std::string> choices;  // choice parameters only: the names of their values, in enum order
};

// Every parameter, in declaration order (ParamTable() lists their `info`).
const std::vector<ParamRow>& ParamRows();
// nullptr when unknown.
const ParamRow* FindParamRow(std::string_view name);

// The value `member` has in `params`; a choice as the name of its value.
ParamValue ReadParamValue(const MapperParams& params, const ParamMember& member);
// A value as a params file or a listing writes it: true / false, a number (shortest round trip),
// or the text as it is.
std::string ParamValueText(const ParamValue& value);
// A value as messages show it: ParamValueText, with a text in quotes.
std::string FormatParamValue(const ParamValue& value);
// Whether `v` is finite and within `bounds`.
bool InParamBounds(double v, const ParamBounds& bounds);

// Throws the InputError "mapper parameter NAME = VALUE is out of range: must be RULE".
[[noreturn]] void ThrowParamOutOfRange(const ParamRow& row, const std::string& value);
// Throws that InputError when the row's value in `params` is outside its bounds or choices.
void CheckParamRow(const MapperParams& params, const ParamRow& row);

}  // namespace slamtune::slam
