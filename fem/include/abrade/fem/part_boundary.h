#pragma once
// The boundary ids of a part's solid mesh once its faces are chosen (part_faces.h), whatever its
// geometry (the parametric knife, or a part from a file): the surface that wears, and the faces
// that are clamped (bolted or welded to the shell; the mesh motion holds them, they do not wear).

namespace abrade::fem
{
  enum PartBoundary : unsigned int
  {
    wearable_boundary = 1,
    clamped_boundary  = 2
  };
} // namespace abrade::fem
