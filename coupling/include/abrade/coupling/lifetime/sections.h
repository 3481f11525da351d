#pragma once
// Cross-sections of the part (planes normal to its length, x in its frame) and their pictures:
// the design's outline and the worn outlines of the updates, drawn zoomed to where they differ,
// with the quantity that ended the life marked (part/profile_F.png, part/section_worst.png).
// No deal.II here.
#include <abrade/common/plane_section.h>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace abrade::coupling::lifetime
{
  /// A piece of a section's outline in the plane's coordinates (y, z as u, v) [m]: the
  /// sections are cut by io::plane_section (VTK's cutter) in the planes x = const.
  using Segment = io::SectionSegment;

  /// A section file's blocks: update -> its segments (part/profile_F.csv: lines
  /// 'update y0 z0 y1 z1', update 0 the design); an empty map when the file cannot be read.
  std::map<long, std::vector<Segment>> read_section_blocks(const std::string &file);

  /// Writes @p blocks as a section file (the format read_section_blocks reads), @p comment
  /// (where the plane lies) on its first line.
  void write_section_blocks(const std::string &file, const std::map<long, std::vector<Segment>> &blocks,
                            const std::string &comment = "");

  /// What a section's picture shows: the window [m] and whether it was zoomed to the wear
  /// (where the last outline lies off the design's by a fifth of the largest distance or
  /// more, with a margin), else the whole section.
  struct SectionWindow
  {
    double y0 = 0, y1 = 0, z0 = 0, z1 = 0;
    bool   zoomed = false;
    double largest_distance = 0; ///< [m] between the design's outline and the last one
  };
  SectionWindow section_window(const std::map<long, std::vector<Segment>> &blocks);

  /// The quantity that ended the life, drawn where it was measured (only in the section
  /// through that place): a marker at @p at (y, z) [m], a line of text, and for the gauged
  /// edge the design's and the worn outline's lowest points as lines (the height gauge's
  /// reading between them), for the depth an arrow to the design's outline.
  struct SectionMark
  {
    bool                  shown = false;
    std::array<double, 2> at{};
    std::string           text;
    bool                  lowest_points = false; ///< the edge gauge's two levels
    bool                  to_design     = false; ///< an arrow to the nearest point of the design
  };

  /// The gnuplot commands that draw @p blocks (the design black and thick, up to six updates
  /// spread over the run, the last among them) into @p png in @p window, titled @p title;
  /// false when there is nothing to draw.
  /// @p u_name, @p v_name: the plane's axes (y, z for a plane normal to x).
  bool section_plot(std::ostream &gp, const std::map<long, std::vector<Segment>> &blocks, const SectionWindow &window,
                    const std::string &png, const std::string &title, const SectionMark &mark = {},
                    const char *u_name = "y", const char *v_name = "z");
} // namespace abrade::coupling::lifetime
