// Every update's unfiltered wear, kept and replayed (stored_wear.h).
#include <abrade/common/csv_reader.h>
#include <abrade/common/error.h>
#include <abrade/common/format_number.h>
#include <abrade/coupling/lifetime/state_file.h>
#include <abrade/coupling/lifetime/stored_wear.h>
#include <abrade/fem/surface_filter.h>

#include <deal.II/base/bounding_box.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

namespace abrade::coupling::lifetime
{
  namespace
  {
    const std::string stored_format = "abrade stored wear 1";

    std::vector<double> numbers_of(const std::vector<int> &v) { return {v.begin(), v.end()}; }

    std::string joined(const std::vector<std::string> &words)
    {
      std::string s;
      for (const auto &w : words)
        s += (s.empty() ? "" : " ") + w;
      return s;
    }

    bool same_surface(const fem::SolidSurface &a, const fem::SolidSurface &b)
    {
      return a.vertices == b.vertices && a.triangles == b.triangles;
    }
  } // namespace

  std::string stored_wear_file(const std::string &run_directory, long update)
  {
    char name[40];
    std::snprintf(name, sizeof name, "wear/update_%05ld.wear", update);
    return run_directory + "/" + name;
  }

  void write_stored_wear(const std::string &path, const StoredWear &s)
  {
    StateFile f;
    f.set("format", stored_format);
    f.set("update", double(s.update));
    f.set("tonnes_start", s.tonnes_start);
    f.set("tonnes_per_cycle", s.wear.tonnes_per_cycle);
    f.set("particle_radius", s.wear.particle_radius);
    f.set("wear_coefficient", s.wear_coefficient);
    f.set("removes_volume", s.removes_volume ? 1.0 : 0.0);
    f.set("coarse_graining_factor", s.coarse_graining_factor);
    f.set("phases", joined(s.phases));
    f.set("phase_volume", s.wear.phase_volume);
    f.set("bed_seeds", numbers_of(s.bed_seeds));
    std::vector<double> points, triangles, ids;
    for (const auto &p : s.surface.vertices)
      points.insert(points.end(), {p[0], p[1], p[2]});
    for (const auto &t : s.surface.triangles)
      triangles.insert(triangles.end(), {double(t[0]), double(t[1]), double(t[2])});
    for (const auto id : s.surface.boundary_id)
      ids.push_back(double(id));
    f.set("vertices", points);
    f.set("triangles", triangles);
    f.set("boundary_ids", ids);
    for (std::size_t k = 0; k < s.wear.seed_volume.size(); ++k)
      f.set("volume_bed_" + std::to_string(k + 1), s.wear.seed_volume[k]);
    // written aside and renamed: a run killed while writing leaves no half file
    f.write(path + ".part");
    std::filesystem::rename(path + ".part", path);
  }

  StoredWear read_stored_wear(const std::string &path)
  {
    StoredWear s;
    try
      {
        const StateFile f = StateFile::read(path);
        if (!f.has("format") || f.text("format") != stored_format)
          throw InputError(path, "not a stored wear file of this abrade ('" + stored_format + "')");
        s.update                = long(f.number("update"));
        s.tonnes_start          = f.number("tonnes_start");
        s.wear.tonnes_per_cycle = f.number("tonnes_per_cycle");
        s.wear.particle_radius  = f.number("particle_radius");
        s.wear_coefficient      = f.number("wear_coefficient");
        s.removes_volume        = f.number("removes_volume") != 0;
        s.coarse_graining_factor = f.number("coarse_graining_factor");
        std::istringstream phases(f.text("phases"));
        for (std::string w; phases >> w;)
          s.phases.push_back(w);
        s.wear.phase_volume = f.numbers("phase_volume");
        for (double x : f.numbers("bed_seeds"))
          s.bed_seeds.push_back(int(x));
        const auto points = f.numbers("vertices"), triangles = f.numbers("triangles"), ids = f.numbers("boundary_ids");
        if (points.size() % 3 != 0 || triangles.size() % 3 != 0 || ids.size() != triangles.size() / 3 ||
            triangles.empty() || s.bed_seeds.empty() || !(s.wear.tonnes_per_cycle > 0) || s.tonnes_start < 0 ||
            s.wear.phase_volume.size() != s.phases.size())
          throw InputError(path, "corrupt stored wear (its surface, beds or tonnes)");
        const std::size_t n = points.size() / 3;
        for (std::size_t v = 0; v < n; ++v)
          s.surface.vertices.emplace_back(points[3 * v], points[3 * v + 1], points[3 * v + 2]);
        for (std::size_t t = 0; t < triangles.size(); t += 3)
          {
            std::array<unsigned, 3> tri;
            for (int k = 0; k < 3; ++k)
              {
                if (!(triangles[t + k] >= 0 && triangles[t + k] < double(n)))
                  throw InputError(path, "corrupt stored wear (triangle " + std::to_string(t / 3 + 1) +
                                           " names a vertex it does not have)");
                tri[k] = unsigned(triangles[t + k]);
              }
            s.surface.triangles.push_back(tri);
          }
        for (double id : ids)
          s.surface.boundary_id.push_back(dealii::types::boundary_id(id));
        for (std::size_t k = 0; k < s.bed_seeds.size(); ++k)
          {
            s.wear.seed_volume.push_back(f.numbers("volume_bed_" + std::to_string(k + 1)));
            const auto &v = s.wear.seed_volume.back();
            if (v.size() != n || std::any_of(v.begin(), v.end(), [](double x) { return !(x >= 0); }))
              throw InputError(path, "corrupt stored wear (the volumes of bed " + std::to_string(k + 1) + ")");
          }
      }
    catch (const InputError &e)
      {
        const std::string what = e.what();
        // (StateFile's own advice is about resuming: not this file's)
        throw InputError("", what.substr(0, what.find("; start afresh")) + " (a run's stored wear, wear/*.wear)");
      }
    return s;
  }

  std::vector<std::vector<double>> carry_wear_volumes(const fem::SolidSurface &from,
                                                      const std::vector<std::vector<double>> &volumes,
                                                      const fem::SolidSurface &to)
  {
    if (same_surface(from, to))
      return volumes;
    // (the areas and each vertex's closest point found once for all fields)
    const auto                 area_from = fem::vertex_areas(from), area_to = fem::vertex_areas(to);
    const fem::SurfaceTransfer transfer(from, to);
    std::vector<std::vector<double>> all;
    for (const auto &volume : volumes)
      {
        std::vector<double> density(volume.size());
        double              total = 0;
        for (std::size_t v = 0; v < volume.size(); ++v)
          density[v] = area_from[v] > 0 ? volume[v] / area_from[v] : 0.0, total += volume[v];
        std::vector<double> carried = transfer(density);
        double              sum     = 0;
        for (std::size_t v = 0; v < carried.size(); ++v) // (interpolated zeros can round below zero)
          sum += (carried[v] = std::max(0.0, carried[v]) * area_to[v]);
        if (sum > 0)
          for (double &x : carried)
            x *= total / sum;
        all.push_back(std::move(carried));
      }
    return all;
  }

  std::vector<double> carry_wear_volume(const fem::SolidSurface &from, const std::vector<double> &volume,
                                        const fem::SolidSurface &to)
  {
    return carry_wear_volumes(from, {volume}, to).front();
  }

  namespace
  {
    class ReplayedWearSource : public WearSource
    {
    public:
      ReplayedWearSource(const std::string &directory, const fem::SolidSurface &design, double tolerance,
                         double coarse_graining_factor)
      {
        namespace fs = std::filesystem;
        const std::string dir = directory + "/wear";
        std::error_code   ec;
        if (!fs::is_directory(directory, ec))
          throw InputError(directory, "no such directory (Lifetime/Replay/Run is taken relative to the parameter file; give "
                                      "an absolute path for a run elsewhere)");
        if (!fs::is_directory(dir, ec))
          throw InputError(directory, "holds no stored wear (wear/update_*.wear): not a lifetime run's "
                                      "directory, or a run of an abrade before it kept its wear");
        for (long u = 0;; ++u)
          {
            const std::string file = stored_wear_file(directory, u);
            if (!fs::exists(file, ec))
              {
                if (u == 0)
                  continue; // (a run with fixed cycles has no pilot)
                break;
              }
            updates.push_back(read_stored_wear(file));
          }
        if (updates.empty() || updates.back().update < 1)
          throw InputError(dir, "no stored update (wear/update_00001.wear)");
        // other particles wear the part otherwise: the stored wear is not this case's (the
        // factor of the particles at the part: a multi-level bed's finest level's)
        if (std::abs(updates.front().coarse_graining_factor / coarse_graining_factor - 1) > 1e-9)
          throw InputError(directory, "its wear was made by particles coarse-grained by " +
                                        io::format_number(updates.front().coarse_graining_factor) + ", this case's at the part are by " +
                                        io::format_number(coarse_graining_factor) +
                                        " (Particles/Coarse graining/Factor, or a fine region's Fine region factor): replay a "
                                        "run of the same case (only W and the Smoothing radius may differ)");
        // the stored run's part must be this one: the first stored surface is its design (the
        // same extent within a tenth of the mesh size, the same volume within 0.1 %)
        const dealii::BoundingBox<3> a(design.vertices), b(updates.front().surface.vertices);
        const double                 v_design = fem::enclosed_volume(design),
                     v_stored = fem::enclosed_volume(updates.front().surface);
        bool other = !(std::abs(v_design / v_stored - 1) <= 1e-3);
        for (int d = 0; d < 3; ++d)
          other = other || std::abs(a.lower_bound(d) - b.lower_bound(d)) > 0.1 * tolerance ||
                  std::abs(a.upper_bound(d) - b.upper_bound(d)) > 0.1 * tolerance;
        if (other)
          throw InputError(directory, "its wear fell on another part (its unworn volume " +
                                        io::format_number(v_stored * 1e6, 6) + " cm^3 and extent against this run's " +
                                        io::format_number(v_design * 1e6, 6) + " cm^3): replay a run of the same case "
                                        "(only W and the Smoothing radius may differ)");
        source_directory = directory;
        // (the worn volumes against each run's own design: this one's now, the stored one's then)
        design_volume = v_design;
        for (const auto &u : updates)
          worn_before.push_back(v_stored - fem::enclosed_volume(u.surface));
        uses.assign(updates.size(), 0);
        // the stored run's end: its trajectory's last worn volume (else its last update's start)
        worn_at_end = worn_before.back();
        try
          {
            const io::CsvTable t = io::read_csv(directory + "/trajectory.csv");
            if (!t.rows.empty())
              worn_at_end = std::max(worn_at_end, std::stod(t.rows.back().at(std::size_t(t.column("worn_volume")))));
          }
        catch (const std::exception &)
          {} // (a run killed before its first update: its stored pilot and first update only)
      }

      CycleWear cycle(const fem::SolidSurface &surface, double tonnes, const std::vector<int> &bed_seeds) override
      {
        // the same run again (the pilot and the first update of any replay; every update of one
        // at the stored footprint): the stored update of these beds on this very surface
        std::vector<std::string> said; // (this cycle's warnings)
        const StoredWear        *use = nullptr;
        for (const auto &u : updates)
          if (u.bed_seeds == bed_seeds && same_surface(u.surface, surface))
            use = &u;
        // else the stored update that began with the most volume worn off, but not more than
        // this part has lost: the nearest state (the worn volume does not depend on the
        // footprint, nor, in cycles, on W: its tonnes do)
        const double worn = design_volume - fem::enclosed_volume(surface);
        if (!use)
          for (std::size_t k = 0; k < updates.size(); ++k)
            if (updates[k].update >= 1 && (!use || worn_before[k] <= worn))
              use = &updates[k];
        if (worn > worn_at_end && !said_beyond)
          {
            said_beyond = true;
            said.push_back("after " + io::format_number(tonnes, 4) + " t the part has lost more (" +
                                    io::format_number(worn * 1e6, 4) + " cm^3) than the stored run " +
                                    source_directory + " did (" + io::format_number(worn_at_end * 1e6, 4) +
                                    " cm^3): its last update's wear, on its last surface, is used from here on");
          }
        const bool pilot = std::any_of(updates.begin(), updates.end(), [&](const StoredWear &u) {
          return u.update == 0 && u.bed_seeds == bed_seeds;
        });
        if (!pilot && ++uses[use - updates.data()] == 2 && use->update >= 1)
          said.push_back("stored update " + std::to_string(use->update) + "'s beds are used by more than one "
                                  "update: the life's interval counts them as fresh beds each time (too narrow)");
        CycleWear w = use->wear;
        w.bed_seeds = use->bed_seeds;
        w.seed_volume = carry_wear_volumes(use->surface, use->wear.seed_volume, surface);
        w.warnings    = std::move(said);
        return w;
      }

      std::vector<std::string> phases() const override { return updates.front().phases; }
      double                   wear_coefficient() const override { return updates.front().wear_coefficient; }
      bool                     removes_volume() const override { return updates.front().removes_volume; }
      std::string              name() const override { return "replay"; }

    private:
      std::vector<StoredWear> updates;
      std::string              source_directory;
      double                   design_volume = 0; ///< enclosed by this run's design (its unworn part)
      std::vector<double>      worn_before;       ///< per stored update: the volume worn off before it
      double                   worn_at_end = 0;   ///< the stored run's worn volume at its end
      std::vector<int>         uses;              ///< per stored update: how often replayed
      bool                     said_beyond = false;
    };
  } // namespace

  std::unique_ptr<WearSource> make_replayed_wear_source(const std::string &run_directory,
                                                        const fem::SolidSurface &design, double tolerance,
                                                        double coarse_graining_factor)
  {
    return std::make_unique<ReplayedWearSource>(run_directory, design, tolerance, coarse_graining_factor);
  }
} // namespace abrade::coupling::lifetime
