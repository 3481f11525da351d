// The lifetime loop's files besides trajectory.csv: the cross-sections per update and the
// gnuplot figures (lifetime_outputs.h).
#include <abrade/common/atomic_file.h>
#include <abrade/common/error.h>
#include <abrade/common/external.h>
#include <abrade/coupling/lifetime/lifetime_outputs.h>
#include <abrade/common/format_number.h>
#include <abrade/common/output_directory.h>
#include <abrade/coupling/lifetime/sections.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace abrade::coupling::lifetime
{
  namespace
  {
    std::string profile_name(double f)
    {
      char name[64];
      std::snprintf(name, sizeof name, "profile_%.2f", f);
      return name;
    }
  } // namespace

  std::string part_surface_name(const std::string &part, long update)
  {
    char number[32];
    std::snprintf(number, sizeof number, "_%05ld.stl", update);
    return part + number;
  }

  double plane_x(const ProfileFrame &frame, double f)
  {
    // (the ends a thousandth of the length inside: a plane on an end face lies in it, cuts nothing)
    return frame.x0 + std::clamp(f, 1e-3, 1 - 1e-3) * (frame.x1 - frame.x0);
  }

  ProfileFrame profile_frame(const fem::SolidSurface &design)
  {
    ProfileFrame f;
    if (design.vertices.empty())
      return f;
    double lo[3], hi[3];
    for (int c = 0; c < 3; ++c)
      lo[c] = hi[c] = design.vertices[0][c];
    for (const auto &p : design.vertices)
      for (int c = 0; c < 3; ++c)
        lo[c] = std::min(lo[c], p[c]), hi[c] = std::max(hi[c], p[c]);
    const double t = hi[1] - lo[1];
    f.x0 = lo[0], f.x1 = hi[0];
    f.y0 = lo[1] - 0.5 * t, f.y1 = hi[1] + 0.5 * t;
    f.z0 = lo[2], f.z1 = lo[2] + std::min(hi[2] - lo[2], 3 * t);
    return f;
  }

  void write_profiles(const fem::SolidSurface &s, const fem::SolidSurface &design, const ProfileFrame &frame,
                      const std::vector<double> &planes, long update, const std::string &dir)
  {
    for (double f : planes)
      {
        const double  x0    = plane_x(frame, f);
        const bool    first = update == 1;
        std::ofstream out(dir + "/" + profile_name(f) + ".csv", first ? std::ios::trunc : std::ios::app);
        out.precision(10);
        auto block = [&](const fem::SolidSurface &surface, long u) {
          for (const auto &c : io::plane_section(surface.as_polydata(), 0, x0))
            out << u << ' ' << c.u0 << ' ' << c.v0 << ' ' << c.u1 << ' ' << c.v1 << '\n';
          out << "\n\n";
        };
        if (first) // the design's outline as update 0
          out << "# update y0 z0 y1 z1 [m] (one segment per line; a block per update, update 0 the design)\n",
            block(design, 0);
        block(s, update);
      }
  }

  std::vector<std::string> truncate_profiles(const std::vector<double> &planes, long update, const std::string &dir)
  {
    std::vector<std::string> missing;
    for (double f : planes)
      {
        const std::string path = dir + "/" + profile_name(f) + ".csv";
        std::ifstream     in(path);
        if (!in)
          {
            missing.push_back(path);
            continue;
          }
        std::vector<std::string> lines;
        for (std::string l; std::getline(in, l);)
          lines.push_back(l);
        std::size_t last = lines.size(); // the last line that is not blank
        while (last > 0 && lines[last - 1].empty())
          --last;
        std::ostringstream keep;
        bool               kept = true; // the block the line is in; its blank separators go with it
        for (std::size_t n = 0; n < lines.size(); ++n)
          {
            const std::string &l = lines[n];
            if (l.empty() || l[0] == '#')
              {
                if (kept || !l.empty())
                  keep << l << '\n';
                continue;
              }
            // "update y0 z0 y1 z1"; a line cut by a crash can only be the last one
            std::istringstream words(l);
            long               u = 0;
            double             v[4];
            std::string        rest;
            const bool         ok = (words >> u >> v[0] >> v[1] >> v[2] >> v[3]) && !(words >> rest) && u >= 0 &&
                            std::isfinite(v[0] + v[1] + v[2] + v[3]);
            if (!ok && n + 1 == last)
              break;
            if (!ok)
              throw InputError(path + ":" + std::to_string(n + 1),
                               "not a profile line 'update y0 z0 y1 z1': '" + l.substr(0, 60) +
                                 "' (edited? delete the file to resume without the earlier profiles)");
            kept = u <= update;
            if (kept)
              keep << l << '\n';
          }
        in.close();
        io::write_file_atomically(path, keep.str());
      }
    return missing;
  }

  namespace
  {
    /// The trajectory plot's extra curves: the limits as horizontal lines, every followed point
    /// after the first, an extrapolation dashed to the predicted life (its data inline).
    std::string extra_curves(const TrajectoryMarks &marks)
    {
      std::ostringstream extra;
      if (marks.depth_limit > 0)
        extra << ", " << 1000 * marks.depth_limit << " with lines dt 3 lw 2 lc rgb 'red' title 'end of life: depth "
              << io::format_number(1000 * marks.depth_limit) << " mm'";
      if (marks.recession_limit > 0)
        extra << ", " << 1000 * marks.recession_limit
              << " with lines dt 3 lw 2 lc rgb 'dark-orange' title 'end of life: recession "
              << io::format_number(1000 * marks.recession_limit) << " mm'";
      if (marks.edge_limit > 0)
        extra << ", " << 1000 * marks.edge_limit
              << " with lines dt 4 lw 2 lc rgb 'dark-violet' title 'end of life: edge recession "
              << io::format_number(1000 * marks.edge_limit) << " mm'";
      if (marks.plate_limit > 0)
        extra << ", '' using (column('tonnes')/T):(column('plate_thickness')*1000) with linespoints title 'plate "
                 "thickness (calipers at Gauge height)', "
              << 1000 * marks.plate_limit << " with lines dt 5 lw 2 lc rgb 'brown' title 'end of life: plate thickness "
              << io::format_number(1000 * marks.plate_limit) << " mm'";
      // every followed point after the first (the first is drawn with the rest)
      for (std::size_t k = 2; k <= marks.recession_points; ++k)
        extra << ", '' using (column('tonnes')/T):(column('point_recession_" << k
              << "')*1000) with linespoints title 'recession of followed point " << k << "'";
      if (marks.extrapolated && marks.life > marks.last_tonnes)
        extra << ", '-' using ($1/T):2 with lines dt 2 lw 2 lc rgb 'black' title 'extrapolated to the predicted life'";
      return extra.str();
    }

    /// trajectory.png: depth, recessions and worn volume against the tonnes (t, kt or Mt,
    /// whichever the largest needs), the key below the plot, off the data; then the settings
    /// back for the cross-sections.
    void write_trajectory_plot(std::ostream &gp, const TrajectoryMarks &marks)
    {
      gp << "set terminal pngcairo size 900,650\nset grid\nset datafile separator ','\nset datafile columnheaders\n"
            "stats 'trajectory.csv' using (column('tonnes')) nooutput\n"
            "T = STATS_max >= 1e6 ? 1e6 : (STATS_max >= 1e3 ? 1e3 : 1)\n"
            "set output 'trajectory.png'\nset xlabel sprintf('handled material [%s]', T == 1e6 ? 'Mt' : (T == 1e3 ? 'kt' : 't'))\n"
            "set ylabel 'wear depth, recession [mm]'\nset y2label 'worn volume [cm^3]'\nset y2tics\nset ytics nomirror\n"
            "set xrange [0:*]\nset yrange [0:*]\nset y2range [0:*]\nset key outside below maxrows 2\n"
            "plot 'trajectory.csv' using (column('tonnes')/T):(column('max_depth')*1000*(1-column('wear_rate_spread'))):"
            "(column('max_depth')*1000*(1+column('wear_rate_spread'))) with filledcurves "
            "fs transparent solid 0.25 noborder title 'largest depth +- spread of the beds', "
            "'' using (column('tonnes')/T):(column('max_depth')*1000) with linespoints title 'largest wear depth (below the design)', "
            "'' using (column('tonnes')/T):(column('point_recession')*1000) with linespoints title 'recession of followed point 1', "
            "'' using (column('tonnes')/T):(column('edge_recession')*1000) with linespoints title 'edge recession (gauged along the edge)', "
            "'' using (column('tonnes')/T):(column('worn_volume')*1e6) axes x1y2 with linespoints title 'worn volume'"
         << extra_curves(marks) << "\n";
      if (marks.extrapolated && marks.life > marks.last_tonnes)
        // (inline data under the file's settings: comma-separated, a header line first; with
        // spaces and no header gnuplot skipped it, and the extrapolation was never drawn)
        gp << "tonnes,value\n" << marks.last_tonnes << "," << 1000 * marks.last_value << "\n" << marks.life << ","
           << 1000 * marks.limit << "\ne\n";
      gp << "unset xrange\nunset yrange\nunset y2range\n"
            "set datafile separator whitespace\nset datafile nocolumnheaders\nunset y2tics\nunset y2label\nset size ratio -1\n";
    }

    /// The profiles' cross-sections (part/profile_*.csv at @p planes, fractions of the
    /// length): the design's outline and the updates', zoomed to where they differ; each
    /// picture drawn is added to @p pictures.
    void write_profile_sections(std::ostream &gp, const std::string &dir, const std::vector<double> &planes,
                                const ProfileFrame &frame, std::vector<std::string> &pictures)
    {
      for (double f : planes)
        {
          const std::string name   = io::part_folder(dir) + "/" + profile_name(f);
          const auto        blocks = read_section_blocks(dir + "/" + name + ".csv");
          const auto        window = section_window(blocks);
          if (section_plot(gp, blocks, window, name + ".png",
                           "cross-section at " + io::format_number(f, 3) + " of the length (x = " +
                             io::format_number(1000 * plane_x(frame, f), 5) + " mm)" +
                             (window.zoomed ? ", zoomed to the wear" : "")))
            pictures.push_back(name + ".png");
        }
    }

    /// The cross-section through the place that ended the life (or the deepest point), cut
    /// from the design and every update's surface (part/part_N.stl), written to
    /// part/section_worst.csv; its picture added to @p pictures when drawn.
    void write_worst_section(std::ostream &gp, const std::string &dir, const WorstSection &worst,
                             std::vector<std::string> &pictures)
    {
      const std::string part = io::part_folder(dir);
      auto              stl  = [&](long u) { return dir + "/" + part + "/" + part_surface_name(part, u); };
      // normal to x, unless the surface there is a face square to x (a worn end): a plane
      // normal to x would lie in that face, not cut it; then the plane of the other two
      // axes that holds the face's normal best
      const std::array<double, 3> place = {worst.where[0], worst.where[1], worst.where[2]};
      int                         axis  = 0;
      try
        {
          const auto n = io::normal_magnitudes_near(stl(worst.updates), place);
          if (n[0] > 0.7)
            axis = n[1] < n[2] ? 1 : 2;
        }
      catch (const std::exception &)
        {
        }
      std::map<long, std::vector<Segment>> blocks;
      for (long u = 0; u <= worst.updates; ++u)
        try
          {
            blocks[u] = io::plane_section_of_file(stl(u), axis, place[axis]);
          }
        catch (const std::exception &) // (a file missing: that update is not drawn)
          {
          }
      const char       *axes = "xyz";
      const int         iu = (axis + 1) % 3, iv = (axis + 2) % 3;
      const std::string plane = std::string(1, axes[axis]) + " = " + io::format_number(1000 * place[axis], 5) + " mm";
      write_section_blocks(dir + "/" + part + "/section_worst.csv", blocks,
                           "section " + std::string(1, axes[axis]) + " " + io::format_number(place[axis], 10) +
                             ": u, v are " + axes[iu] + ", " + axes[iv]);
      auto         window = section_window(blocks);
      const double u = place[iu], v = place[iv];
      // a thin layer along a long face: centred on the place, five of its depths around it
      const double d = window.largest_distance;
      if (d > 0 && std::max(window.y1 - window.y0, window.z1 - window.z0) > 10 * d)
        window = {u - 5 * d, u + 5 * d, v - 5 * d, v + 5 * d, true, d};
      // the place itself inside, with a margin
      const double margin = 0.1 * std::max(window.y1 - window.y0, window.z1 - window.z0);
      window.y0 = std::min(window.y0, u - margin), window.y1 = std::max(window.y1, u + margin);
      window.z0 = std::min(window.z0, v - margin), window.z1 = std::max(window.z1, v + margin);
      SectionMark mark   = worst.mark;
      mark.shown         = true;
      mark.at            = {u, v};
      mark.lowest_points = mark.lowest_points && axis == 0; // (the gauge's sections are normal to x)
      if (!blocks.empty() && blocks.rbegin()->first != worst.updates)
        mark.text += " (the last surface found, " + part_surface_name(part, blocks.rbegin()->first) +
                     ", is drawn: a later one is missing)";
      if (section_plot(gp, blocks, window, part + "/section_worst.png",
                       "cross-section through where the life ended (" + plane + ")" +
                         (window.zoomed ? ", zoomed to the wear" : ""),
                       mark, std::string(1, axes[iu]).c_str(), std::string(1, axes[iv]).c_str()))
        pictures.push_back(part + "/section_worst.png");
    }
  } // namespace

  void plot_lifetime(const std::string &dir, const std::vector<double> &planes, const ProfileFrame &frame,
                     const TrajectoryMarks &marks, const WorstSection *worst)
  {
    std::ofstream gp(dir + "/lifetime.gp");
    write_trajectory_plot(gp, marks);
    std::vector<std::string> pictures = {"trajectory.png"};
    write_profile_sections(gp, dir, planes, frame, pictures);
    if (worst && worst->where.size() == 3)
      write_worst_section(gp, dir, *worst, pictures);
    gp.close();
    if (!gp)
      throw RunError("cannot write " + dir + "/lifetime.gp (disk full?)");
    io::run_gnuplot_for(dir, "lifetime.gp", pictures);
  }
} // namespace abrade::coupling::lifetime
