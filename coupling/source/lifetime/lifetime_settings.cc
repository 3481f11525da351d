// Subsection Lifetime (lifetime_settings.h): the tonnes, the beds and the updates, the filter,
// the gauges, the wear source (each source's entries in its subsection) and the end-of-life
// criteria (each declaring its own entries), the
// interval asked for and a calibration; declared here and read and checked by the loop that
// uses them (LifetimeLoop::read_settings()).
#include <abrade/dem/parameter_section.h>
#include <abrade/common/format_number.h>
#include <abrade/coupling/lifetime/lifetime_loop.h>
#include <abrade/coupling/lifetime/lifetime_settings.h>
#include <abrade/dem/wear.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <limits>

namespace abrade::coupling::lifetime
{
  using dealii::Patterns::Anything;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;
  using dealii::Patterns::List;

  void declare_lifetime_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Lifetime");
    prm.declare_entry("Tonnes per cycle", "10", Double(0, 1e6),
                      "[t] Material handled per operating cycle (the tonnes axis of the trajectory); 0: "
                      "the DEM's payload, the most mass above Simulation/Payload height at the end of a "
                      "phase, measured at every update (a grab: a knife that burrows worse takes less). "
                      "Range: [0, 1e6] (the largest grabs take tens of tonnes a cycle: a million is "
                      "a unit mistake).");
    prm.declare_entry("Seeds", "1", List(Integer(0)),
                      "Bed seeds of the replicate DEM cycles run at every update; their wear is "
                      "averaged. Every update settles fresh beds, their seeds derived from these and the "
                      "update number (the first update's are these seeds themselves, whose beds are kept in "
                      "beds/), so that the updates are independent samples for the life's interval "
                      "(docs/lifetime.md). Three or more give an interval from the first update on.");
    prm.declare_entry("Cycles per update", "0", Integer(0),
                      "Real cycles one update stands for; 0: adaptive, so that the largest depth "
                      "increment is 'Depth increment fraction' of the mesh size. Range: >= 0.");
    prm.declare_entry("Depth increment fraction", "0.05", Double(1e-6, 1),
                      "[-] Adaptive updates: largest depth increment per update over the mesh size. Range: (0, 1].");
    prm.declare_entry("Smoothing radius", "0", Double(0, dem::unbounded),
                      "[m] Length of the wear filter: the per-cycle wear is smoothed over the part's "
                      "surface with a Gaussian of this length in the distance along the surface (it never "
                      "crosses the plate), conserving the volume. It stands for the particle's footprint; "
                      "0: the largest particle radius (DEM wear), none (analytic wear). Range: >= 0.");
    prm.declare_entry("Recession points", "0.2, 0, 0", List(List(Double(-dem::unbounded, dem::unbounded), 3, 3), 1, 100, ";"),
                      "[m] Points of the part (in its own coordinates: x along the length from 0, y "
                      "across the thickness from its middle, z up from the edge), separated by ';', whose "
                      "recession (how far the surface point that was there on the fresh part has moved, "
                      "interpolated: at a chisel's tip, the tip's recession along its bisector) the trajectory "
                      "follows: column point_recession for the first, point_recession_2, ... for the "
                      "others. Default: the middle of the edge of the default knife.");
    prm.declare_entry("Gauge height", "0", Double(0, dem::unbounded),
                      "[m] Where the plate's thickness is gauged, above the design's edge; 0: one plate "
                      "thickness above where the design's middle section first reaches its full thickness "
                      "(a chisel's bevel top, whose worn corner rises as the faces beside it wear). "
                      "Range: >= 0.");
    prm.declare_entry("Gauge stations", "41", Integer(2, 10000),
                      "Stations along the part's length (its x axis) where the edge recession and the plate "
                      "thickness are gauged, evenly spaced from end to end of the part as it is (the end ones "
                      "one Part/Mesh size inside its ends: the corners as far as the mesh resolves them). "
                      "Range: [2, 10000].");
    lifetime::declare_wear_sources(prm); // (Wear source and each source's own: lifetime/wear_sources/)
    lifetime::declare_end_of_life_criteria(prm); // (Maximum depth, ...: each criterion's own, lifetime/criteria/)
    prm.declare_entry("Target tonnes", "0", Double(0, dem::unbounded),
                      "[t] Stop when this many tonnes are handled; 0: no target. Range: >= 0.");
    prm.declare_entry("Maximum updates", "20", Integer(1), "Stop after this many updates. Range: >= 1.");
    prm.declare_entry("Target interval", "0", Double(0, 1),
                      "[-] The life's 95 % interval asked for, as a relative half-width (0.1: +-10 %); "
                      "while the interval is wider, the next updates draw more beds (the seeds' beds "
                      "settled again in further rounds), up to Maximum beds. The summary says what was "
                      "achieved. 0: the Seeds' beds at every update. Range: [0, 1).");
    prm.declare_entry("Maximum beds", "12", Integer(1, 1000),
                      "Target interval: the most beds an update draws. Range: [1, 1000].");
    prm.declare_entry("Calibration", "", Anything(),
                      "[file] calibration.json of abrade calibrate (relative to this file): the best-ranked "
                      "run's fitted wear coefficient (W) replaces the part's, every cycle's wear scaled by "
                      "their ratio, and the fit's standard error enters the life's interval as its "
                      "component 'calibration' (to first order the life goes as 1/W). The fit holds for the "
                      "footprint it was made with (the calibrated run's Smoothing radius): another one is "
                      "warned about. DEM wear only. Empty: the case's W, no calibration component.");
    prm.declare_entry("Profile planes", "0.5", List(Double(0, 1)),
                      "Cross-sections of the part written per update (part/profile_N.csv and .png), "
                      "at these fractions of the part's length (planes normal to its length).");
    prm.leave_subsection();
  }

  void LifetimeLoop::read_settings()
  {
    auto &prm = ctx.parameters.handler();
    prm.enter_subsection("Lifetime");
    s.tonnes_per_cycle = prm.get_double("Tonnes per cycle");
    for (const auto &x : dealii::Utilities::split_string_list(prm.get("Seeds")))
      s.seeds.push_back(std::stoi(x));
    s.fixed_cycles  = prm.get_integer("Cycles per update");
    s.fraction      = prm.get_double("Depth increment fraction");
    s.smoothing     = prm.get_double("Smoothing radius");
    s.target_tonnes = prm.get_double("Target tonnes");
    for (const auto &p : dealii::Utilities::split_string_list(prm.get("Profile planes")))
      s.planes.push_back(std::stod(p));
    for (const auto &point : dealii::Utilities::split_string_list(prm.get("Recession points"), ';'))
      {
        const auto xyz = dealii::Utilities::split_string_list(point);
        s.recession_points.emplace_back(std::stod(xyz[0]), std::stod(xyz[1]), std::stod(xyz[2]));
      }
    s.max_updates     = prm.get_integer("Maximum updates");
    source_choice     = make_wear_source_choice(prm.get("Wear source"));
    if (!source_choice) // (the pattern lists the registered ones: a program without its plugins)
      ctx.parameters.fail({"Lifetime"}, "Wear source", "no wear source of that name is registered in this program");
    prm.enter_subsection(source_choice->section());
    source_choice->parse_parameters(ctx.parameters);
    prm.leave_subsection();
    s.target_interval = prm.get_double("Target interval");
    s.max_beds        = prm.get_integer("Maximum beds");
    s.calibration_file = ctx.parameters.path_beside(prm.get("Calibration"));
    criteria = make_end_of_life_criteria();
    for (auto &c : criteria)
      c->parse_parameters(prm);
    s.gauge_height        = prm.get_double("Gauge height");
    s.gauge_stations      = prm.get_integer("Gauge stations");
    prm.leave_subsection();
    if (s.target_interval > 0 && s.max_beds < long(s.seeds.size()))
      ctx.parameters.fail({"Lifetime"}, "Maximum beds",
                          "fewer than the " + std::to_string(s.seeds.size()) + " Seeds: a target interval adds beds, "
                          "it does not take them away");

    if (s.seeds.empty())
      ctx.parameters.fail({"Lifetime"}, "Seeds", "at least one seed is needed");
    for (std::size_t a = 0; a < s.seeds.size(); ++a)
      for (std::size_t b = a + 1; b < s.seeds.size(); ++b)
        if (s.seeds[a] == s.seeds[b])
          ctx.parameters.fail({"Lifetime"}, "Seeds",
                              "seed " + std::to_string(s.seeds[a]) +
                                " is given twice: the same bed twice is no replicate (its interval would be zero)");
    const bool particles = source_choice->from_particles();
    if (particles && s.smoothing > 0 && dem_case.factor_at_tools() != 1) // (a multi-level bed: its finest)
      {
        warnings.push_back("Lifetime/Smoothing radius is fixed (" + io::format_number(s.smoothing) + " m) while the "
                           "particles are coarse-grained (by " + io::format_number(dem_case.factor_at_tools(), 4) +
                           " at the part): 0 ties the wear filter to the simulated radius");
        ctx.log.warning(warnings.back());
      }
    if (particles && s.tonnes_per_cycle == 0 && !dem_case.payload_height)
      ctx.parameters.fail({"Lifetime"}, "Tonnes per cycle",
                          "0 takes the tonnes from the DEM's payload: set Simulation/Payload height");
    if (particles &&
        std::none_of(dem_case.walls.begin(), dem_case.walls.end(), [](const auto &w) { return w.solid_model; }))
      ctx.parameters.fail({}, "Walls", "a lifetime run needs a wall with Geometry = solid model (the part)");
    if (particles)
      for (const auto &w : dem_case.walls)
        if (w.solid_model && !dem::law_recording(w.wear, dem_case.wear_field))
          {
            const dem::WearLaw *law = dem::wear_law_of_field(dem_case.wear_field);
            ctx.parameters.fail({"Wall " + w.wall.name, "Wear"}, "Laws",
                                "the part's wear laws do not record Output/Wear field = " + dem_case.wear_field +
                                  ", the field the lifetime loop wears the part by: add " +
                                  (law ? law->name() : std::string("its law")));
          }
    // a known rate is per tonne: nothing weighs a payload
    if (!particles && s.tonnes_per_cycle <= 0)
      ctx.parameters.fail({"Lifetime"}, "Tonnes per cycle",
                          "the " + source_choice->name() + " wear rate is per tonne: set Tonnes per cycle > 0");
    if (std::none_of(criteria.begin(), criteria.end(), [](const auto &c) { return c->active(); }))
      {
        std::string keys;
        for (std::size_t c = 0; c < criteria.size(); ++c)
          keys += (c == 0 ? "" : c + 1 == criteria.size() ? " or " : ", ") + criteria[c]->parameter();
        ctx.parameters.fail({"Lifetime"}, criteria[criterion_named(depth_name)]->parameter(),
                            "no end-of-life criterion: set " + keys + " > 0");
      }
  }
} // namespace abrade::coupling::lifetime
