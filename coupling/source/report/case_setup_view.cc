// The preview's set-up picture (case_setup_view.h).
#include "case_setup_view.h"

#include <abrade/common/external.h>

#include <filesystem>
#include <fstream>

namespace abrade::report
{
  bool render_case_setup(const std::string &directory, const std::string &png, const CaseSetupPicture &setup,
                         const std::vector<std::pair<std::string, std::string>> &roles)
  {
    std::filesystem::create_directories(directory);
    const std::string   stem = std::filesystem::path(png).stem().string();
    std::vector<double> values;
    if (!write_pm3d_surface({setup.part_file, "role", ""}, directory + "/" + stem + "_part.dat", 1.0, values))
      return false;
    // the fill region and the domain: a box's twelve edges each, in mm, a data set per edge
    // (two blank lines: splot joins the points of consecutive blocks of one set into a mesh)
    for (const auto &[b, name] : {std::pair{setup.fill_region, "_fill.dat"}, std::pair{setup.domain, "_domain.dat"}})
        {
          std::ofstream boxes(directory + "/" + stem + name);
          auto corner = [&](int k) {
            return std::array<double, 3>{1000 * b[(k & 1) ? 3 : 0], 1000 * b[(k & 2) ? 4 : 1], 1000 * b[(k & 4) ? 5 : 2]};
          };
          for (int k = 0; k < 8; ++k)
            for (int d = 0; d < 3; ++d)
              if (!(k & (1 << d))) // each edge once: from a corner along a direction it can go
                {
                  const auto p = corner(k), q = corner(k | (1 << d));
                  boxes << p[0] << ' ' << p[1] << ' ' << p[2] << '\n' << q[0] << ' ' << q[1] << ' ' << q[2] << "\n\n\n";
                }
        }
    std::error_code e;
    const bool      walls = std::filesystem::file_size(setup.walls_file, e) > 0 && !e;
    const bool      path  = std::filesystem::file_size(setup.path_file, e) > 0 && !e;
    const std::size_t n = roles.size();
    std::ofstream     gp(directory + "/" + stem + ".gp");
    gp << "set terminal pngcairo size 1400,1050 font 'DejaVu Sans,10'\n"
       << "set output '" << gnuplot_output_name(directory + "/" + png) << "'\nset termoption noenhanced\n"
       << "set multiplot layout 2,2 rowsfirst\nset view equal xyz\nset xyplane 0\nunset colorbox\n"
       << "set pm3d depthorder corners2color mean lighting primary 0.5 specular 0.1\n"
       << "set cbrange [-0.5:" << double(n) - 0.5 << "]\nset palette maxcolors " << n << "\nset palette defined (";
    for (std::size_t k = 0; k < n; ++k)
      gp << (k ? ", " : "") << k << " '" << roles[k].second << "'";
    gp << ")\nset xlabel 'x [mm]'\nset ylabel 'y [mm]'\nset zlabel 'z [mm]'\nset tics font ',8'\n"
       << "set style line 1 lc rgb '#8c8c8c' lw 1\nset style line 2 lc rgb '#1a9641' lw 2 dt 2\n"
       << "set style line 3 lc rgb '#bdbdbd' lw 1 dt 3\nset style line 4 lc rgb '#d7191c' lw 3\n";
    for (const auto &[name, at] : setup.phase_ends)
      gp << "set label '" << quote_free(name) << "' at " << 1000 * at[0] << ',' << 1000 * at[1] << ',' << 1000 * at[2]
         << " front offset 0.5,0.5 textcolor rgb '#d7191c'\n";
    // the part's roles on the first view's colour bar, the lines in its key
    const struct
    {
      const char *view, *title;
    } views[] = {{"62, 30", "the set-up"}, {"90, 0", "from the side (x-z)"}, {"0, 0", "from above (x-y)"},
                 {"90, 90", "from the front (y-z)"}};
    gp << "set cbtics (";
    for (std::size_t k = 0; k < n; ++k)
      gp << (k ? ", " : "") << "'" << quote_free(roles[k].first) << "' " << k;
    gp << ")\nset cblabel 'the part''s faces'\n";
    for (int v = 0; v < 4; ++v)
      {
        gp << (v == 0 ? "set colorbox\n" : "unset colorbox\n") << (v == 2 ? "unset ztics\nset zlabel ''\n" : "set ztics\nset zlabel 'z [mm]'\n")
           << "set view " << views[v].view << (v == 0 ? ", 1.0" : ", 1.35") << "\nset title '" << views[v].title << "'\n"
           << (v == 0 ? "set key bottom center horizontal font ',9'\n" : "unset key\n")
           << "splot '" << stem << "_part.dat' using 1:2:3:4 with pm3d title 'the part'";
        gp << ", '" << stem << "_fill.dat' using 1:2:3 with lines ls 2 title 'the particles'' fill region', '" << stem
           << "_domain.dat' using 1:2:3 with lines ls 3 title 'the domain'";
        if (walls)
          gp << ", '" << gnuplot_output_name(setup.walls_file)
             << "' using ($1*1000):($2*1000):($3*1000) with lines ls 1 title 'the other walls'";
        if (path)
          gp << ", '" << gnuplot_output_name(setup.path_file)
             << "' using ($1*1000):($2*1000):($3*1000) with lines ls 4 title 'the path of the part''s lowest point'";
        gp << '\n';
      }
    gp << "unset multiplot\n";
    gp.close();
    return io::run_gnuplot(directory, stem + ".gp", true) && std::filesystem::exists(directory + "/" + png);
  }
} // namespace abrade::report
