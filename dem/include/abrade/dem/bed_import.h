#pragma once
// Beds from elsewhere: particle positions and radii from a CSV table or a LIGGGHTS/LAMMPS text
// dump, so that a run starts from a bed another code made (a cross-code check needs one bed for
// both codes) or one a user generated or measured.
//
// CSV: a header naming the columns, in any order and case: x, y, z [m] and radius or diameter
// [m] are needed; id, vx, vy, vz [m/s] and wx, wy, wz [rad/s] are read when present (ids are
// otherwise 0 .. n-1, velocities 0). Other columns are ignored.
//
// Dump (LIGGGHTS' and LAMMPS' `dump custom`, text): the last snapshot in the file is read; its
// "ITEM: ATOMS" line names the columns: id, x y z (or xu yu zu), radius or diameter, and vx vy
// vz, omegax omegay omegaz when present. Scaled coordinates (xs) are refused: dump x y z.
//
// Every particle gets the given material (a dump's type and mass columns are not read: the
// mass follows from the material's density), and the bed passes the checks every bed read from
// a file passes (finite values, radii 1 um .. 10 m, inside Simulation/Domain, unique ids).
#include <string>

namespace abrade::dem
{
  class Simulation;

  /// Whether @p path names a bed to import (extension .csv, .dump, .lammpstrj or .liggghts)
  /// rather than an abrade bed file.
  bool is_imported_bed(const std::string &path);

  struct ImportedBed
  {
    std::size_t particles = 0;
    std::string format;        ///< "CSV table" or "LIGGGHTS/LAMMPS dump"
    long        timestep = -1; ///< of the dump's snapshot read (-1: a table)
  };

  /// Replaces the particles of @p sim with those of @p path (material @p material); InputError
  /// naming the file and line when it cannot be read or a particle fails a check.
  ImportedBed import_bed(Simulation &sim, const std::string &path, int material);
} // namespace abrade::dem
