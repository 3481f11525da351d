#pragma once
// The subsection "Grab mechanism" of a case: the mechanism that moves a grab's walls (Type =
// rope: a rope grab, dem/rope_grab_driver.h), declared, read and checked against the walls.
#include <abrade/coupling/parameters/parameter_file.h>
#include <abrade/coupling/parameters/parameters.h>

namespace abrade::coupling
{
  void declare_grab_mechanism(dealii::ParameterHandler &prm);
  /// Reads it into @p c (whose phases and walls, knives mounted, are read): the walls it names
  /// must be there without a motion of their own; a knife mounted on one of its shells rides
  /// with that shell.
  void read_grab_mechanism(ParameterFile &f, DemCase &c);
} // namespace abrade::coupling
