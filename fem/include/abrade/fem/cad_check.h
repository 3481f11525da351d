#pragma once
// A STEP or IGES file checked by OpenCASCADE's own reader before Gmsh imports it: Gmsh 4.8
// transfers the shapes of a file whose entities failed to read (an unresolved reference, an
// entity of an unknown type, a parameter of the wrong kind) and OpenCASCADE then dereferences
// null handles and crashes the process. The reader's check list names the entity instead.
#include <string>

namespace abrade::fem
{
  /// Reads @p path (.step/.stp or .iges/.igs) with OpenCASCADE's STEP or IGES reader and its
  /// entity checks; throws InputError naming the file, the entity (#N) and the reader's message
  /// when the file cannot be parsed or an entity failed to read.
  void check_cad_file(const std::string &path);
} // namespace abrade::fem
