// The run report (report.h): which run it is, and its page.
#include "html_page.h"
#include "case_setup_view.h"
#include "surface_views.h"

#include <abrade/common/atomic_file.h>
#include <abrade/common/csv_reader.h>
#include <abrade/common/format_number.h>
#include <abrade/common/json.h>
#include <abrade/common/output_directory.h>
#include <abrade/common/error.h>
#include <abrade/common/wear_field_names.h>
#include <abrade/report/report.h>

// (property_tree includes boost/bind.hpp, which otherwise prints a deprecation message)
#define BOOST_BIND_GLOBAL_PLACEHOLDERS
#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <tuple>

namespace abrade::report
{
  namespace
  {
    namespace fs = std::filesystem;
    using Tree   = boost::property_tree::ptree;

    /// Whether @p file can be read as a run's output: a regular file (not a device such as a
    /// link to /dev/full, which never ends) of at most 200 MB.
    bool readable(const std::string &file)
    {
      std::error_code e;
      return fs::is_regular_file(file, e) && fs::file_size(file, e) < 200u << 20;
    }

    std::string read_text(const std::string &file)
    {
      if (!readable(file))
        return "";
      std::ifstream in(file);
      return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    }

    /// summary.json (an empty tree if there is none or it is not JSON).
    Tree read_json(const std::string &file)
    {
      Tree t;
      try
        {
          if (readable(file))
            boost::property_tree::read_json(file, t);
        }
      catch (const std::exception &)
        {}
      return t;
    }

    /// The text at @p key ("" if none).
    std::string text_at(const Tree &t, const std::string &key)
    {
      const auto v = t.get_optional<std::string>(key);
      return v ? *v : std::string();
    }

    /// The first @p N numbers of the list at @p key of @p t (zeros where the list is shorter or
    /// missing): a point, a box.
    template <std::size_t N>
    std::array<double, N> numbers_at(const Tree &t, const std::string &key)
    {
      std::array<double, N> out{};
      std::size_t           d = 0;
      if (const auto list = t.get_child_optional(key))
        for (const auto &[i, x] : *list)
          if (d < N)
            out[d++] = x.template get_value<double>();
      return out;
    }

    std::string number(double x, int digits = 4) { return io::format_number(x, digits); }

    /// The unit tonnes are shown in (t, kt, Mt: the largest that keeps the number, rounded to
    /// three digits, at 1 or more), and its size.
    std::pair<const char *, double> tonnes_unit(double t)
    {
      const double a = std::abs(t);
      if (a >= 999.5e3)
        return {"Mt", 1e6};
      if (a >= 999.5)
        return {"kt", 1e3};
      return {"t", 1};
    }

    /// Tonnes in t, kt or Mt, three digits.
    std::string tonnes(double t)
    {
      const auto [unit, size] = tonnes_unit(t);
      return number(t / size, 3) + " " + unit;
    }

    /// A length [m] in mm, to 0.01 mm.
    std::string mm(double metres)
    {
      char b[40];
      std::snprintf(b, sizeof b, "%.2f", std::abs(metres) < 5e-6 ? 0.0 : 1000 * metres);
      return b;
    }

    /// A table of the run (an empty one when it is missing, not a regular file, or malformed: a
    /// report shows what it can).
    io::CsvTable read_table(const std::string &file)
    {
      try
        {
          if (readable(file))
            return io::read_csv(file);
        }
      catch (const std::exception &)
        {}
      return {};
    }

    /// Every "warnings" list anywhere in @p t.
    void collect_warnings(const Tree &t, std::vector<std::string> &out)
    {
      for (const auto &[key, child] : t)
        {
          if (key == "warnings")
            for (const auto &[k, w] : child)
              out.push_back(w.get_value<std::string>());
          else
            collect_warnings(child, out);
        }
    }

    /// The files of a .pvd collection in order, with their times.
    std::vector<std::pair<double, std::string>> pvd_files(const std::string &pvd)
    {
      std::vector<std::pair<double, std::string>> files;
      const std::string                           text = read_text(pvd);
      const std::regex re("timestep=\"([^\"]*)\"[^>]*file=\"([^\"]*)\"");
      for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator(); ++it)
        files.emplace_back(std::atof((*it)[1].str().c_str()), (fs::path(pvd).parent_path() / (*it)[2].str()).string());
      return files;
    }

    /// Provenance and parameters: the end of every report.
    void provenance(HtmlPage &page, const std::string &dir, const Tree &summary)
    {
      page.heading("Run and parameters");
      std::vector<std::vector<std::string>> rows;
      for (const char *key : {"abrade_version", "job", "command", "parameter_file", "parameters_hash", "started",
                              "threads", "mpi_ranks", "status"})
        if (const auto v = summary.get_optional<std::string>(key))
          rows.push_back({key, *v});
      if (const auto t = summary.get_optional<double>("timings.total"))
        rows.push_back({"runtime", number(*t, 4) + " s"});
      rows.push_back({"directory", fs::absolute(dir).string()});
      page.table({"", ""}, rows);
      if (fs::exists(dir + "/parameters.prm"))
        page.details("Parameter file as run (parameters.prm)", read_text(dir + "/parameters.prm"));
    }

    /// The worst region, zoomed: the last surface (@p file, titled @p title) within a few wear
    /// depths of where the life ended (summary.json's end_of_life_where, else the deepest point
    /// of the last update in trajectory.csv), circled, seen from the side its wear faces.
    void worst_region_picture(HtmlPage &page, const std::string &dir, const Tree &r, const std::string &part,
                              const std::string &file, const std::string &title)
    {
      std::array<double, 3> where{};
      if (r.get_child_optional("end_of_life_where") && r.get_child("end_of_life_where").size() == 3)
        where = numbers_at<3>(r, "end_of_life_where");
      else
        {
          const io::CsvTable csv = read_table(dir + "/trajectory.csv");
          const int          x   = csv.find("deepest_x");
          if (csv.rows.empty() || x < 0 || csv.find("deepest_z") != x + 2)
            return;
          for (int c = 0; c < 3; ++c)
            where[c] = std::atof(csv.rows.back()[x + c].c_str());
        }
      // six depths or five triangles around it, whichever is more, no less than 6 % and no more
      // than 35 % of the part's size
      const SurfaceSize size   = surface_size(file);
      const double      radius = std::min(std::max({6 * r.get<double>("max_depth", 0), 5 * size.mean_edge,
                                                    0.06 * size.largest_extent}),
                                          0.35 * size.largest_extent);
      RenderOptions zoom;
      zoom.crop = {where, radius};
      zoom.labels.push_back({where, "where the life ended", {}, true});
      std::error_code ec; // (a picture of an earlier report is not this one's)
      fs::remove(dir + "/report/worst_region.png", ec);
      render_surfaces(dir + "/report", "worst_region.png", {{file, "wear_depth", title}}, zoom);
      page.png(dir + "/report/worst_region.png",
               "The worst region, zoomed: the " + part + " within " + mm(radius) + " mm of where the life ended (circled: x = " +
                 mm(where[0]) + ", y = " + mm(where[1]) + ", z = " + mm(where[2]) +
                 " mm; a followed point is circled where it was on the design), coloured by wear depth (mm below the "
                 "design surface), seen from the side its wear faces, 35 degrees to either side of it.",
               "worst");
    }

    // ---------------------------------------------------------------------------------------

    /// The life in one sentence (@p r: summary.json's results.lifetime): the tonnes and their
    /// interval (its components), the criterion and where it ended the life, and how the end
    /// was found; or that none was reached.
    std::string lifetime_headline(const Tree &r, const std::string &part)
    {
      const auto         predicted = r.get_optional<double>("predicted_tonnes_to_end_of_life");
      std::ostringstream headline;
      if (predicted)
        {
          char value[40];
          std::snprintf(value, sizeof value, "%.17g", *predicted);
          headline << "End of life after <span id=\"headline-tonnes\" data-value=\"" << value << "\"><b>"
                   << tonnes(*predicted) << "</b></span> of handled material";
          const double low = r.get<double>("predicted_tonnes_low", 0), high = r.get<double>("predicted_tonnes_high", 0);
          // (no interval without two beds in an update: summary.json then has no bounds)
          if (!(low > 0 && high > 0))
            headline << " (no interval: one bed per update)";
          else
            {
              headline << " (" << number(100 * r.get<double>("confidence", 0.95), 3) << " % interval "
                       << tonnes(low) << " to " << tonnes(high) << ", +-"
                       << number(100 * r.get<double>("relative_half_width", 0), 2) << " %, from every update's beds";
              const double extrapolation = r.get<double>("interval.components.extrapolation", 0);
              if (extrapolation > 0)
                headline << "; the extrapolation's share " << number(100 * extrapolation, 2) << " % of "
                         << number(100 * r.get<double>("interval.relative_sd", 0), 2) << " % (standard deviations)";
              // Lifetime/Calibration: W's (and the fitted footprint's) uncertainty, a component of its own
              const double calibration = r.get<double>("interval.components.calibration", 0);
              if (calibration > 0)
                headline << "; the calibration's share (W " << number(r.get<double>("calibration.wear_coefficient", 0), 4)
                         << (r.get<bool>("calibration.footprint_fitted", false)
                               ? " and the footprint " + mm(r.get<double>("smoothing_radius", 0)) + " mm"
                               : std::string())
                         << ") " << number(100 * calibration, 2) << " % of "
                         << number(100 * r.get<double>("interval.relative_sd", 0), 2) << " % (standard deviations)";
              headline << ")";
            }
          headline << ", by " << escape_html(text_at(r, "end_of_life_criterion"));
          if (r.get_child_optional("end_of_life_where") && r.get_child("end_of_life_where").size() == 3)
            {
              const auto where = numbers_at<3>(r, "end_of_life_where");
              headline << " at x = " << mm(where[0]) << " mm, y = " << mm(where[1]) << " mm, z = " << mm(where[2])
                       << " mm (the " << part << "'s frame)";
            }
          std::string method = text_at(r, "end_of_life_method");
          if (!method.empty())
            method[0] = char(std::toupper(static_cast<unsigned char>(method[0])));
          headline << ". " << escape_html(method) << ".";
        }
      else
        headline << "<span id=\"headline-tonnes\" data-value=\"none\"><b>No end of life reached</b></span> after "
                 << tonnes(r.get<double>("tonnes", 0)) << " (" << escape_html(text_at(r, "end")) << ")";
      return headline.str();
    }

    /// The worn part at the design, the middle and the last update, and its worst region.
    void worn_part_pictures(HtmlPage &page, const std::string &dir, const Tree &r, const std::string &part)
    {
      const std::string part_files = io::part_folder(dir); // (the folder and the files' stem)
      const std::string pvd   = dir + "/" + part_files + "/" + part_files + ".pvd";
      const auto        files = fs::exists(pvd) ? pvd_files(pvd) : std::vector<std::pair<double, std::string>>();
      if (files.empty())
        return;
      std::vector<SurfacePicture> stages;
      stages.push_back({files.front().second, "wear_depth", "design"});
      if (files.size() > 2)
        stages.push_back({files[files.size() / 2].second, "wear_depth", "after " + tonnes(files[files.size() / 2].first)});
      stages.push_back({files.back().second, "wear_depth", "after " + tonnes(files.back().first)});
      RenderOptions laid; // (a long part face on: surface_views.h)
      laid.face_on_elongation = 3;
      bool face_on            = false;
      if (!render_surfaces(dir + "/report", "part_wear.png", stages, laid, &face_on))
        page.paragraph("(the " + part + "'s pictures could not be drawn: gnuplot, or its VTU files, are missing)");
      page.png(dir + "/report/part_wear.png",
               "The " + part + " coloured by wear depth (mm below the design surface) at the design, the middle "
               "update and the last update of the run, " +
                 std::string(face_on ? "laid face on (its longest extent across the picture), each from its two "
                                       "sides, one above the other"
                                     : "seen from two opposite sides (top row: from +x, -y; bottom row: from -x, +y)") +
                 "; one colour range for all. Beyond the last update the end of life is extrapolated, not drawn.",
               "part");
      worst_region_picture(page, dir, r, part, files.back().second, "after " + tonnes(files.back().first));
    }

    /// The cross-section through where the life ended, then the profiles along the part.
    void cross_sections(HtmlPage &page, const std::string &dir, const std::string &part)
    {
      std::vector<fs::path> profiles;
      const std::string     folder = dir + "/" + io::part_folder(dir);
      if (fs::is_directory(folder))
        for (const auto &entry : fs::directory_iterator(folder))
          if (entry.path().extension() == ".png" && entry.path().stem().string().rfind("profile_", 0) == 0)
            profiles.push_back(entry.path());
      std::sort(profiles.begin(), profiles.end());
      if (fs::exists(folder + "/section_worst.csv"))
        page.png(folder + "/section_worst.png",
                 "Cross-section of the " + part + " through where the life ended (circled), normal to x: the design's "
                 "outline (black) and the worn outlines of the updates (up to six), zoomed to where they differ; the "
                 "quantity that ended the life is drawn there and named below; y and z in mm.",
                 "section-worst");
      for (const auto &p : profiles)
        page.png(p.string(), "Cross-section of the " + part + " at " + p.stem().string().substr(8) +
                               " of its length: the design's outline (black) and the worn outlines of the updates, "
                               "zoomed to where they differ; y and z in mm.",
                 "profile");
    }

    /// trajectory.csv's main columns, an update per row, in the units a reader expects.
    void updates_table(HtmlPage &page, const std::string &dir)
    {
      const io::CsvTable csv = read_table(dir + "/trajectory.csv");
      if (csv.rows.empty())
        return;
      const std::vector<std::pair<std::string, std::string>> shown = {
        {"update", "update"}, {"tonnes", "handled"}, {"max_depth", "largest depth [mm]"},
        {"point_recession", "recession [mm]"}, {"worn_mass", "worn mass [kg]"},
        {"min_scaled_jacobian", "worst cell quality"}, {"remeshed", "remeshed"}, {"dem_warnings", "DEM warnings"}};
      std::vector<std::string>              header;
      std::vector<std::vector<std::string>> rows;
      const int  tonnes_column = csv.find("tonnes");
      const auto [unit, size]  = tonnes_unit(tonnes_column >= 0 ? std::atof(csv.rows.back()[tonnes_column].c_str()) : 0);
      for (const auto &[c, title] : shown)
        if (csv.find(c) >= 0)
          header.push_back(c == "tonnes" ? title + " [" + unit + "]" : title);
      for (const auto &line : csv.rows)
        {
          std::vector<std::string> row;
          for (const auto &[c, title] : shown)
            {
              const int i = csv.find(c);
              if (i < 0)
                continue;
              const double v = std::atof(line[i].c_str());
              row.push_back(c == "tonnes" ? number(v / size, 4)
                            : (c == "max_depth" || c == "point_recession") ? number(1000 * v, 4)
                                                                            : number(v, 4));
            }
          rows.push_back(row);
        }
      page.table(header, rows);
    }

    std::string lifetime_page(const std::string &dir, const Tree &summary)
    {
      const Tree        none;
      const auto        results = summary.get_child_optional("results.lifetime");
      const Tree       &r       = results ? *results : none;
      // a part from a file is a part, the parametric knife a knife (summary.json lifetime.part)
      const std::string part    = text_at(r, "part") == "part" ? "part" : "knife";
      HtmlPage          page(part == "part" ? "Part lifetime prediction" : "Knife lifetime prediction");
      const std::string status  = text_at(summary, "status");
      if (!status.empty() && status != "completed")
        page.headline("<span id=\"headline-status\"><b>This run did not complete</b></span>: " + escape_html(status) +
                      ". What it wrote before it stopped is shown below; resume it with abrade run ... --resume.");
      if (results)
        page.headline(lifetime_headline(r, part));
      char cycles[40];
      std::snprintf(cycles, sizeof cycles, "%.0f", r.get<double>("cycles", 0));
      page.paragraph("Run ended: " + escape_html(text_at(r, "end")) + "; " + tonnes(r.get<double>("tonnes", 0)) +
                     " handled in " + cycles + " cycles; largest wear depth " +
                     number(1000 * r.get<double>("max_depth", 0), 4) + " mm; worn mass " +
                     number(r.get<double>("worn_mass", 0), 4) + " kg; " +
                     std::to_string(r.get<int>("seeds", 1)) + " bed(s).");

      page.heading("Trajectory");
      page.png(dir + "/trajectory.png",
               "Wear against handled material: the largest depth with the spread of the beds, the followed point's "
               "recession and the worn volume.",
               "trajectory");
      page.heading("The worn " + part);
      worn_part_pictures(page, dir, r, part);
      cross_sections(page, dir, part);
      page.heading("Updates");
      updates_table(page, dir);
      page.heading("Warnings");
      std::vector<std::string> warnings;
      collect_warnings(summary, warnings);
      page.warnings(warnings);
      provenance(page, dir, summary);
      return page.html();
    }

    /// The first wall of a run that has a wear table, and its last snapshot.
    std::string worn_wall_snapshot(const std::string &run)
    {
      if (!fs::exists(run + "/walls"))
        return "";
      std::vector<std::string> walls;
      for (const auto &e : fs::directory_iterator(run + "/walls"))
        {
          const std::string name = e.path().filename().string();
          if (name.size() > 9 && name.compare(name.size() - 9, 9, "_wear.csv") == 0)
            walls.push_back(name.substr(0, name.size() - 9));
        }
      std::sort(walls.begin(), walls.end());
      if (walls.empty())
        return "";
      // a knife first: the part the comparison is about
      std::stable_partition(walls.begin(), walls.end(), [](const std::string &w) { return w.find("knife") != std::string::npos; });
      const auto files = pvd_files(run + "/walls/" + walls.front() + ".pvd");
      return files.empty() ? "" : files.back().second;
    }

    /// The changes against the first row whose 95 % interval excludes no change, in words: every
    /// column NAME_significant that is 1, with NAME_percent and its _low_percent/_high_percent
    /// (concepts.csv) or the ratio NAME and its NAME_low/NAME_high (study.csv).
    std::string significant_changes(const io::CsvTable &csv)
    {
      const std::string tail = "_significant";
      std::string       list;
      for (std::size_t r = 1; r < csv.rows.size(); ++r)
        for (std::size_t c = 0; c < csv.header.size(); ++c)
          {
            const std::string &h = csv.header[c];
            if (h.size() <= tail.size() || h.compare(h.size() - tail.size(), tail.size(), tail) != 0 ||
                csv.rows[r][c] != "1")
              continue;
            const std::string name = h.substr(0, h.size() - tail.size());
            auto              cell = [&](const std::string &column) {
              const int k = csv.find(column);
              return k >= 0 ? std::strtod(csv.rows[r][k].c_str(), nullptr) : std::nan("");
            };
            char text[160];
            if (csv.find(name + "_percent") >= 0)
              std::snprintf(text, sizeof text, "%+.3g %% [%+.3g, %+.3g]", cell(name + "_percent"),
                            cell(name + "_low_percent"), cell(name + "_high_percent"));
            else
              std::snprintf(text, sizeof text, "x %.4g [%.4g, %.4g]", cell(name), cell(name + "_low"),
                            cell(name + "_high"));
            std::string what = name.rfind("change_", 0) == 0 ? name.substr(7) : name;
            std::replace(what.begin(), what.end(), '_', ' ');
            list += "<li><b>" + escape_html(csv.rows[r][0]) + "</b>: " + escape_html(what) + " " + escape_html(text) +
                    "</li>";
          }
      return list.empty() ? "No change against the first row is significant: each 95 % interval (pair by pair on "
                            "the same beds) holds no change, or there is none (one bed)."
                          : "Against the first row, pair by pair on the same beds, the 95 % interval excludes no "
                            "change for:<ul>" + list + "</ul>";
    }

    /// The variants' table (numbers to four digits) and the changes against the first row that
    /// are significant.
    void add_comparison(HtmlPage &page, const io::CsvTable &csv)
    {
      std::vector<std::vector<std::string>> rows;
      for (const auto &line : csv.rows)
        {
          std::vector<std::string> row;
          for (const auto &cell : line)
            {
              char        *end = nullptr;
              const double v   = std::strtod(cell.c_str(), &end);
              row.push_back(end && *end == '\0' && !cell.empty() ? number(v, 4) : cell);
            }
          rows.push_back(row);
        }
      page.table(csv.header, rows);
      page.paragraph("Wear in m^3 per cycle (Archard's volume unless Output/Wear field says otherwise), payload in "
                     "t per cycle, wear per tonne in m^3/t; columns ending in _std are the standard deviations over the "
                     "bed seeds, _uncertainty the uncertainty of a change against the first row, in per cent "
                     "(docs/user-guide.md).");
      page.heading("Significant changes");
      page.paragraph(significant_changes(csv));
    }

    /// Each variant's worn wall after its run of the lowest seed (dir/runs/VARIANT-seedN), in
    /// the table's order, coloured by the run's Output/Wear field.
    std::vector<SurfacePicture> worn_shapes(const std::string &dir, const io::CsvTable &csv)
    {
      std::vector<std::string> runs;
      for (const auto &e : fs::directory_iterator(dir + "/runs"))
        if (e.is_directory())
          runs.push_back(e.path().string());
      auto variant = [](const std::string &run) {
        const std::string name = fs::path(run).filename().string();
        return name.substr(0, name.rfind("-seed"));
      };
      auto seed = [](const std::string &run) {
        const auto at = run.rfind("-seed");
        return at == std::string::npos ? 0L : std::atol(run.c_str() + at + 5);
      };
      auto rank = [&](const std::string &run) {
        for (std::size_t k = 0; k < csv.rows.size(); ++k)
          if (!csv.rows[k].empty() && csv.rows[k][0] == variant(run))
            return long(k);
        return long(csv.rows.size());
      };
      std::sort(runs.begin(), runs.end(), [&](const std::string &a, const std::string &b) {
        return std::make_tuple(rank(a), variant(a), seed(a)) < std::make_tuple(rank(b), variant(b), seed(b));
      });
      std::vector<SurfacePicture> shapes;
      std::vector<std::string>    seen;
      for (const auto &run : runs)
        {
          std::string name = fs::path(run).filename().string();
          name             = name.substr(0, name.rfind("-seed"));
          if (std::find(seen.begin(), seen.end(), name) != seen.end())
            continue;
          const std::string snapshot = worn_wall_snapshot(run);
          if (snapshot.empty())
            continue;
          seen.push_back(name);
          std::string clean = name;
          std::replace(clean.begin(), clean.end(), '\'', ' ');
          // as the run's Output/Wear field saw it (Archard's volume by default)
          const std::string field = io::summary_string(run + "/summary.json", "wear_field").value_or("archard_volume");
          shapes.push_back({snapshot, io::wear_surface_field(field), clean});
        }
      return shapes;
    }

    /// The warnings of the runs under dir/runs, each named by its run.
    std::vector<std::string> warnings_of_runs(const std::string &dir)
    {
      std::vector<std::string> warnings;
      if (!fs::is_directory(dir + "/runs"))
        return warnings;
      std::vector<fs::path> runs;
      for (const auto &e : fs::directory_iterator(dir + "/runs"))
        if (e.is_directory())
          runs.push_back(e.path());
      std::sort(runs.begin(), runs.end());
      for (const auto &run : runs)
        {
          std::vector<std::string> own;
          collect_warnings(read_json((run / "summary.json").string()), own);
          for (const auto &w : own)
            warnings.push_back(run.filename().string() + ": " + w);
        }
      return warnings;
    }

    std::string table_page(const std::string &dir, const std::string &title, const std::string &csv_file,
                           const std::vector<std::string> &pngs)
    {
      HtmlPage           page(title);
      const io::CsvTable csv = read_table(dir + "/" + csv_file);
      page.headline("<span id=\"headline-count\" data-value=\"" + std::to_string(csv.rows.size()) + "\"><b>" +
                    std::to_string(csv.rows.size()) + "</b></span> variants compared (" +
                    escape_html(csv_file) + ")");
      page.heading("Comparison");
      if (!csv.rows.empty())
        add_comparison(page, csv);
      page.heading("Plots");
      for (const auto &p : pngs)
        if (fs::exists(dir + "/" + p))
          page.png(dir + "/" + p, p, fs::path(p).stem().string());
      // the worn shapes side by side: each variant's first seed
      if (fs::exists(dir + "/runs"))
        if (const auto shapes = worn_shapes(dir, csv); !shapes.empty())
          {
            page.heading("Worn shapes");
            RenderOptions o;
            o.align = true, o.top_percentile = 0.99;
            render_surfaces(dir + "/report", "worn_shapes.png", shapes, o);
            page.png(dir + "/report/worn_shapes.png",
                     "Each variant's worn knife (a knife first, else the first wall with wear) coloured by the wear "
                     "depth of its Output/Wear field (Archard's by default) after the run (its lowest bed seed), in the table's order, seen along its principal axes; "
                     "one colour range, whose top is the 99th percentile (the deepest 1 % share its colour).");
          }
      page.heading("Warnings");
      page.warnings(warnings_of_runs(dir));
      if (fs::exists(dir + "/concepts.md"))
        page.details("concepts.md", read_text(dir + "/concepts.md"));
      if (fs::exists(dir + "/study.md"))
        page.details("study.md", read_text(dir + "/study.md"));
      return page.html();
    }

    std::string field_page(const std::string &dir)
    {
      const bool  calibration = fs::exists(dir + "/calibration.json");
      const Tree  j           = read_json(dir + (calibration ? "/calibration.json" : "/comparison.json"));
      HtmlPage    page(calibration ? "Calibration against measured wear" : "Comparison with a field scan");
      if (calibration)
        {
          const auto runs = j.get_child_optional("runs");
          if (!runs || runs->empty())
            throw InputError(dir + "/calibration.json", "no calibrated run in it");
          const Tree  &best = runs->begin()->second;
          const double w = best.get<double>("archard_coefficient", 0), lo = best.get<double>("archard_coefficient_low", 0),
                       hi = best.get<double>("archard_coefficient_high", 0);
          char value[40];
          if (w > 0)
            {
              std::snprintf(value, sizeof value, "%.17g", w);
              page.headline("Fitted wear coefficient W = <span id=\"headline-w\" data-value=\"" + std::string(value) +
                            "\"><b>" + number(w, 4) + " 1/Pa</b></span> (95 % interval " + number(lo, 4) + " to " +
                            number(hi, 4) + " 1/Pa), " + number(best.get<double>("scale", 0), 4) +
                            " times the run's W; correlation of the pattern " + number(best.get<double>("correlation", 0), 4));
            }
          else // a run without a wear coefficient (an analytic wear rate): its scale
            {
              std::snprintf(value, sizeof value, "%.17g", best.get<double>("scale", 0));
              page.headline("No W for this run (its wear has no coefficient): the measured wear is <span "
                            "id=\"headline-scale\" data-value=\"" + std::string(value) + "\"><b>" +
                            number(best.get<double>("scale", 0), 4) + "</b></span> times the predicted (95 % interval " +
                            number(best.get<double>("scale_low", 0), 4) + " to " + number(best.get<double>("scale_high", 0), 4) +
                            "); correlation " + number(best.get<double>("correlation", 0), 4));
            }
          if (const auto fp = j.get_child_optional("footprint"); fp && fp->get<bool>("identifiable", false))
            page.paragraph("W and the footprint together, from the candidates at several footprints: footprint <b>" +
                           number(1000 * fp->get<double>("smoothing_radius", 0), 3) + " mm</b> (95 % interval " +
                           number(1000 * fp->get<double>("smoothing_radius_low", 0), 3) + " to " +
                           number(1000 * fp->get<double>("smoothing_radius_high", 0), 3) + " mm) and W <b>" +
                           number(fp->get<double>("wear_coefficient", 0), 4) + " 1/Pa</b> at it (95 % interval with the "
                           "footprint's uncertainty " + number(fp->get<double>("wear_coefficient_low", 0), 4) + " to " +
                           number(fp->get<double>("wear_coefficient_high", 0), 4) + " 1/Pa). Lifetime/Calibration takes both.");
          page.png(dir + "/calibration.png", "Predicted against measured wear depths with the fitted scale.", "calibration");
          if (fs::exists(dir + "/footprint.png"))
            page.png(dir + "/footprint.png",
                     "Each candidate run's W fitted at its footprint (the ridge along which W and the footprint trade "
                     "off), the fit, and the joint 95 % region of the two: along the ridge the measured profile's width "
                     "tells them apart.",
                     "footprint");
          if (fs::exists(dir + "/calibration.md"))
            page.details("calibration.md", read_text(dir + "/calibration.md"));
        }
      else
        {
          char value[40];
          std::snprintf(value, sizeof value, "%.17g", j.get<double>("registration.rms_distance", 0));
          page.headline("Scan registered with an RMS distance of <span id=\"headline-rms\" data-value=\"" +
                        std::string(value) + "\"><b>" + number(1000 * j.get<double>("registration.rms_distance", 0), 4) +
                        " mm</b></span> (" +
                        std::to_string(j.get<int>("registration.points_used", 0)) + " points)");
          RenderOptions o;
          o.label = "deviation [mm]", o.signed_range = true;
          render_surfaces(dir + "/report", "deviation.png", {{dir + "/deviation.vtp", "deviation", "scan against prediction"}}, o);
          page.png(dir + "/report/deviation.png",
                   "The scan's points coloured by their signed distance from the predicted surface (mm; red: outside "
                   "it, the part less worn than predicted; blue: more worn).");
          for (const auto &e : fs::directory_iterator(dir))
            if (e.path().extension() == ".png")
              page.png(e.path().string(), e.path().filename().string());
          page.details("comparison.json", read_text(dir + "/comparison.json"));
        }
      std::vector<std::string> warnings;
      collect_warnings(j, warnings);
      page.heading("Warnings");
      page.warnings(warnings);
      return page.html();
    }
    /// The preview's set-up: the part where the case places it, among the walls, with the fill
    /// region, the domain and the part's path over one cycle (summary.json results.part.case;
    /// case_setup_view.h), and the same in numbers.
    void case_setup_section(HtmlPage &page, const std::string &dir, const Tree &scene,
                            const std::vector<std::pair<std::string, std::string>> &roles)
    {
      const std::string folder = dir + "/" + io::part_folder(dir);
      CaseSetupPicture  setup{folder + "/scene_part.vtp", folder + "/scene_walls.dat", folder + "/scene_path.dat",
                             numbers_at<6>(scene, "domain"), numbers_at<6>(scene, "fill_region"), {}};
      std::vector<std::vector<std::string>> legs;
      if (const auto path = scene.get_child_optional("path"))
        for (const auto &[i, leg] : *path)
          {
            const auto start = numbers_at<3>(leg, "start"), end = numbers_at<3>(leg, "end");
            setup.phase_ends.push_back({text_at(leg, "phase"), end});
            legs.push_back({text_at(leg, "wall"), text_at(leg, "phase"), mm(start[0]) + ", " + mm(start[1]) + ", " + mm(start[2]),
                            mm(end[0]) + ", " + mm(end[1]) + ", " + mm(end[2])});
          }
      page.heading("The case around the part");
      render_case_setup(dir + "/report", "setup.png", setup, roles);
      page.png(dir + "/report/setup.png",
               "The part where the case's walls place it (Geometry = solid model), coloured by its faces' roles, "
               "among the other walls (grey), with the particles' fill region (green, dashed: "
               "Particles/Generation/Region), the domain (dotted: Simulation/Domain) and the path of the part's "
               "lowest point over one cycle of prescribed motion (red, each phase named at its end); in mm.",
               "setup");
      const auto f = setup.fill_region, d = setup.domain;
      page.paragraph("Fill region " + mm(f[0]) + ", " + mm(f[1]) + ", " + mm(f[2]) + " ... " + mm(f[3]) + ", " + mm(f[4]) +
                     ", " + mm(f[5]) + " mm (" + text_at(scene, "particles") + " particles; 0: by solid fraction); domain " +
                     mm(d[0]) + ", " + mm(d[1]) + ", " + mm(d[2]) + " ... " + mm(d[3]) + ", " + mm(d[4]) + ", " + mm(d[5]) +
                     " mm.");
      if (!legs.empty())
        page.table({"wall", "phase", "the lowest point at its start [mm]", "at its end [mm]"}, legs);
      if (const auto notes = scene.get_child_optional("notes"))
        for (const auto &[i, n] : *notes)
          page.paragraph(n.get_value<std::string>());
    }

    /// The part's volume, mass and cells (and a file's wearing and clamped areas).
    std::string part_headline(const Tree &k, bool from_file)
    {
      char         value[40];
      const double volume = k.get<double>("volume", 0);
      std::snprintf(value, sizeof value, "%.17g", volume);
      return "The part: <span id=\"headline-volume\" data-value=\"" + std::string(value) + "\"><b>" +
             number(1e6 * volume, 4) + " cm^3</b></span>, " + number(k.get<double>("mass", 0), 4) + " kg, " +
             std::to_string(k.get<long>("cells", 0)) + " cells" +
             (from_file ? "; wearing " + number(k.get<double>("wearable_area", 0), 4) + " m^2, clamped or held " +
                            number(k.get<double>("clamped_area", 0), 4) + " m^2"
                        : std::string());
    }

    /// A part file's faces: a table row each (with the selectors that took a part of it), and
    /// the numbers of the larger ones (0.2 % of the area or more, at most 60) at their centres in
    /// @p o (small faces would hide the part).
    std::vector<std::vector<std::string>> file_face_rows(const Tree &k, RenderOptions &o)
    {
      std::vector<std::vector<std::string>>                rows;
      std::vector<std::pair<double, RenderOptions::Label>> labels;
      double                                               total = 0;
      for (const auto &[key, f] : *k.get_child_optional("file_faces"))
        total += f.get<double>("area", 0);
      for (const auto &[key, f] : *k.get_child_optional("file_faces"))
        {
          const auto c = numbers_at<3>(f, "centre"), n = numbers_at<3>(f, "normal");
          const std::string id = text_at(f, "id"), name = text_at(f, "name");
          const double      area = f.get<double>("area", 0);
          if (area >= 0.002 * total)
            labels.push_back({area, {c, id, n}});
          std::string taken;
          if (const auto sel = k.get_child_optional("selectors"))
            for (const auto &[j, t] : *sel)
              for (const auto &[m, x] : t.get_child("faces"))
                if (x.get_value<std::string>() == id)
                  taken += (taken.empty() ? "" : "; ") + text_at(t, "list") + " '" + text_at(t, "selector") + "'";
          rows.push_back({id, name, text_at(f, "role"), number(area, 4), number(f.get<double>("wearing_area", 0), 4),
                          number(f.get<double>("clamped_area", 0), 4), number(f.get<double>("held_area", 0), 4),
                          mm(c[0]) + ", " + mm(c[1]) + ", " + mm(c[2]),
                          number(n[0], 3) + ", " + number(n[1], 3) + ", " + number(n[2], 3), taken});
        }
      std::sort(labels.begin(), labels.end(), [](const auto &a, const auto &b) { return a.first > b.first; });
      for (std::size_t i = 0; i < labels.size() && i < 60; ++i)
        o.labels.push_back(labels[i].second);
      return rows;
    }

    /// The sections of a part file: its faces (@p rows) and the selectors that chose them.
    void file_face_sections(HtmlPage &page, const Tree &k, const std::vector<std::vector<std::string>> &rows)
    {
      page.heading("Faces");
      page.paragraph("The file's faces as Gmsh numbers them (Part/Clamped faces and Wearable faces select them by "
                     "'group NUMBER', a box of centres or a normal); a face a box or normal selector took in part is "
                     "'mixed'. Areas in m^2, centres in mm, in the part's own frame (as the face selectors see it).");
      page.table({"id", "name", "role", "area", "wearing", "clamped", "held", "centre [mm]", "normal", "taken by"}, rows);
      std::vector<std::vector<std::string>> taken;
      if (const auto sel = k.get_child_optional("selectors"))
        for (const auto &[j, t] : *sel)
          {
            std::string faces;
            for (const auto &[m, x] : t.get_child("faces"))
              faces += (faces.empty() ? "" : ", ") + x.get_value<std::string>();
            taken.push_back({text_at(t, "list"), text_at(t, "selector"), number(t.get<double>("area", 0), 4), faces});
          }
      if (!taken.empty())
        {
          page.heading("Selectors");
          page.table({"list", "selector", "area [m^2]", "faces"}, taken);
        }
    }

    /// The part job's page: the part's preview. The part as the case places it, drawn from
    /// two sides with its faces coloured by what the selectors made of them (wears, clamped,
    /// held) and the file's face numbers at their centres; the face table and what each
    /// selector took (summary.json `results.part`; `results.knife` from an abrade before the
    /// job's rename).
    std::string part_page(const std::string &dir, const Tree &summary)
    {
      auto k = summary.get_child_optional("results.part");
      if (!k)
        k = summary.get_child_optional("results.knife");
      if (!k)
        throw InputError(dir + "/summary.json", "no results.part in it (a part job that did not finish?)");
      const bool from_file = k->get_child_optional("file_faces").has_value();
      HtmlPage   page(from_file ? "Part preview" : "Knife preview");
      page.headline(part_headline(*k, from_file));
      RenderOptions o;
      o.label      = "role";
      o.categories = {{"wears", "#e66101"}, {"clamped", "#5e3c99"}, {"held", "#b2abd2"}};
      const std::vector<std::vector<std::string>> rows = from_file ? file_face_rows(*k, o) : std::vector<std::vector<std::string>>{};
      render_surfaces(dir + "/report", "faces.png",
                      {{dir + "/" + io::part_folder(dir) + "/faces.vtp", "role", "the part as placed"}}, o);
      page.png(dir + "/report/faces.png",
               "The part in its own frame (the file's placed by Part/Rotation and Offset; the case's walls place "
               "it in the case: below), in mm, from the front and from the back: each face coloured by what "
               "Clamped faces / Wearable faces made of it" +
                 std::string(from_file ? ", the file's face numbers at the larger faces' centres." : "."),
               "faces");
      if (const auto scene = k->get_child_optional("case"))
        case_setup_section(page, dir, *scene, o.categories);
      if (from_file)
        file_face_sections(page, *k, rows);
      page.heading("Warnings");
      std::vector<std::string> warnings;
      collect_warnings(summary, warnings);
      page.warnings(warnings);
      return page.html();
    }
  } // namespace

  std::string write_report(const std::string &dir, std::vector<std::string> *missing)
  {
    if (!fs::is_directory(dir))
      throw InputError(dir, "not a directory");
    const Tree  summary = read_json(dir + "/summary.json");
    std::string html;
    if (summary.get_child_optional("results.lifetime") || text_at(summary, "job") == "lifetime")
      {
        html = lifetime_page(dir, summary);
        if (fs::is_directory(dir + "/" + io::part_folder(dir)))
          write_paraview_script(dir);
      }
    else if (text_at(summary, "job") == "part" || text_at(summary, "job") == "knife") // (knife: its old name)
      html = part_page(dir, summary);
    else if (fs::exists(dir + "/concepts.csv"))
      html = table_page(dir, "Knife concepts compared", "concepts.csv", {"wear.png", "lifetime.png"});
    else if (fs::exists(dir + "/study.csv"))
      {
        std::vector<std::string> pngs; // the sweep's plots (plots/*.png), and any beside study.csv
        for (const std::string sub : {"", "plots"})
          if (fs::is_directory(dir + "/" + sub))
            for (const auto &e : fs::directory_iterator(dir + "/" + sub))
              if (e.path().extension() == ".png")
                pngs.push_back((sub.empty() ? "" : sub + "/") + e.path().filename().string());
        std::sort(pngs.begin(), pngs.end());
        html = table_page(dir, "Parameter sweep", "study.csv", pngs);
      }
    else if (fs::exists(dir + "/calibration.json") || fs::exists(dir + "/comparison.json"))
      html = field_page(dir);
    else
      throw InputError(dir, "no lifetime, part, concepts, sweep, compare or calibrate run here (summary.json, concepts.csv, "
                            "study.csv, comparison.json or calibration.json)");
    const std::string file = dir + "/report.html";
    io::write_file_atomically(file, html);
    // the pictures the page notes as missing (HtmlPage::png)
    if (missing)
      {
        missing->clear();
        const std::string mark = "data-missing-figure=\"";
        for (auto at = html.find(mark); at != std::string::npos; at = html.find(mark, at + 1))
          {
            const auto from = at + mark.size();
            missing->push_back(html.substr(from, html.find('"', from) - from));
          }
      }
    return file;
  }

  void write_paraview_script(const std::string &dir)
  {
    const std::string part = io::part_folder(dir);
    std::ofstream     py(dir + "/" + part + "/open_in_paraview.py");
    py << "# Opens the part's worn shapes of this lifetime run in ParaView, coloured by wear depth [mm]:\n"
          "#   paraview --script=open_in_paraview.py    (the GUI, to turn it around)\n"
          "#   pvpython open_in_paraview.py             (" << part << "_wear_paraview.png beside it, either way)\n"
          "# The time slider steps through the updates (time = handled tonnes).\n"
          "import os\n"
          "from paraview.simple import *\n"
          "here = os.path.dirname(os.path.abspath(__file__)) if '__file__' in globals() else os.getcwd()\n"
          "part = PVDReader(FileName=os.path.join(here, '" << part << ".pvd'))\n"
          "depth = Calculator(Input=part)\n"
          "depth.ResultArrayName = 'wear_depth_mm'\n"
          "depth.Function = 'wear_depth*1000'\n"
          "view = GetActiveViewOrCreate('RenderView')\n"
          "display = Show(depth, view)\n"
          "ColorBy(display, ('POINTS', 'wear_depth_mm'))\n"
          "lut = GetColorTransferFunction('wear_depth_mm')\n"
          "lut.ApplyPreset('Viridis (matplotlib)', True)\n"
          "animation = GetAnimationScene()\n"
          "animation.UpdateAnimationUsingDataTimeSteps()\n"
          "animation.AnimationTime = part.TimestepValues[-1]\n"
          "display.RescaleTransferFunctionToDataRange(False, True)\n"
          "display.SetScalarBarVisibility(view, True)\n"
          "GetScalarBar(lut, view).Title = 'wear depth [mm]'\n"
          "view.ResetCamera()\n"
          "Render()\n"
          "# (pvpython closes when the script ends: a picture of the last update stays)\n"
          "SaveScreenshot(os.path.join(here, '" << part << "_wear_paraview.png'), view, ImageResolution=[1200, 900])\n";
  }
} // namespace abrade::report
