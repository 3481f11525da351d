// Cross-sections' pictures: the window that shows the wear, and the gnuplot that draws the
// outlines in it (sections.h).
#include <abrade/common/format_number.h>
#include <abrade/coupling/lifetime/sections.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace abrade::coupling::lifetime
{
  std::map<long, std::vector<Segment>> read_section_blocks(const std::string &file)
  {
    std::map<long, std::vector<Segment>> blocks;
    std::ifstream                        in(file);
    for (std::string line; std::getline(in, line);)
      {
        if (line.empty() || line[0] == '#')
          continue;
        std::istringstream words(line);
        long               u = 0;
        Segment            s;
        if ((words >> u >> s.u0 >> s.v0 >> s.u1 >> s.v1) && std::isfinite(s.u0 + s.v0 + s.u1 + s.v1))
          blocks[u].push_back(s);
      }
    return blocks;
  }

  void write_section_blocks(const std::string &file, const std::map<long, std::vector<Segment>> &blocks,
                            const std::string &comment)
  {
    std::ofstream out(file);
    if (!comment.empty())
      out << "# " << comment << "\n";
    out << "# update u0 v0 u1 v1 [m] (one segment per line; a block per update, update 0 the design)\n";
    out.precision(10);
    for (const auto &[u, segments] : blocks)
      {
        for (const auto &s : segments)
          out << u << ' ' << s.u0 << ' ' << s.v0 << ' ' << s.u1 << ' ' << s.v1 << '\n';
        out << "\n\n";
      }
  }

  namespace
  {
    using Point2 = std::array<double, 2>;

    /// The point of @p s nearest to @p p.
    Point2 nearest_on(const Segment &s, const Point2 &p)
    {
      const double dy = s.u1 - s.u0, dz = s.v1 - s.v0, l2 = dy * dy + dz * dz;
      const double t = l2 > 0 ? std::clamp(((p[0] - s.u0) * dy + (p[1] - s.v0) * dz) / l2, 0.0, 1.0) : 0.0;
      return {s.u0 + t * dy, s.v0 + t * dz};
    }

    /// The distance from @p p to the outline @p outline, and its nearest point there.
    std::pair<double, Point2> distance_to(const std::vector<Segment> &outline, const Point2 &p)
    {
      double best = std::numeric_limits<double>::infinity();
      Point2 at   = p;
      for (const auto &s : outline)
        {
          const Point2 q = nearest_on(s, p);
          const double d = std::hypot(q[0] - p[0], q[1] - p[1]);
          if (d < best)
            best = d, at = q;
        }
      return {best, at};
    }

    /// Each end and middle of @p from's segments with its distance to the outline @p to (the
    /// middles: a worn edge between two ends that lie on the design's sides).
    void distances(const std::vector<Segment> &from, const std::vector<Segment> &to,
                   std::vector<std::pair<Point2, double>> &out)
    {
      for (const auto &s : from)
        for (const Point2 p : {Point2{s.u0, s.v0}, Point2{s.u1, s.v1}, Point2{0.5 * (s.u0 + s.u1), 0.5 * (s.v0 + s.v1)}})
          out.push_back({p, distance_to(to, p).first});
    }
  } // namespace

  SectionWindow section_window(const std::map<long, std::vector<Segment>> &blocks)
  {
    SectionWindow w;
    double        lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    double        hi[2] = {-lo[0], -lo[1]};
    for (const auto &[u, segments] : blocks)
      for (const auto &s : segments)
        {
          lo[0] = std::min({lo[0], s.u0, s.u1}), hi[0] = std::max({hi[0], s.u0, s.u1});
          lo[1] = std::min({lo[1], s.v0, s.v1}), hi[1] = std::max({hi[1], s.v0, s.v1});
        }
    if (!(hi[0] >= lo[0]))
      return w;
    const double diagonal = std::hypot(hi[0] - lo[0], hi[1] - lo[1]);
    // the whole section, with a margin
    w.y0 = lo[0] - 0.05 * diagonal, w.y1 = hi[0] + 0.05 * diagonal;
    w.z0 = lo[1] - 0.05 * diagonal, w.z1 = hi[1] + 0.05 * diagonal;
    const auto design = blocks.find(0);
    if (design == blocks.end() || blocks.rbegin()->first == 0 || design->second.empty())
      return w;
    const auto &last = blocks.rbegin()->second;
    std::vector<std::pair<Point2, double>> d;
    distances(last, design->second, d); // worn ends off the design
    distances(design->second, last, d); // design ends worn away
    for (const auto &[p, distance] : d)
      w.largest_distance = std::max(w.largest_distance, distance);
    if (!(w.largest_distance > 1e-6 * diagonal))
      return w;
    // where the outlines differ by a fifth of the largest distance or more, with a margin of
    // the distance and a quarter of the region's size, no thinner than a third of its length
    double a[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    double b[2] = {-a[0], -a[1]};
    for (const auto &[p, distance] : d)
      if (distance >= 0.2 * w.largest_distance)
        for (int c = 0; c < 2; ++c)
          a[c] = std::min(a[c], p[c]), b[c] = std::max(b[c], p[c]);
    const double size = std::max(b[0] - a[0], b[1] - a[1]);
    const double pad  = std::max(w.largest_distance, 0.25 * size);
    for (int c = 0; c < 2; ++c)
      {
        const double half = std::max(0.5 * (b[c] - a[c]) + pad, (size + 2 * pad) / 6), mid = 0.5 * (a[c] + b[c]);
        a[c] = mid - half, b[c] = mid + half;
      }
    const double whole = (w.y1 - w.y0) * (w.z1 - w.z0);
    if ((b[0] - a[0]) * (b[1] - a[1]) < 0.8 * whole)
      {
        w.y0 = std::max(w.y0, a[0]), w.y1 = std::min(w.y1, b[0]);
        w.z0 = std::max(w.z0, a[1]), w.z1 = std::min(w.z1, b[1]);
        w.zoomed = true;
      }
    return w;
  }

  namespace
  {
    /// Text inside gnuplot's single quotes: a quote doubled ("the part's").
    std::string quoted(const std::string &text)
    {
      std::string q;
      for (const char c : text)
        q += c == '\'' ? std::string("''") : std::string(1, c);
      return q;
    }

    /// The updates drawn: all up to six, else six spread over the run, the first and the last.
    std::vector<long> updates_drawn(const std::map<long, std::vector<Segment>> &blocks)
    {
      std::vector<long> updates;
      for (const auto &[u, segments] : blocks)
        if (u > 0)
          updates.push_back(u);
      if (updates.size() > 6)
        {
          std::vector<long> some;
          for (int k = 0; k < 6; ++k)
            some.push_back(updates[std::size_t(std::lround(k * double(updates.size() - 1) / 5))]);
          some.erase(std::unique(some.begin(), some.end()), some.end());
          updates = some;
        }
      return updates;
    }

    /// gnuplot's inline vectors (mm) of the @p segments whose box meets @p window (gnuplot clips
    /// the rest), ended by "e".
    std::string segment_data(const std::vector<Segment> &segments, const SectionWindow &window)
    {
      std::ostringstream d;
      d.precision(8);
      for (const auto &s : segments)
        if (std::max(s.u0, s.u1) >= window.y0 && std::min(s.u0, s.u1) <= window.y1 &&
            std::max(s.v0, s.v1) >= window.z0 && std::min(s.v0, s.v1) <= window.z1)
          d << 1000 * s.u0 << ' ' << 1000 * s.v0 << ' ' << 1000 * (s.u1 - s.u0) << ' ' << 1000 * (s.v1 - s.v0) << '\n';
      return d.str() + "e\n";
    }

    /// Where the life ended, on the plot: its label, and a height gauge's lines (the design's
    /// lowest point and the worn outline's, @p design and @p last) or the distance to the design.
    void mark_the_end(std::ostream &gp, const SectionMark &mark, const std::vector<Segment> *design,
                      const std::vector<Segment> *last)
    {
      const double y = 1000 * mark.at[0], z = 1000 * mark.at[1];
      gp << "set label 1 '" << quoted(mark.text) << "' at screen 0.5, screen 0.02 center front noenhanced textcolor rgb 'red'\n"
         << "set bmargin 5\n";
      if (mark.lowest_points && design && last)
        {
          auto lowest = [](const std::vector<Segment> &segments) {
            double z = std::numeric_limits<double>::infinity();
            for (const auto &s : segments)
              z = std::min({z, s.v0, s.v1});
            return 1000 * z;
          };
          const double zd = lowest(*design), zw = lowest(*last);
          gp << "set arrow 1 from graph 0, first " << zd << " to graph 1, first " << zd
             << " nohead dt 2 lw 1.5 lc rgb 'black'\nset arrow 2 from graph 0, first " << zw << " to graph 1, first "
             << zw << " nohead dt 2 lw 1.5 lc rgb 'red'\nset arrow 3 from first " << y << ", first " << zd
             << " to first " << y << ", first " << zw << " heads lw 2 lc rgb 'red'\n";
        }
      if (mark.to_design && design)
        {
          const Point2 q = distance_to(*design, mark.at).second;
          gp << "set arrow 3 from first " << 1000 * q[0] << ", first " << 1000 * q[1] << " to first " << y
             << ", first " << z << " head lw 2 lc rgb 'red'\n";
        }
    }
  } // namespace

  bool section_plot(std::ostream &gp, const std::map<long, std::vector<Segment>> &blocks, const SectionWindow &window,
                    const std::string &png, const std::string &title, const SectionMark &mark, const char *u_name,
                    const char *v_name)
  {
    if (blocks.empty() || !(window.y1 > window.y0 && window.z1 > window.z0))
      return false;
    const std::vector<long> updates = updates_drawn(blocks);
    gp << "set output '" << quoted(png) << "'\nset title '" << quoted(title) << "' noenhanced\nunset label\nunset arrow\n"
       << "set xlabel '" << u_name << " [mm]'\nset ylabel '" << v_name
       << " [mm]'\nset size ratio -1\nset key rmargin top vertical maxrows auto\n"
       << "set xrange [" << 1000 * window.y0 << ":" << 1000 * window.y1 << "]\nset yrange [" << 1000 * window.z0 << ":"
       << 1000 * window.z1 << "]\n";
    std::ostringstream curves, inline_data;
    const auto         design = blocks.find(0);
    if (design != blocks.end())
      curves << "'-' using 1:2:3:4 with vectors nohead lw 3 lc rgb 'black' title 'design'",
        inline_data << segment_data(design->second, window);
    for (std::size_t k = 0; k < updates.size(); ++k)
      {
        curves << (curves.tellp() > 0 ? ", " : "") << "'-' using 1:2:3:4 with vectors nohead lw 1.5 lc "
               << k + 1 << " title 'update " << updates[k] << "'";
        inline_data << segment_data(blocks.at(updates[k]), window);
      }
    if (mark.shown)
      {
        mark_the_end(gp, mark, design != blocks.end() ? &design->second : nullptr,
                     updates.empty() ? nullptr : &blocks.rbegin()->second);
        curves << ", '-' using 1:2 with points pt 6 ps 2.5 lw 2 lc rgb 'red' title 'where the life ended'";
        inline_data << 1000 * mark.at[0] << ' ' << 1000 * mark.at[1] << "\ne\n";
      }
    gp << "plot " << curves.str() << "\n" << inline_data.str() << "set bmargin\n";
    return true;
  }
} // namespace abrade::coupling::lifetime
