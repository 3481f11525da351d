#pragma once
// Pictures of worn parts without a display: the surface of a VTK file (a knife's .vtu, a wall's
// .vtp, a deviation map) coloured by one of its fields, drawn by gnuplot's pm3d from two views,
// with a colour bar in mm. Several surfaces share one colour range, so that the design, mid-life
// and end-of-life pictures (or concepts side by side) compare at a glance.
#include <array>
#include <string>
#include <utility>
#include <vector>

namespace abrade::report
{
  struct SurfacePicture
  {
    std::string file;  ///< a VTK XML file (.vtu, .vtp)
    std::string field; ///< point or cell data [m], shown in mm
    std::string title; ///< above the picture
  };

  struct RenderOptions
  {
    std::string label = "wear depth [mm]"; ///< the colour bar's label, with its unit
    bool        signed_range = false;      ///< a range symmetric about 0 (deviations)
    /// Turn each surface into its principal axes (longest along x, shortest along y) before
    /// drawing: parts mounted at any angle (a grab's knives) are seen face on.
    bool align = false;
    /// The top of the colour range: this percentile of the values (1: the largest), so that a
    /// few hot triangles do not leave the rest in one colour.
    double top_percentile = 1;
    /// A field of categories 0, 1, ... (a face's role, say): each drawn in its colour, named
    /// on the colour bar; (name, colour as '#rrggbb'). Empty: a field in metres, drawn in mm.
    std::vector<std::pair<std::string, std::string>> categories;
    /// Text drawn at points of the surface [m] (a face's number at its centre), in a view only
    /// where the normal (unit; zero: always) faces the viewer; without align.
    struct Label
    {
      std::array<double, 3> at{};
      std::string           text;
      std::array<double, 3> normal{};
      bool                  marker = false; ///< a red circle at the point, the text beside it
    };
    std::vector<Label> labels;
    /// Lay a long part face on: when the first surface's largest extent is this many times its
    /// middle one or more (0: never), each surface is drawn in the first one's principal frame
    /// from its two sides, one above the other at full width, so that a 4 m x 0.3 m blade
    /// fills its panels instead of a strip of them.
    double face_on_elongation = 0;
    /// A zoom on a region: only the triangles whose centre lies within @p radius [m] of
    /// @p centre (radius 0: all), seen from the side the region's wear faces (its normals,
    /// weighted by area and the field, turned away from the part's middle), 35 degrees to
    /// either side of it.
    struct Crop
    {
      std::array<double, 3> centre{};
      double                radius = 0;
    } crop;
  };

  /// The size of @p file's surface [m]: its largest extent along x, y or z, and its triangles'
  /// mean edge (zeros: it cannot be read).
  struct SurfaceSize
  {
    double largest_extent = 0, mean_edge = 0;
  };
  SurfaceSize surface_size(const std::string &file);

  /// @p path made absolute and ready for gnuplot's `set output '...'` (a quote doubled): the
  /// picture named inside the run's directory, whatever gnuplot's working directory.
  std::string gnuplot_output_name(const std::string &path);
  /// @p text without the quotes that would end a gnuplot string.
  std::string quote_free(std::string text);

  /// Writes the triangles of @p picture's surface as gnuplot pm3d data into @p out (each
  /// triangle a 2 x 2 patch with its third corner doubled; coordinates in mm, the field times
  /// @p scale as the colour), appending the colours to @p values; false when the file or the
  /// field is missing.
  bool write_pm3d_surface(const SurfacePicture &picture, const std::string &out, double scale, std::vector<double> &values);

  /// Draws @p surfaces, one column each with two views (front above back), into
  /// @p directory/@p png (the data and the gnuplot script stay beside it); @p laid_face_on
  /// says whether a long part was laid face on (RenderOptions::face_on_elongation). Returns false (and
  /// leaves no picture) when a file cannot be read or gnuplot fails.
  bool render_surfaces(const std::string &directory, const std::string &png, const std::vector<SurfacePicture> &surfaces,
                       const RenderOptions &options = {}, bool *laid_face_on = nullptr);
} // namespace abrade::report
