// Every update's unfiltered wear, kept and replayed (stored_wear.h).
#include <abrade/common/csv_reader.h>
#include <abrade/common/error.h>
#include <abrade/common/format_number.h>
#include <abrade/common/list_items.h>
#include <abrade/coupling/lifetime/state_file.h>
#include <abrade/coupling/lifetime/stored_wear.h>
#include <abrade/fem/surface_filter.h>

#include <deal.II/base/bounding_box.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <utility>

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

    /// The same beds in any order (the runs of a joined replay in another order than Seeds).
    bool same_beds(const std::vector<int> &a, const std::vector<int> &b)
    {
      return a.size() == b.size() && std::is_permutation(a.begin(), a.end(), b.begin());
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

  StoredWear join_stored_wear(const std::vector<StoredWear> &parts, const std::vector<std::string> &names,
                              bool tonnes_from_payload)
  {
    if (parts.empty())
      throw std::logic_error("join_stored_wear: no runs");
    const StoredWear &first = parts.front();
    StoredWear        joined = first;
    joined.bed_seeds.clear(), joined.wear.seed_volume.clear();
    std::size_t beds = 0;
    for (const auto &p : parts)
      beds += p.bed_seeds.size();
    std::fill(joined.wear.phase_volume.begin(), joined.wear.phase_volume.end(), 0.0);
    double tonnes = 0;
    for (std::size_t r = 0; r < parts.size(); ++r)
      {
        const StoredWear &p = parts[r];
        const char       *other = nullptr;
        if (p.update != first.update)
          other = "update";
        else if (!same_surface(p.surface, first.surface) || p.surface.boundary_id != first.surface.boundary_id)
          other = "surface (the part it fell on)";
        else if (p.tonnes_start != first.tonnes_start)
          other = "tonnes before it";
        else if (p.wear_coefficient != first.wear_coefficient || p.removes_volume != first.removes_volume)
          other = "wear law or W";
        else if (p.phases != first.phases || p.wear.phase_volume.size() != first.wear.phase_volume.size())
          other = "phases of the cycle";
        else if (p.coarse_graining_factor != first.coarse_graining_factor)
          other = "coarse-graining factor";
        else if (!tonnes_from_payload && p.wear.tonnes_per_cycle != first.wear.tonnes_per_cycle)
          other = "Lifetime/Tonnes per cycle";
        if (other)
          throw InputError(names.at(r), "its stored update " + std::to_string(p.update) + " differs in its " + other +
                                          " from " + names.front() +
                                          "'s: only the beds of runs of one case on one part are joined");
        for (std::size_t b = 0; b < p.bed_seeds.size(); ++b)
          {
            if (std::find(joined.bed_seeds.begin(), joined.bed_seeds.end(), p.bed_seeds[b]) != joined.bed_seeds.end())
              throw InputError(names.at(r), "its bed of seed " + std::to_string(p.bed_seeds[b]) +
                                              " is in another of the runs too: one bed twice is not two beds");
            joined.bed_seeds.push_back(p.bed_seeds[b]);
            joined.wear.seed_volume.push_back(p.wear.seed_volume.at(b));
          }
        // (a run of k beds stores their mean: k of the joined run's terms; a run of one, its
        // bed's term, added as the DEM adds its beds' terms)
        const double k = double(p.bed_seeds.size());
        for (std::size_t i = 0; i < joined.wear.phase_volume.size(); ++i)
          joined.wear.phase_volume[i] += p.wear.phase_volume[i] * k / double(beds);
        tonnes += p.wear.tonnes_per_cycle * k / double(beds);
      }
    if (tonnes_from_payload) // (a grab's tonnes are its payload, measured bed by bed)
      joined.wear.tonnes_per_cycle = tonnes;
    // (the largest particle of the last bed, as the DEM keeps it: a size distribution's
    // largest differs from bed to bed)
    joined.wear.particle_radius = parts.back().wear.particle_radius;
    return joined;
  }

  namespace
  {
    /// A run's stored wear: its updates in order (its pilot first where it has one) and the
    /// volume it had worn off at its end (its trajectory's last, else its last update's start).
    struct StoredRun
    {
      std::string             directory;
      std::vector<StoredWear> updates;
      double                  worn_at_end = 0;
    };

    StoredRun read_stored_run(const std::string &directory)
    {
      namespace fs = std::filesystem;
      StoredRun         run{directory, {}, 0};
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
          run.updates.push_back(read_stored_wear(file));
        }
      if (run.updates.empty() || run.updates.back().update < 1)
        throw InputError(dir, "no stored update (wear/update_00001.wear)");
      run.worn_at_end = fem::enclosed_volume(run.updates.front().surface) - fem::enclosed_volume(run.updates.back().surface);
      try
        {
          const io::CsvTable t = io::read_csv(directory + "/trajectory.csv");
          if (!t.rows.empty())
            run.worn_at_end = std::max(run.worn_at_end, std::stod(t.rows.back().at(std::size_t(t.column("worn_volume")))));
        }
      catch (const std::exception &)
        {} // (a run killed before its first update: its stored pilot and first update only)
      return run;
    }

    /// Several runs' stored wear joined update by update (join_stored_wear) while their parts
    /// have the same surface; pilots only where every run has one. The joined run's end: the
    /// runs' mean worn volume after its last update (each run's at the start of its next, else
    /// at its end). @p stopped: where the join ended before a run did, and why (else empty).
    StoredRun join_stored_runs(const std::vector<StoredRun> &runs, bool tonnes_from_payload, std::string &stopped)
    {
      if (runs.size() == 1)
        return runs.front();
      StoredRun                joined;
      std::vector<std::string> names;
      for (const auto &r : runs)
        names.push_back(r.directory);
      joined.directory = io::list_text(names);
      const auto has_pilot = [](const StoredRun &r) { return r.updates.front().update == 0; };
      long       u         = std::all_of(runs.begin(), runs.end(), has_pilot) ? 0 : 1;
      for (;; ++u)
        {
          std::vector<StoredWear> parts;
          for (const auto &r : runs)
            for (const auto &s : r.updates)
              if (s.update == u)
                parts.push_back(s);
          if (parts.size() < runs.size()) // (a run ended)
            {
              if (!parts.empty())
                stopped = "the joined runs end at update " + std::to_string(u - 1) + ", where the first of them ends";
              break;
            }
          const bool parted = std::any_of(parts.begin(), parts.end(), [&](const StoredWear &s) {
            return !same_surface(s.surface, parts.front().surface);
          });
          if (parted && u > 1)
            {
              stopped = "the joined runs end at update " + std::to_string(u - 1) +
                        ": after it each run's part had worn its own way (their later updates are not joined)";
              break;
            }
          joined.updates.push_back(join_stored_wear(parts, names, tonnes_from_payload)); // (refuses other parts on the design)
        }
      const long last = joined.updates.back().update;
      for (const auto &r : runs)
        {
          double worn = r.worn_at_end;
          for (const auto &s : r.updates)
            if (s.update == last + 1)
              worn = fem::enclosed_volume(r.updates.front().surface) - fem::enclosed_volume(s.surface);
          joined.worn_at_end += worn / double(runs.size());
        }
      return joined;
    }

    class ReplayedWearSource : public WearSource
    {
    public:
      ReplayedWearSource(const std::vector<std::string> &directories, const fem::SolidSurface &design, double tolerance,
                         double coarse_graining_factor, bool tonnes_from_payload, const std::vector<int> &seeds)
      {
        for (int seed : seeds)
          pilot_beds.push_back(bed_seed(seed, 0));
        std::vector<StoredRun> runs;
        for (const auto &d : directories)
          runs.push_back(read_stored_run(d));
        StoredRun stored = join_stored_runs(runs, tonnes_from_payload, join_stopped);
        updates          = std::move(stored.updates);
        source_directory = stored.directory;
        const std::string &directory = source_directory;
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
        // (the worn volumes against each run's own design: this one's now, the stored one's then)
        design_volume = v_design;
        for (const auto &u : updates)
          worn_before.push_back(v_stored - fem::enclosed_volume(u.surface));
        uses.assign(updates.size(), 0);
        worn_at_end = stored.worn_at_end;
      }

      CycleWear cycle(const fem::SolidSurface &surface, double tonnes, const std::vector<int> &bed_seeds) override
      {
        // the same run again (the pilot and the first update of any replay; every update of one
        // at the stored footprint): the stored update of these beds on this very surface
        std::vector<std::string> said; // (this cycle's warnings)
        const StoredWear        *use = nullptr;
        for (const auto &u : updates)
          if (same_beds(u.bed_seeds, bed_seeds) && same_surface(u.surface, surface))
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
        // (the pilot cycle, on this run's pilot beds, only sizes the first update: not a use; a
        // stored run of fixed cycles has none, and its first update serves this run's pilot too.
        // Not told by a stored pilot's beds: a replay's stored pilot holds the beds it borrowed,
        // the seeds' own, which a replay of it asks for in its first update)
        const bool pilot = same_beds(bed_seeds, pilot_beds);
        if (!pilot && ++uses[use - updates.data()] == 2 && use->update >= 1)
          said.push_back("stored update " + std::to_string(use->update) + "'s beds are used by more than one "
                                  "update: the life's interval counts them as fresh beds each time (too narrow)");
        CycleWear w = use->wear;
        w.bed_seeds = use->bed_seeds;
        w.seed_volume = carry_wear_volumes(use->surface, use->wear.seed_volume, surface);
        w.warnings    = std::move(said);
        if (!join_stopped.empty()) // (said once, in the first cycle's notes)
          w.notes.push_back(std::exchange(join_stopped, std::string()));
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
      std::string              join_stopped; ///< where the joined runs end before one of them did (said once)
      std::vector<int>         pilot_beds;   ///< the beds of this run's pilot cycle
    };
  } // namespace

  std::unique_ptr<WearSource> make_replayed_wear_source(const std::vector<std::string> &run_directories,
                                                        const fem::SolidSurface &design, double tolerance,
                                                        double coarse_graining_factor, bool tonnes_from_payload,
                                                        const std::vector<int> &seeds)
  {
    return std::make_unique<ReplayedWearSource>(run_directories, design, tolerance, coarse_graining_factor,
                                                tonnes_from_payload, seeds);
  }
} // namespace abrade::coupling::lifetime
